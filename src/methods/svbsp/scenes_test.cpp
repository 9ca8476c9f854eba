#include <gtest/gtest.h>

#include <filesystem>

#include "shadowkit/app/mask_compare.h"
#include "shadowkit/scene/scene_file.h"
#include "svbsp_method.h"

namespace shadowkit {
namespace {

ShadowMask mask_of(ShadowMethod& method, const Scene& scene, const VisibleSurfaceBuffer& vsb,
                   std::size_t light) {
  method.build(scene, light, {});
  ShadowMask mask(vsb.width, vsb.height, kMaskBackground);
  method.shade(scene, vsb, mask, {});
  return mask;
}

// Interior mismatch (percent) of svbsp against raytrace at 480x270, worst light.
double worst_interior_mismatch(Scene scene) {
  scene.camera.width = 480;
  scene.camera.height = 270;
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  const auto reference = make_method("raytrace", {});
  SvbspMethod svbsp({});
  reference->prepare(scene, {});
  svbsp.prepare(scene, {});
  double worst = 0;
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const MaskComparison c = compare_masks(mask_of(*reference, scene, vsb, l),
                                           mask_of(svbsp, scene, vsb, l), vsb.object_ids());
    worst = std::max(worst, c.interior_pct());
  }
  return worst;
}

class BuiltInScene : public ::testing::TestWithParam<const char*> {};

TEST_P(BuiltInScene, AgreesWithTheReference) {
  EXPECT_LE(worst_interior_mismatch(load_scene(GetParam(), {})), 0.05);
}

INSTANTIATE_TEST_SUITE_P(Svbsp, BuiltInScene,
                         ::testing::Values("cubes:125", "tetra:3", "room", "table", "three-lights",
                                           "square"));

TEST(SvbspScenes, EveryExampleAgreesWithTheReference) {
  const std::filesystem::path dir = std::filesystem::path(SHADOWKIT_SOURCE_DIR) / "examples";
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    EXPECT_LE(worst_interior_mismatch(load_scene_file(entry.path(), {})), 0.05) << entry.path();
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

}  // namespace
}  // namespace shadowkit
