// svbsp.contour_planes=1 (§6, contour edges only): which solids are convex, that the scene
// BSP tree keeps them whole, and that their contour planes alone give the default's areas.
#include "convex_solids.h"

#include <gtest/gtest.h>

#include <string>

#include "shadowkit/scene/scene_file.h"
#include "svbsp_test_support.h"
#include "testing/test_scenes.h"

namespace shadowkit::svbsp {
namespace {

const Camera kCamera = testing::camera({0, 9, 6}, {0, 0, 0}, 64, 48);
const std::map<std::string, std::string> kContour = {{"contour_planes", "1"}};

// A closed L-shaped prism, 2 high: not convex.
PolygonSoup l_prism() {
  const Vec3 outline[] = {{0, 0, 0}, {2, 0, 0}, {2, 0, 1}, {1, 0, 1}, {1, 0, 2}, {0, 0, 2}};
  PolygonSoup soup;
  for (const Vec3& p : outline) soup.positions.push_back(p);
  for (const Vec3& p : outline) soup.positions.push_back(p + Vec3{0, 2, 0});
  soup.add_face({0, 1, 2, 3, 4, 5});    // bottom, normal -y
  soup.add_face({11, 10, 9, 8, 7, 6});  // top, normal +y
  for (std::uint32_t i = 0; i < 6; ++i) {
    const std::uint32_t j = (i + 1) % 6;
    soup.add_face({i, i + 6, j + 6, j});
  }
  return soup;
}

std::size_t convex_count(const std::vector<PolygonSoup>& soups) {
  const Scene scene = testing::make_scene(kCamera, {testing::point_light({0, 9, 0})}, soups);
  return ConvexSolids(scene, scene.outward_solids()).size();
}

TEST(ConvexSolids, BoxesAndSpheresAreConvexButNotAnLShapeARoomOrAnOpenQuad) {
  EXPECT_EQ(convex_count({testing::box({-1, -1, -1}, {1, 1, 1})}), 1u);
  EXPECT_EQ(convex_count({sphere(48, 24)}), 1u);
  EXPECT_EQ(convex_count({l_prism()}), 0u);
  EXPECT_EQ(convex_count({inside_out(testing::box({-1, -1, -1}, {1, 1, 1}))}), 0u);
  EXPECT_EQ(convex_count({testing::horizontal_quad(-1, 1, -1, 1, 0)}), 0u);
  // The tetrahedra of tetra:3 touch only at corners: each is a solid of its own.
  const Scene tetra = load_scene("tetra:3", {});
  EXPECT_EQ(ConvexSolids(tetra, tetra.outward_solids()).size(), 64u);
}

TEST(ConvexSolids, ContourPlanesOfABoxLitFromAboveACorner) {
  // Three faces turned to the light: a hexagonal silhouette, six contour planes, each with
  // the box on its positive side.
  const Scene scene = testing::make_scene(kCamera, {testing::point_light({4, 9, 5})},
                                          {testing::box({-1, 1, -1}, {1, 3, 1})});
  const ConvexSolids solids(scene, scene.outward_solids());
  const Light& light = scene.lights[0];
  const auto planes = solids.contour_planes(
      0, light, [&](std::uint32_t f) { return light_side(scene.face_plane(f), light) > 0; });
  ASSERT_EQ(planes.size(), 6u);
  for (const ShadowPlane& s : planes) {
    EXPECT_NEAR(s.plane.distance(light.position), 0, 1e-12);
    EXPECT_GT(s.plane.distance({0, 2, 0}), 0);
  }
}

TEST(SvbspContourPlanes, ACubeAddsItsSixContourPlanesOnly) {
  // Default: a plane per edge of the first face of each lit pair as well (9 to 11 nodes,
  // Svbsp.ClosedCubeGetsPlanesForItsContourAndOnePerInteriorEdge).
  const Scene scene = testing::make_scene(kCamera, {testing::point_light({4, 9, 5})},
                                          {testing::box({-1, 1, -1}, {1, 3, 1})});
  const MethodRun run = run_method(scene, 0, kContour);
  EXPECT_EQ(run.svbsp_nodes, 6);
  EXPECT_EQ(run.convex_units, 1);
  EXPECT_EQ(run.fragments.size(), 6u);  // three faces lit whole, three shadowed
  EXPECT_EQ(run.light_facing, 3);
}

// The per-face areas of contour_planes=1 against the default's, and the node counts.
void expect_default_areas(const Scene& scene, const std::string& name, bool fewer_nodes) {
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const MethodRun contour = run_method(scene, l, kContour);
    const MethodRun plain = run_method(scene, l);
    const auto want = face_areas(plain.fragments);
    const auto got = face_areas(contour.fragments);
    ASSERT_EQ(got.size(), scene.face_count()) << name;
    for (const auto& [face, a] : want) {
      const double size = face_area(scene, face);
      EXPECT_NEAR(got.at(face).lit, a.lit, 1e-9 * size) << name << " L" << l << " " << face;
      EXPECT_NEAR(got.at(face).shadowed, a.shadowed, 1e-9 * size) << name << " " << face;
    }
    if (fewer_nodes) {
      EXPECT_LT(contour.svbsp_nodes, plain.svbsp_nodes) << name << " L" << l;
    }
  }
}

TEST(SvbspContourPlanes, GiveTheDefaultsAreasWithFewerPlanes) {
  for (const char* name : {"tetra:3", "cubes:125", "three-lights"}) {
    expect_default_areas(load_scene(name, {}), name, true);
  }
  // Fewer planes per unit do not make a smaller tree everywhere: the scene BSP trees differ
  // (units kept whole, or their faces), and so does the order in which the light meets the
  // pieces. The table's chairs are boxes that meet: its tree with units splits 223
  // polygons, the default's 189, and its SVBSP tree holds 271 nodes to the default's 252.
  expect_default_areas(load_scene("table", {}), "table", false);
  EXPECT_EQ(run_method(load_scene("cubes:125", {}), 0, kContour).convex_units, 125);
}

TEST(SvbspContourPlanes, LightsInsideOnAndAtTheCornerOfABox) {
  // Inside the box no face is turned to the light: it is no unit, each face goes alone.
  // In the plane of the top face: that face is edge-on, its edges with the sides are
  // contour edges. At a corner: three faces edge-on, none turned to the light.
  const std::vector<PolygonSoup> soups = {testing::horizontal_quad(-10, 10, -10, 10, 0),
                                          testing::box({-1, 0.5, -1}, {1, 1.5, 1})};
  for (const Vec3 light : {Vec3{0.2, 1, 0.3}, Vec3{-3, 1.5, 1}, Vec3{1, 1.5, 1}}) {
    const Scene scene = testing::make_scene(kCamera, {testing::point_light(light)}, soups);
    expect_default_areas(scene, "box", false);
  }
  const Scene sun =
      testing::make_scene(kCamera, {testing::directional_light({0.3, -1, -0.2})}, soups);
  expect_default_areas(sun, "box under a sun", true);
}

TEST(SvbspContourPlanes, ASolidThatAPlaneCrossesGoesOnAsItsFaces) {
  // A wide quad through the middle of the box: no plane keeps the box whole.
  const Scene scene = testing::make_scene(
      kCamera, {testing::point_light({2, 8, 1})},
      {testing::horizontal_quad(-10, 10, -10, 10, 0), testing::box({-1, 0.5, -1}, {1, 2.5, 1}),
       testing::horizontal_quad(-3, 3, -3, 3, 1.5)});
  EXPECT_EQ(run_method(scene, 0, kContour).convex_units, 0);
  expect_default_areas(scene, "pierced box", false);
}

}  // namespace
}  // namespace shadowkit::svbsp
