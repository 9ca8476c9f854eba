#include "ridge_edges.h"

#include <gtest/gtest.h>

#include <map>

#include "shadowkit/scene/scene_file.h"
#include "testing/test_scenes.h"

namespace shadowkit::angular {
namespace {

Mesh build(const PolygonSoup& soup) {
  return Mesh::build(soup, "test", {});
}

std::vector<RidgeEdge> find_ridge_edges(const Mesh& mesh, const Light& light) {
  return angular::find_ridge_edges(mesh, far_sheets(mesh, light, one_solid(mesh)));
}

std::vector<std::uint32_t> hidden_edges_at_loops(const Mesh& mesh, const Light& light,
                                                 std::span<const RidgeEdge> edges) {
  return angular::hidden_edges_at_loops(mesh, far_sheets(mesh, light, one_solid(mesh)), edges);
}

// Sec. 2: at every vertex as many REs leave as arrive, so every loop closes.
void expect_closed_loops(const Mesh& mesh, const Light& light) {
  const std::vector<RidgeEdge> ridges = find_ridge_edges(mesh, light);
  std::map<std::uint32_t, int> balance;
  for (const RidgeEdge& re : ridges) ++balance[re.from], --balance[re.to];
  for (const auto& [vertex, b] : balance) EXPECT_EQ(b, 0) << "vertex " << vertex;
  for (const RidgeEdgeLoop& loop : chain_ridge_edge_loops(ridges)) EXPECT_TRUE(loop.closed);
}

TEST(RidgeEdges, ACubeLitFromACornerHasOneHexagonalLoop) {
  const Mesh cube = build(testing::box({-1, -1, -1}, {1, 1, 1}));
  const Light light = Light::point({3, 4, 5});
  const std::vector<RidgeEdge> ridges = find_ridge_edges(cube, light);
  ASSERT_EQ(ridges.size(), 6u);
  for (const RidgeEdge& re : ridges) EXPECT_FALSE(re.hidden_ridge);  // convex: all VREs
  const auto loops = chain_ridge_edge_loops(ridges);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_TRUE(loops[0].closed);
  EXPECT_EQ(loops[0].edges.size(), 6u);
  // The three edges at the far corner (-1, -1, -1) join hidden faces and loop vertices.
  EXPECT_EQ(hidden_edges_at_loops(cube, light, ridges).size(), 3u);
}

TEST(RidgeEdges, ACubeLitFromAboveHasTheTopSquareAsItsLoop) {
  const Mesh cube = build(testing::box({-1, -1, -1}, {1, 1, 1}));
  const auto ridges = find_ridge_edges(cube, Light::point({0, 5, 0}));
  const auto loops = chain_ridge_edge_loops(ridges);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].edges.size(), 4u);
  for (const RidgeEdge& re : ridges) {
    EXPECT_EQ(cube.vertices[re.from].y, 1);
    EXPECT_EQ(cube.vertices[re.to].y, 1);
  }
}

TEST(RidgeEdges, AnOpenSurfaceIsAThinSolidWhoseBoundaryIsItsLoop) {
  PolygonSoup grid = testing::horizontal_quad(0, 1, 0, 1, 0);
  grid.append(testing::horizontal_quad(1, 2, 0, 1, 0));
  grid.append(testing::horizontal_quad(0, 1, 1, 2, 0));
  grid.append(testing::horizontal_quad(1, 2, 1, 2, 0));
  const Mesh sheet = build(grid);
  for (const Light& light : {Light::point({0.5, 3, 0.5}), Light::point({0.5, -3, 0.5})}) {
    const auto ridges = find_ridge_edges(sheet, light);
    EXPECT_EQ(ridges.size(), 8u);  // the boundary, whichever side the light is on
    const auto loops = chain_ridge_edge_loops(ridges);
    ASSERT_EQ(loops.size(), 1u);
    EXPECT_TRUE(loops[0].closed);
    EXPECT_EQ(hidden_edges_at_loops(sheet, light, ridges).size(), 4u);  // interior edges
  }
}

TEST(RidgeEdges, AFoldLitFromOneSideOfEachSheetIsARidgeTwice) {
  // Two quads meeting at x = 0 like a roof; the light sees one from the front, one from the back.
  PolygonSoup roof = testing::polygon({{-1, 0, 1}, {0, 1, 1}, {0, 1, 0}, {-1, 0, 0}});
  roof.append(testing::polygon({{0, 1, 1}, {1, 0, 1}, {1, 0, 0}, {0, 1, 0}}));
  const Mesh mesh = build(roof);
  const Light light = Light::point({-5, 3, 0.5});
  int fold = 0;
  for (const RidgeEdge& re : find_ridge_edges(mesh, light)) {
    fold += mesh.vertices[re.from].x == 0 && mesh.vertices[re.to].x == 0;
  }
  EXPECT_EQ(fold, 2);
  expect_closed_loops(mesh, light);
}

TEST(RidgeEdges, AWallNearerTheLightThanTheFloorMakesAHiddenRidge) {
  // A floor (normal +y) and a wall (normal +x) sharing the edge x = y = 0; the light behind
  // the wall and above the floor: the wall is hidden and between the light and the floor.
  PolygonSoup valley = testing::polygon({{0, 0, 1}, {2, 0, 1}, {2, 0, 0}, {0, 0, 0}});
  valley.append(testing::polygon({{0, 0, 0}, {0, 2, 0}, {0, 2, 1}, {0, 0, 1}}));
  const Mesh mesh = build(valley);
  ASSERT_TRUE(mesh.consistently_oriented());
  const Light light = Light::point({-1, 3, 0.5});
  int corner = 0;
  for (const RidgeEdge& re : find_ridge_edges(mesh, light)) {
    const bool at_corner = mesh.vertices[re.from].x == 0 && mesh.vertices[re.from].y == 0 &&
                           mesh.vertices[re.to].x == 0 && mesh.vertices[re.to].y == 0;
    if (!at_corner) continue;
    ++corner;
    EXPECT_TRUE(re.hidden_ridge);
  }
  EXPECT_EQ(corner, 2);
  expect_closed_loops(mesh, light);
}

TEST(RidgeEdges, EveryLoopClosesOnEveryExampleMesh) {
  for (const char* name : {"tetra:3", "table", "room", "three-lights"}) {
    const Scene scene = load_scene(name, {});
    for (const Light& light : scene.lights) {
      for (const SceneObject& object : scene.objects) expect_closed_loops(object.mesh, light);
    }
  }
  const Scene open =
      load_scene_file(std::string(SHADOWKIT_SOURCE_DIR) + "/examples/open-meshes.json", {});
  for (const Light& light : open.lights) {
    for (const SceneObject& object : open.objects) expect_closed_loops(object.mesh, light);
  }
}

}  // namespace
}  // namespace shadowkit::angular
