#pragma once
// Shared by the angular tests: one light's mask from a method, and mismatch with raytrace.
#include "shadowkit/app/mask_compare.h"
#include "shadowkit/methods/shadow_method.h"

namespace shadowkit::testing {

/// The mask of \p method for light \p light.
inline ShadowMask angular_mask(ShadowMethod& method, const Scene& scene,
                               const VisibleSurfaceBuffer& vsb, std::size_t light) {
  method.prepare(scene, {});
  method.build(scene, light, {});
  ShadowMask mask(vsb.width, vsb.height, kMaskBackground);
  method.shade(scene, vsb, mask, {});
  return mask;
}

/// A counter of \p method by name, or -1.
inline double angular_counter(const ShadowMethod& method, const std::string& name) {
  for (const auto& [key, value] : method.counters()) {
    if (key == name) return value;
  }
  return -1;
}

}  // namespace shadowkit::testing
