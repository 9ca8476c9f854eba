#pragma once
// Running a method in a test: one light's mask, its counters, its mismatch with raytrace.
#include <algorithm>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "shadowkit/methods/mask_compare.h"
#include "shadowkit/methods/registry.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/scene/scene_file.h"
#include "testing/test_scenes.h"

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

/// \brief What a coincident copy changes in a method's masks (coincident_copy_difference).
struct CopyDifference {
  int differ = 0;   ///< pixels whose mask differs, over both lights
  int lit_box = 0;  ///< lit pixels of the box alone, under the light that lights fewer
};

/// \p box on a ground, alone and with a second copy at the same spot, each copy's faces in the
/// other's planes, under a point and a directional light: the masks of the method that
/// \p make gives should be the same, since a coincident face is not strictly between a point
/// and the light.
inline CopyDifference coincident_copy_difference(
    const std::function<std::unique_ptr<ShadowMethod>()>& make, const PolygonSoup& box) {
  const Camera cam = camera({4, 6, 7}, {0, 0.5, 0}, 320, 240);
  const PolygonSoup ground = horizontal_quad(-10, 10, -10, 10, 0);
  CopyDifference out{0, std::numeric_limits<int>::max()};
  for (const Light& light : {point_light({-2, 5, 3}), directional_light({0.4, -1, -0.3})}) {
    const Scene one = make_scene(cam, {light}, {ground, box});
    const Scene two = make_scene(cam, {light}, {ground, box, box});
    const VisibleSurfaceBuffer vsb_one = render_visible_surfaces(one, {});
    const VisibleSurfaceBuffer vsb_two = render_visible_surfaces(two, {});
    const ShadowMask mask_one = method_mask(*make(), one, vsb_one, 0);
    const ShadowMask mask_two = method_mask(*make(), two, vsb_two, 0);
    int lit_box = 0;
    for (std::size_t i = 0; i < mask_one.size(); ++i) {
      out.differ += mask_one.pixels[i] != mask_two.pixels[i];
      lit_box += vsb_one.object(i) == 1 && mask_one.pixels[i] == kMaskLit;
    }
    out.lit_box = std::min(out.lit_box, lit_box);
  }
  return out;
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
