#pragma once
// Shared by the volume tests: one light's mask from a method, and its mismatch with raytrace.
#include <memory>
#include <string>

#include "shadowkit/app/mask_compare.h"
#include "shadowkit/methods/shadow_method.h"

namespace shadowkit::testing {

/// The mask of \p method for light \p light, and the method's counters after it.
inline ShadowMask method_mask(ShadowMethod& method, const Scene& scene,
                              const VisibleSurfaceBuffer& vsb, std::size_t light) {
  method.prepare(scene, {});
  method.build(scene, light, {});
  ShadowMask mask(vsb.width, vsb.height, kMaskBackground);
  method.shade(scene, vsb, mask, {});
  return mask;
}

/// Interior mismatch (percent) of `volume` with \p options against `raytrace`, light by light;
/// the worst light.
inline double worst_interior_mismatch(const Scene& scene, const MethodOptions& options = {}) {
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  const std::vector<std::uint32_t> ids = vsb.object_ids();
  double worst = 0;
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const auto reference = make_method("raytrace", {});
    const auto volume = make_method("volume", options);
    const MaskComparison c = compare_masks(method_mask(*reference, scene, vsb, l),
                                           method_mask(*volume, scene, vsb, l), ids);
    worst = std::max(worst, c.interior_pct());
  }
  return worst;
}

/// A counter of \p method by name.
inline double counter(const ShadowMethod& method, const std::string& name) {
  for (const auto& [key, value] : method.counters()) {
    if (key == name) return value;
  }
  return -1;
}

}  // namespace shadowkit::testing
