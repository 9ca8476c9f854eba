#include "multi_light.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "shadowkit/core/error.h"
#include "shadowkit/scene/scene_file.h"
#include "svbsp_test_support.h"
#include "testing/test_scenes.h"

namespace shadowkit::svbsp {
namespace {

TEST(SvbspMultiLight, ThreeLightsConserveAreaAndMatchSingleLightRuns) {
  const Scene scene = load_scene("three-lights", {});
  const SceneBsp bsp = SceneBsp::build(scene);
  const MultiLightFragments multi = generate_multi_light_shadows(bsp, scene);
  ASSERT_EQ(multi.passes.size(), 3u);
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const auto pipelined = face_areas(multi.fragments, l);
    const auto single = face_areas(generate_shadows(bsp, scene, scene.lights[l]).fragments);
    ASSERT_EQ(pipelined.size(), scene.face_count());
    for (const auto& [face, areas] : pipelined) {
      const double total = face_area(scene, face);
      EXPECT_NEAR(areas.lit + areas.shadowed, total, 1e-9 * total) << "face " << face;
      EXPECT_NEAR(areas.lit, single.at(face).lit, 1e-9 * total) << "face " << face << " L" << l;
    }
  }
  // Pipelining splits more than any one light alone, and the lights together shadow some
  // fragments partly: masks other than all-lit and all-shadowed occur.
  EXPECT_GT(multi.fragments.size(), multi.passes.front().fragments);
  EXPECT_TRUE(
      std::any_of(multi.fragments.begin(), multi.fragments.end(),
                  [](const MaskedFragment& f) { return f.lit_mask != 0 && f.lit_mask != 7; }));
}

TEST(SvbspMultiLight, LightsFacingFewerPolygonsComeFirst) {
  // The light below sees the fronts of the box's bottom and two sides (3 polygons); the
  // light above those of the ground, the square, the box's top and the same two sides (5).
  const Camera cam = testing::camera({0, 9, 6}, {0, 0, 0}, 64, 48);
  const Scene scene = testing::make_scene(
      cam, {testing::point_light({0, 4, 0}), testing::point_light({0, -4, 0})},
      {testing::horizontal_quad(-10, 10, -10, 10, 0), testing::horizontal_quad(-1, 1, -1, 1, 1),
       testing::box({3, 0, 3}, {4, 1, 4})});
  EXPECT_LT(front_facing(scene, scene.lights[1]).polygons,
            front_facing(scene, scene.lights[0]).polygons);
  EXPECT_EQ(light_order(scene), (std::vector<std::size_t>{1, 0}));
  const MultiLightFragments multi = generate_multi_light_shadows(SceneBsp::build(scene), scene);
  EXPECT_EQ(multi.passes.front().light, 1u);
}

TEST(SvbspMultiLight, MoreLightsThanMaskBitsIsAnInputError) {
  const Camera cam = testing::camera({0, 9, 6}, {0, 0, 0}, 64, 48);
  Scene scene = testing::square_over_plane(cam, testing::point_light({0, 4, 0}));
  scene.lights.resize(kMaxLights + 1, scene.lights.front());
  EXPECT_THROW(generate_multi_light_shadows(SceneBsp::build(scene), scene), InputError);
}

}  // namespace
}  // namespace shadowkit::svbsp
