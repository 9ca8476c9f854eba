#pragma once
// Running a method in a test: one light's mask, its counters, its mismatch with raytrace.
#include <algorithm>
#include <string>
#include <vector>

#include "shadowkit/methods/mask_compare.h"
#include "shadowkit/methods/registry.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit::testing {

/// \brief A scene (file or built-in name) and its visible surfaces, as benchmarks use them.
struct RenderedScene {
  Scene scene;
  VisibleSurfaceBuffer vsb;
  explicit RenderedScene(const std::string& name)
      : scene(load_scene(name, {})), vsb(render_visible_surfaces(scene, {})) {}
};

/// The mask of light \p light from \p method, prepared for \p scene already (build, shade).
inline ShadowMask light_mask(ShadowMethod& method, const Scene& scene,
                             const VisibleSurfaceBuffer& vsb, std::size_t light,
                             const Context& ctx = {}) {
  method.build(scene, light, ctx);
  ShadowMask mask(vsb.width, vsb.height, kMaskBackground);
  method.shade(scene, vsb, mask, ctx);
  return mask;
}

/// The mask of \p method for light \p light (prepare, build, shade).
inline ShadowMask method_mask(ShadowMethod& method, const Scene& scene,
                              const VisibleSurfaceBuffer& vsb, std::size_t light) {
  method.prepare(scene, {});
  return light_mask(method, scene, vsb, light);
}

/// A counter of \p method by name, or -1.
inline double counter(const ShadowMethod& method, const std::string& name) {
  for (const auto& [key, value] : method.counters()) {
    if (key == name) return value;
  }
  return -1;
}

/// The masks of \p method_name with \p options against `raytrace`'s, one comparison per light
/// of \p scene. Each method is prepared once and built once per light, as the commands do.
inline std::vector<MaskComparison> compare_with_reference(const Scene& scene,
                                                          const VisibleSurfaceBuffer& vsb,
                                                          const std::string& method_name,
                                                          const MethodOptions& options = {},
                                                          const Context& ctx = {}) {
  const auto reference = make_method("raytrace", {});
  const auto method = make_method(method_name, options);
  reference->prepare(scene, ctx);
  method->prepare(scene, ctx);
  const std::vector<std::uint32_t> ids = vsb.object_ids();
  std::vector<MaskComparison> out;
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    out.push_back(compare_masks(light_mask(*reference, scene, vsb, l, ctx),
                                light_mask(*method, scene, vsb, l, ctx), ids));
  }
  return out;
}

/// Interior mismatch (percent) of \p method_name with \p options against `raytrace`, for the
/// worst light of \p scene.
inline double worst_interior_mismatch(const Scene& scene, const std::string& method_name,
                                      const MethodOptions& options = {}) {
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  double worst = 0;
  for (const MaskComparison& c : compare_with_reference(scene, vsb, method_name, options)) {
    worst = std::max(worst, c.interior_pct());
  }
  return worst;
}

}  // namespace shadowkit::testing
