#include "shadowkit/scene/footprints.h"

#include <gtest/gtest.h>

#include "testing/test_scenes.h"

namespace shadowkit {
namespace {

// A 2 x 2 x 2 box at the origin's column over a ground, and small boxes below it at \p
// small (their lower corners), each 0.5 across.
Scene boxes_under_a_box(const Light& light, std::vector<Vec3> small) {
  std::vector<PolygonSoup> objects{testing::box({-1, 4, -1}, {1, 6, 1})};
  for (const Vec3& lo : small) objects.push_back(testing::box(lo, lo + Vec3{0.5, 0.5, 0.5}));
  objects.push_back(testing::horizontal_quad(-8, 8, -8, 8, 0));
  return testing::make_scene(testing::camera({0, 7, 12}, {0, 2, 0}, 160, 120), {light}, objects);
}

std::vector<char> shadowed(const Scene& scene) {
  const SubObjects parts = SubObjects::of(scene);
  return shadowed_sub_objects(parts, scene.lights[0], scene.bounds());
}

TEST(Footprints, MarkBoxesWhollyBehindANearerConvexBox) {
  // Sub-objects: the big box, then the small ones, then the ground.
  for (const Light& light :
       {testing::directional_light({0, -1, 0}), testing::point_light({0, 40, 0})}) {
    const Scene scene =
        boxes_under_a_box(light, {{-0.25, 1, -0.25},      // right under it: shadowed
                                  {0.7, 1, -0.25},        // half out to the side: lit in part
                                  {-0.25, 6.2, -0.25}});  // above it, nearer the light
    EXPECT_EQ(shadowed(scene), (std::vector<char>{0, 1, 0, 0, 0})) << int(light.type);
  }
}

TEST(Footprints, MarkABoxBehindTheSeamOfTwoNearerBoxes) {
  // Two boxes overlapping by 0.06 along x, far from a point light; a small box below the seam
  // lies in the shadow of their union, not of either. The grid spans the footprints, so
  // cells fit within the overlap (across the whole cube face, one cell would be 0.14 wide).
  std::vector<PolygonSoup> objects{testing::box({-1, 4, -1}, {0.1, 6, 1}),
                                   testing::box({0.04, 4, -1}, {1, 6, 1}),
                                   testing::box({-0.13, 1, -0.25}, {0.27, 1.5, 0.25})};
  for (const Light& light :
       {testing::point_light({0, 40, 0}), testing::directional_light({0, -1, 0})}) {
    const Scene scene =
        testing::make_scene(testing::camera({0, 7, 12}, {0, 2, 0}, 160, 120), {light}, objects);
    EXPECT_EQ(shadowed(scene), (std::vector<char>{0, 0, 1})) << int(light.type);
  }
}

TEST(Footprints, KeepABoxTouchingTheFarSide) {
  // 1e-3 below the big box's bottom face, the small box lies beyond its far reach; touching
  // it, where rounding could put it on either side, it is kept.
  const Light sun = testing::directional_light({0, -1, 0});
  EXPECT_EQ(shadowed(boxes_under_a_box(sun, {{-0.25, 3.499, -0.25}})),
            (std::vector<char>{0, 1, 0}));
  EXPECT_EQ(shadowed(boxes_under_a_box(sun, {{-0.25, 3.5, -0.25}})), (std::vector<char>{0, 0, 0}));
}

TEST(Footprints, NeedAFootprintOnOneCubeFaceOfAPointLight) {
  // A point light inside the big box: its corners look out on every face, so it leaves no
  // footprint, and nothing is marked.
  const Scene scene = boxes_under_a_box(testing::point_light({0, 5, 0}), {{-0.25, 1, -0.25}});
  EXPECT_EQ(shadowed(scene), (std::vector<char>{0, 0, 0}));
}

TEST(Footprints, TestEveryPartOfAWideBox) {
  // 2,304 small cubes make the grid 192 cells across: the grid is kept in strips of columns
  // that go by the light's first axis, here world z. Under a slab, a box across the three
  // strips is shadowed; a box across two, out from under the slab in the second, is not.
  std::vector<PolygonSoup> objects{testing::box({-1, 4, -5}, {1, 4.2, 5}),
                                   testing::box({-0.5, 2, -4.5}, {0.5, 2.5, 4.5}),
                                   testing::box({-0.5, 2, -1}, {0.5, 2.5, 5.8})};
  for (int i = 0; i < 48; ++i) {
    for (int j = 0; j < 48; ++j) {
      const Vec3 lo{-6 + 0.25 * i, 0, -6 + 0.25 * j};
      objects.push_back(testing::box(lo, lo + Vec3{0.1, 0.1, 0.1}));
    }
  }
  for (const Light& light :
       {testing::directional_light({0, -1, 0}), testing::point_light({0, 400, 0})}) {
    const std::vector<char> marked = shadowed(
        testing::make_scene(testing::camera({0, 7, 12}, {0, 2, 0}, 160, 120), {light}, objects));
    EXPECT_EQ(marked[1], 1) << int(light.type);
    EXPECT_EQ(marked[2], 0) << int(light.type);
  }
}

}  // namespace
}  // namespace shadowkit
