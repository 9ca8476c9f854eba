#include <gtest/gtest.h>

#include "../../testing/test_scenes.h"
#include "shadowkit/scene/scene_file.h"
#include "svbsp_test_support.h"

namespace shadowkit::svbsp {
namespace {

using testing::face_areas;
using testing::light_fragments;

const Camera kCamera = testing::camera({0, 9, 6}, {0, 0, 0}, 64, 48);

// A strip [x0, x1] x [-1, 1] at height y: a "line" of Fig. 2 extruded along z.
PolygonSoup strip(double x0, double x1, double y) {
  return testing::horizontal_quad(x0, x1, -1, 1, y);
}

TEST(Svbsp, FigureTwoSplitsTheFarLineAtTheShadowPlaneThroughB) {
  // Light at (0, 10); ab = [-2, -0.5] and cd = [1, 2] at y = 6 shadow nothing of each
  // other; ef = [-3, 0] at y = 3 is cut at g, the shadow of b: x = -0.5 * 7 / 4 = -0.875.
  // The strips' ends at z = +-1 project to +-1.75 on ef: ab covers ef's whole width.
  const Scene scene = testing::make_scene(kCamera, {testing::point_light({0, 10, 0})},
                                          {strip(-2, -0.5, 6), strip(1, 2, 6), strip(-3, 0, 3)});
  const LightFragments r = light_fragments(scene, 0);
  const auto areas = face_areas(r.fragments);
  EXPECT_NEAR(areas.at(0).lit, 3.0, 1e-12);
  EXPECT_NEAR(areas.at(1).lit, 2.0, 1e-12);
  EXPECT_NEAR(areas.at(2).shadowed, (3 - 0.875) * 2, 1e-12);  // eg
  EXPECT_NEAR(areas.at(2).lit, 0.875 * 2, 1e-12);             // gf
  EXPECT_EQ(r.fragments.size(), 4u);
  // ab adds four planes; cd three, its edge at z = 1 lies in ab's plane for it; gf three,
  // its edge at g lies in b's plane.
  EXPECT_EQ(r.svbsp_nodes, 10u);
}

TEST(Svbsp, SquareOverPlaneHasTheAnalyticShadowArea) {
  const Scene point = testing::square_over_plane(kCamera, testing::point_light({0, 4, 0}));
  const double side = 8.0 / 3.0;  // the 2x2 square scaled by 4 / (4 - 1)
  const auto a = face_areas(light_fragments(point, 0).fragments);
  EXPECT_NEAR(a.at(0).shadowed, side * side, 1e-10);
  EXPECT_NEAR(a.at(0).lit, 400 - side * side, 1e-10);
  EXPECT_NEAR(a.at(1).lit, 4, 1e-12);

  // A directional light shifts the shadow without scaling it.
  const Scene sun =
      testing::square_over_plane(kCamera, testing::directional_light({0.5, -1, 0.25}));
  const auto b = face_areas(light_fragments(sun, 0).fragments);
  EXPECT_NEAR(b.at(0).shadowed, 4, 1e-10);
  EXPECT_NEAR(b.at(0).lit, 396, 1e-10);
}

TEST(Svbsp, OpenSquareShadowsFromBelowToo) {
  // Light under the square, ground above it: the square's underside faces the light.
  const Scene scene = testing::make_scene(
      kCamera, {testing::point_light({0, -2, 0})},
      {testing::horizontal_quad(-10, 10, -10, 10, 2), testing::horizontal_quad(-1, 1, -1, 1, 0)});
  const auto a = face_areas(light_fragments(scene, 0).fragments);
  EXPECT_NEAR(a.at(0).shadowed, 16, 1e-10);  // scaled by 4 / 2
  EXPECT_NEAR(a.at(1).lit, 4, 1e-12);
}

TEST(Svbsp, LightInAPolygonsPlaneShadowsItAndItCastsNothing) {
  // A vertical quad in the plane x = 0, which holds the light.
  const Scene scene =
      testing::make_scene(kCamera, {testing::point_light({0, 4, 0})},
                          {testing::horizontal_quad(-10, 10, -10, 10, 0),
                           testing::polygon({{0, 1, -1}, {0, 1, 1}, {0, 2, 1}, {0, 2, -1}})});
  const auto a = face_areas(light_fragments(scene, 0).fragments);
  EXPECT_NEAR(a.at(0).lit, 400, 1e-10);
  EXPECT_EQ(a.at(0).shadowed, 0);
  EXPECT_NEAR(a.at(1).shadowed, 2, 1e-12);
  EXPECT_EQ(a.at(1).lit, 0);
}

TEST(Svbsp, OverlappingCoplanarPolygonsDoNotShadowEachOther) {
  const Scene scene = testing::make_scene(
      kCamera, {testing::point_light({0, 4, 0})},
      {testing::horizontal_quad(-10, 10, -10, 10, 0), testing::horizontal_quad(-1, 1, -1, 1, 1),
       testing::horizontal_quad(0, 2, -1, 1, 1)});
  const auto a = face_areas(light_fragments(scene, 0).fragments);
  EXPECT_NEAR(a.at(1).lit, 4, 1e-12);
  EXPECT_NEAR(a.at(2).lit, 4, 1e-12);
  // The union [-1, 2] x [-1, 1] scaled by 4 / 3.
  EXPECT_NEAR(a.at(0).shadowed, 6 * 16.0 / 9.0, 1e-10);
}

TEST(Svbsp, PolygonsTouchingAtAVertexCastDisjointShadows) {
  const Scene scene = testing::make_scene(kCamera, {testing::point_light({0, 4, 0})},
                                          {testing::horizontal_quad(-10, 10, -10, 10, 0),
                                           testing::polygon({{0, 1, 0}, {-1, 1, 1}, {-1, 1, -1}}),
                                           testing::polygon({{0, 1, 0}, {1, 1, -1}, {1, 1, 1}})});
  const auto a = face_areas(light_fragments(scene, 0).fragments);
  EXPECT_NEAR(a.at(1).lit, 1, 1e-12);
  EXPECT_NEAR(a.at(2).lit, 1, 1e-12);
  EXPECT_NEAR(a.at(0).shadowed, 2 * 16.0 / 9.0, 1e-10);
}

TEST(Svbsp, FragmentsOfEveryFaceSumToItsArea) {
  for (const char* name : {"tetra:3", "three-lights", "room", "cubes:125"}) {
    const Scene scene = load_scene(name, {});
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
      const LightFragments r = light_fragments(scene, l);
      const auto areas = face_areas(r.fragments);
      ASSERT_EQ(areas.size(), scene.face_count()) << name;
      for (const auto& [face, a] : areas) {
        const double expected =
            scene.objects[scene.object_of_face(face)].mesh.areas[scene.local_face(face)];
        EXPECT_NEAR(a.lit + a.shadowed, expected, 1e-9 * (1 + expected)) << name << " " << face;
      }
    }
  }
}

}  // namespace
}  // namespace shadowkit::svbsp
