#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "shadowkit/methods/mask_compare.h"
#include "shadowkit/methods/registry.h"
#include "shadowkit/scene/scene_file.h"
#include "svbsp_method.h"

namespace shadowkit::svbsp {
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

// §6's shadowed-fragments-only mode draws the shadowed fragments over the lit faces: the
// same mask from fewer fragments, but for pixel centres on snapped slivers of an outline.
TEST(SvbspScenes, ShadowedFragmentsOnlyGiveTheSameMasks) {
  for (const char* name : {"table", "three-lights", "room"}) {
    Scene scene = load_scene(name, {});
    scene.camera.width = 320;
    scene.camera.height = 180;
    const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
    SvbspMethod both({}), shadowed({"svbsp", {{"shadowed_only", "1"}}});
    both.prepare(scene, {});
    shadowed.prepare(scene, {});
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
      const ShadowMask expected = mask_of(both, scene, vsb, l);
      const ShadowMask got = mask_of(shadowed, scene, vsb, l);
      std::size_t differing = 0;
      for (std::size_t i = 0; i < got.pixels.size(); ++i) {
        differing += got.pixels[i] != expected.pixels[i];
      }
      // Only centres that no fragment of their face owns may differ: where a cut point on
      // the face's outline snaps off it (1/256 pixel), a sliver of the face has no fragment.
      EXPECT_LE(differing, got.pixels.size() / 10000) << name << " L" << l;
      EXPECT_LT(shadowed.fragments().size(), both.fragments().size()) << name << " L" << l;
      EXPECT_TRUE(std::none_of(shadowed.fragments().begin(), shadowed.fragments().end(),
                               [](const svbsp::Fragment& f) { return f.lit; }));
    }
  }
}

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
}  // namespace shadowkit::svbsp
