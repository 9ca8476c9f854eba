#include "convex_volume.h"

#include <gtest/gtest.h>

#include <cmath>

#include "shadowkit/scene/sub_objects.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"
#include "volume_method.h"

namespace shadowkit::volume {
namespace {

// An octahedron whose top vertex is pushed down through its centre: closed, not convex.
PolygonSoup dented_octahedron(Vec3 c) {
  PolygonSoup s;
  s.positions = {c + Vec3{1, 0, 0},  c + Vec3{-1, 0, 0},   c + Vec3{0, 0, 1},
                 c + Vec3{0, 0, -1}, c + Vec3{0, -0.5, 0}, c + Vec3{0, -1, 0}};
  for (const auto& [a, b] : {std::pair{0u, 2u}, {2u, 1u}, {1u, 3u}, {3u, 0u}}) {
    s.add_face({a, b, 4});
    s.add_face({b, a, 5});
  }
  return s;
}

// The ground, a 2x2x2 cube at height 1 to 3 and \p more, seen from above at 160x120.
Scene cube_scene(Vec3 eye, Light light, std::vector<PolygonSoup> more = {}) {
  std::vector<PolygonSoup> soups{testing::horizontal_quad(-10, 10, -10, 10, 0),
                                 testing::box({-1, 1, -1}, {1, 3, 1})};
  soups.insert(soups.end(), more.begin(), more.end());
  return testing::make_scene(testing::camera(eye, {0, 0, 0}, 160, 120), {light}, soups);
}

struct Counted {
  ShadowMask mask;
  double convex_volumes, shadowed_cells;
};

Counted count(const Scene& scene, const VisibleSurfaceBuffer& vsb) {
  VolumeMethod m({});
  ShadowMask mask = testing::method_mask(m, scene, vsb, 0);
  return {std::move(mask), testing::counter(m, "convex_volumes"),
          testing::counter(m, "shadowed_cells")};
}

Counted count(const Scene& scene) {
  return count(scene, render_visible_surfaces(scene, {}));
}

TEST(SubObjects, AreConvexWhenClosedWithEveryFacePlaneSupportingThem) {
  const Scene scene =
      cube_scene({0, 9, 6}, testing::point_light({0, 8, 0}),
                 {dented_octahedron({4, 2, 0}), testing::horizontal_quad(5, 6, 5, 6, 1)});
  const SubObjects parts = SubObjects::of(scene);
  ASSERT_EQ(parts.size(), 4u);
  EXPECT_FALSE(parts.convex[0]);  // the ground: open
  EXPECT_TRUE(parts.convex[1]);   // the cube
  EXPECT_FALSE(parts.convex[2]);  // closed, dented
  EXPECT_FALSE(parts.convex[3]);  // a square: open
}

TEST(ConvexVolume, SettlesTheCubesShadowOnTheGroundAsTheAnalyticOne) {
  // The light above the cube's centre: the top face's outline casts |x|, |z| < 1.6 (8 / 5).
  const Scene scene = cube_scene({0, 9, 6}, testing::point_light({0, 8, 0}));
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  const Counted c = count(scene, vsb);
  EXPECT_EQ(c.convex_volumes, 1);
  EXPECT_GT(c.shadowed_cells, 4);
  int shadowed = 0, lit = 0;
  for (std::size_t i = 0; i < c.mask.size(); ++i) {
    if (!vsb.covered(i) || vsb.object(i) != 0) continue;
    const Vec3 p = vsb.point(i);
    const double edge = std::max(std::abs(p.x), std::abs(p.z)) - 1.6;
    if (std::abs(edge) < 1e-4) continue;
    EXPECT_EQ(c.mask.pixels[i], edge < 0 ? kMaskShadow : kMaskLit) << p.x << " " << p.z;
    (edge < 0 ? shadowed : lit)++;
  }
  EXPECT_GT(shadowed, 100);
  EXPECT_GT(lit, 100);
}

TEST(ConvexVolume, IsNotTakenForADentedSubObject) {
  const Scene scene =
      cube_scene({0, 9, 6}, testing::point_light({3, 8, 0}), {dented_octahedron({4, 2, 0})});
  EXPECT_EQ(count(scene).convex_volumes, 1);  // the cube alone
  EXPECT_LT(testing::worst_interior_mismatch(scene, "volume"), 0.05);
}

TEST(ConvexVolume, IsNotTakenForALightInsideTheCube) {
  const Scene scene = cube_scene({0, 9, 6}, testing::point_light({0, 2, 0}));
  EXPECT_EQ(count(scene).convex_volumes, 0);
  EXPECT_LT(testing::worst_interior_mismatch(scene, "volume"), 0.05);
}

TEST(ConvexVolume, IsNotTakenWhenTheEyeIsInsideIt) {
  // The eye under the cube, in its shadow: the eye's count holds the cube's volume.
  const Scene scene = cube_scene({0.2, 0.5, 0.3}, testing::point_light({0, 8, 0}));
  const Counted c = count(scene);
  EXPECT_EQ(c.convex_volumes, 0);
  EXPECT_LT(testing::worst_interior_mismatch(scene, "volume"), 0.05);
}

TEST(ConvexVolume, DirectionalLightGivesTheSameShadowAsRaytrace) {
  const Scene scene =
      cube_scene({0, 9, 6}, testing::directional_light(normalize(Vec3{0.5, -1, 0.25})));
  EXPECT_EQ(count(scene).convex_volumes, 1);
  EXPECT_LT(testing::worst_interior_mismatch(scene, "volume"), 0.05);
}

TEST(ConvexVolume, OverlappingVolumesSettleTheirPixelsAsRaytrace) {
  // Cubes in a row away from the light: each lies in the shadow of the one before, and their
  // volumes overlap on the ground; whichever settles a pixel first, the mask is the same.
  const Scene scene = cube_scene({6, 9, 8}, testing::point_light({-6, 7, 0}),
                                 {testing::box({2, 0.5, -0.6}, {3, 1.5, 0.4}),
                                  testing::box({4.5, 0.2, -0.3}, {5.3, 1.0, 0.5})});
  const Counted c = count(scene);
  EXPECT_EQ(c.convex_volumes, 3);
  EXPECT_GT(c.shadowed_cells, 4);
  EXPECT_LT(testing::worst_interior_mismatch(scene, "volume"), 0.05);
}

TEST(OutlineColumns, HoldEveryColumnTheOutlineCoversWidenedByAPixel) {
  // The triangle (10, 0), (30, 20), (0, 20), edges from their upper ends down.
  const std::vector<OutlineEdge> outline{
      {10, 0, 30, 20, 1}, {10, 0, 0, 20, -0.5}, {0, 20, 30, 20, 0}};
  int xa = 0, xb = 100;
  ASSERT_TRUE(outline_columns(outline, 10, 10, xa, xb));
  // Rows 9 to 11: x from 4.5 to 21.
  EXPECT_EQ(xa, 3);
  EXPECT_EQ(xb, 22);
  xa = 0, xb = 100;
  EXPECT_FALSE(outline_columns(outline, 30, 40, xa, xb));  // below it
  xa = 25, xb = 100;
  EXPECT_FALSE(outline_columns(outline, 0, 2, xa, xb));  // right of it near the top
}

}  // namespace
}  // namespace shadowkit::volume
