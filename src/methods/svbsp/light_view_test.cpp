#include "light_view.h"

#include <gtest/gtest.h>

#include "shadowkit/scene/scene_file.h"
#include "svbsp_test_support.h"
#include "testing/test_scenes.h"

namespace shadowkit::svbsp {
namespace {

Bounds3 box(Vec3 lo, Vec3 hi) {
  Bounds3 b;
  b.add(lo);
  b.add(hi);
  return b;
}

TEST(LightView, DirectionalPlanesHoldTheLightsDirectionAndOrderTheCoordinates) {
  const Light light = Light::directional({0.4, -1, -0.45});
  const auto view = LightView::of(light, box({-1, -1, -1}, {1, 1, 1}));
  ASSERT_TRUE(view);
  const Vec3 p{0.3, 0.2, -0.5};
  // A light ray is one point of the view.
  const auto a = view->coordinates(p), b = view->coordinates(p + light.direction * 0.7);
  EXPECT_NEAR(a[0], b[0], 1e-12);
  EXPECT_NEAR(a[1], b[1], 1e-12);
  for (const int axis : {0, 1}) {
    const Plane plane = view->plane(axis, a[std::size_t(axis)] - 0.1);
    EXPECT_NEAR(dot(plane.normal, light.direction), 0, 1e-12);
    EXPECT_NEAR(plane.distance(p), 0.1, 1e-12);  // greater coordinate: positive side
  }
}

TEST(LightView, PointLightPlanesPassThroughTheLightAndTheirPoints) {
  const Light light = Light::point({-24, 30, 9});
  const auto view = LightView::of(light, box({-10, 0, -10}, {10, 3, 10}));
  ASSERT_TRUE(view);
  const Vec3 p{2, 1, -3}, q{-5, 2.5, 7};
  const auto c = view->coordinates(p);
  for (const int axis : {0, 1}) {
    const Plane through_p = view->plane(axis, c[std::size_t(axis)]);
    EXPECT_NEAR(length(through_p.normal), 1, 1e-12);
    EXPECT_NEAR(through_p.distance(light.position), 0, 1e-12);
    EXPECT_NEAR(through_p.distance(p), 0, 1e-12);
    // Side and coordinate agree for a point on either side.
    const double qc = view->coordinates(q)[std::size_t(axis)];
    EXPECT_EQ(through_p.distance(q) > 0, qc > c[std::size_t(axis)]);
  }
}

TEST(LightView, NoViewForALightInsideOrAgainstTheBoxOrAnEmptyBox) {
  const Bounds3 b = box({-1, -1, -1}, {1, 1, 1});
  EXPECT_FALSE(LightView::of(Light::point({0, 0.5, 0}), b));
  EXPECT_FALSE(LightView::of(Light::point({1, 1, 1}), b));  // on a corner
  EXPECT_TRUE(LightView::of(Light::point({0, 3, 0}), b));
  EXPECT_FALSE(LightView::of(Light::directional({0, -1, 0}), Bounds3{}));
}

// The fragments of \p scene's light 0, its pieces filtered front to back down a tree cut
// into 2^levels cells first.
std::vector<Fragment> divided_fragments(const Scene& scene, std::size_t levels) {
  const Light& light = scene.lights[0];
  const SceneBsp bsp = SceneBsp::build(scene);
  SvbspTree tree(light, 1e-9 * 30);
  const auto view = LightView::of(light, scene.bounds());
  // A grid of points over the ground: the cells cut the shadow of the square too.
  std::vector<LightView::Coordinates> points;
  for (int i = 0; i < 8; ++i) {
    for (int k = 0; k < 8; ++k) points.push_back(view->coordinates({i - 3.5, 0, k - 3.5}));
  }
  tree.divide(*view, points, levels);
  EXPECT_EQ(tree.node_count(), (std::size_t(1) << levels) - 1);
  std::vector<Fragment> out;
  bsp.front_to_back(light, [&](NodePieces node) {
    for (const ConvexPolygon& p : node.pieces) tree.determine_shadow(p, out);
  });
  return out;
}

TEST(SvbspBalance, CellsKeepTheAnalyticShadowAndEveryArea) {
  const Camera camera = testing::camera({0, 9, 6}, {0, 0, 0}, 64, 48);
  const double side = 8.0 / 3.0;
  for (const Light& light : {testing::point_light({0, 4, 0}), testing::point_light({0.3, 4, -0.2}),
                             testing::directional_light({0.5, -1, 0.25})}) {
    const Scene scene = testing::square_over_plane(camera, light);
    const double shadow = light.type == Light::Type::point ? side * side : 4;
    for (const std::size_t levels : {0, 1, 4}) {
      const auto areas = face_areas(divided_fragments(scene, levels));
      EXPECT_NEAR(areas.at(0).shadowed, shadow, 1e-10) << levels;
      EXPECT_NEAR(areas.at(0).lit, 400 - shadow, 1e-10) << levels;
      EXPECT_NEAR(areas.at(1).lit, 4, 1e-12) << levels;
    }
  }
}

TEST(SvbspBalance, NoCellsFromTooFewPoints) {
  const Light light = testing::point_light({0, 4, 0});
  SvbspTree tree(light, 1e-9);
  const auto view = LightView::of(light, box({-1, 0, -1}, {1, 1, 1}));
  std::vector<LightView::Coordinates> one{{0, 0}};
  tree.divide(*view, one, 5);
  EXPECT_EQ(tree.node_count(), 0u);
}

TEST(SvbspBalance, TheMethodsAreasDoNotDependOnIt) {
  // cubes:2000 has enough pieces for cells; its point light is outside the field.
  const Scene scene = load_scene("cubes:2000", {});
  const auto balanced = face_areas(run_method(scene, 0).fragments);
  const auto unbalanced = face_areas(run_method(scene, 0, {{"balance", "0"}}).fragments);
  ASSERT_EQ(balanced.size(), unbalanced.size());
  for (const auto& [face, a] : balanced) {
    const FaceAreas& b = unbalanced.at(face);
    EXPECT_NEAR(a.lit, b.lit, 1e-9) << face;
    EXPECT_NEAR(a.shadowed, b.shadowed, 1e-9) << face;
  }
}

}  // namespace
}  // namespace shadowkit::svbsp
