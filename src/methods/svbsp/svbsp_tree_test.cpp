#include <gtest/gtest.h>

#include <map>
#include <string>

#include "shadowkit/scene/scene_file.h"
#include "svbsp_test_support.h"
#include "testing/test_scenes.h"

namespace shadowkit::svbsp {
namespace {

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

// Fragment count and per-face lit and shadowed areas of a scene, one light.
struct Totals {
  std::size_t fragments = 0;
  std::map<std::uint32_t, FaceAreas> areas;
};
Totals totals(const Scene& scene, std::size_t light, bool merge) {
  GeneratorSettings settings;
  settings.merge_siblings = merge;
  const LightFragments r =
      generate_shadows(SceneBsp::build(scene), scene, scene.lights[light], settings);
  return {r.fragments.size(), face_areas(r.fragments)};
}

TEST(Svbsp, SiblingFragmentsInTheSameStateMergeBackIntoTheUnsplitPolygon) {
  // The square's shadow on y = 0 is [-2, 2]^2. Two ground strips beside it cross two of its
  // four shadow planes each and lie outside a third: whichever edge the chain starts with,
  // one of them is split, and all its pieces end up lit.
  const Light light = testing::point_light({0, 10, 0});
  const ConvexPolygon square = make_polygon({{-1, 5, -1}, {1, 5, -1}, {1, 5, 1}, {-1, 5, 1}}, 0);
  const ConvexPolygon east = make_polygon({{3, 0, -3}, {4, 0, -3}, {4, 0, 3}, {3, 0, 3}}, 1);
  const ConvexPolygon north = make_polygon({{-3, 0, 3}, {3, 0, 3}, {3, 0, 4}, {-3, 0, 4}}, 2);
  for (const bool merge : {false, true}) {
    SvbspTree tree(light, 1e-9, merge);
    std::vector<Fragment> out;
    tree.determine_shadow(square, out);
    ASSERT_EQ(out.size(), 1u);
    out.clear();
    tree.classify(east, out);
    tree.classify(north, out);
    const auto areas = face_areas(out);
    EXPECT_NEAR(areas.at(1).lit, 6, 1e-12);
    EXPECT_NEAR(areas.at(2).lit, 6, 1e-12);
    EXPECT_EQ(areas.at(1).shadowed + areas.at(2).shadowed, 0);
    if (merge) {
      ASSERT_EQ(out.size(), 2u);  // each strip whole, with its own corners
      EXPECT_EQ(out[0].polygon.vertices, east.vertices);
      EXPECT_EQ(out[1].polygon.vertices, north.vertices);
    } else {
      EXPECT_GE(out.size(), 3u);
    }
  }
}

TEST(Svbsp, MergingSiblingsKeepsAreasAndReducesFragments) {
  for (const char* name : {"tetra:3", "cubes:125", "table", "room"}) {
    const Scene scene = load_scene(name, {});
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
      const Totals split = totals(scene, l, false), merged = totals(scene, l, true);
      ASSERT_EQ(split.areas.size(), merged.areas.size()) << name;
      for (const auto& [face, a] : split.areas) {
        const FaceAreas& b = merged.areas.at(face);
        const double tolerance = 1e-9 * (1 + a.lit + a.shadowed);
        EXPECT_NEAR(a.lit, b.lit, tolerance) << name << " " << face;
        EXPECT_NEAR(a.shadowed, b.shadowed, tolerance) << name << " " << face;
      }
      EXPECT_LE(merged.fragments, split.fragments) << name;
      if (std::string(name) == "tetra:3" || std::string(name) == "cubes:125") {
        EXPECT_LT(merged.fragments, split.fragments) << name;
      }
    }
  }
}

TEST(Svbsp, ClosedCubeGetsPlanesForItsContourAndOnePerInteriorEdge) {
  // Three faces of the cube see the light: six contour edges, three interior ones, twelve
  // edges in all. A face filtered after its neighbour finds their common edge already in a
  // plane of its cell and adds none for it; the first face of each pair still needs that
  // plane, as what is filtered after it is not shadowed beyond the edge: a face's contour
  // edges alone bound no volume of its own in a capless SVBSP tree. The solid filtered as a
  // unit does (SvbspContourPlanes.ACubeAddsItsSixContourPlanesOnly).
  const Scene scene = testing::make_scene(kCamera, {testing::point_light({4, 9, 5})},
                                          {testing::box({-1, 1, -1}, {1, 3, 1})});
  const LightFragments r = light_fragments(scene, 0);
  EXPECT_EQ(front_facing(scene, scene.lights[0]).polygons, 3u);
  EXPECT_GE(r.svbsp_nodes, 6u + 3u);
  EXPECT_LT(r.svbsp_nodes, 12u);
  EXPECT_EQ(r.fragments.size(), 6u);  // every face whole: three lit, three shadowed
  std::size_t lit = 0;
  for (const Fragment& f : r.fragments) lit += f.lit;
  EXPECT_EQ(lit, 3u);
}

}  // namespace
}  // namespace shadowkit::svbsp
