#include "contour_edges.h"

#include <gtest/gtest.h>

#include <numeric>

#include "testing/test_scenes.h"

namespace shadowkit::volume {
namespace {

Mesh mesh_of(const PolygonSoup& soup) {
  return Mesh::build(soup, "test", {});
}

struct LoopShape {
  std::size_t edges = 0, loops = 0;
  bool all_closed = true;
  int weight = 0;  ///< the common weight, or -1 if they differ
};

LoopShape shape(const Mesh& mesh, const Light& light) {
  const std::vector<ContourEdge> edges = find_contour_edges(mesh, light);
  const std::vector<ContourLoop> loops = chain_contour_loops(edges);
  LoopShape s{edges.size(), loops.size(), true, edges.empty() ? 0 : edges[0].weight};
  std::size_t chained = 0;
  for (const ContourLoop& loop : loops) {
    s.all_closed = s.all_closed && loop.closed;
    chained += loop.edges.size();
    // Closure, edge by edge: each edge starts where the previous one ended.
    for (std::size_t k = 0; k < loop.edges.size(); ++k) {
      const ContourEdge& a = edges[loop.edges[k]];
      const ContourEdge& b = edges[loop.edges[(k + 1) % loop.edges.size()]];
      if (a.to != b.from) s.all_closed = false;
    }
  }
  EXPECT_EQ(chained, edges.size());
  for (const ContourEdge& e : edges) {
    if (e.weight != s.weight) s.weight = -1;
  }
  return s;
}

const PolygonSoup kCube = testing::box({-1, -1, -1}, {1, 1, 1});

TEST(ContourEdges, CubeLitFromACornerDirectionHasOneLoopOfSix) {
  const LoopShape s = shape(mesh_of(kCube), Light::directional({-1, -2, -3}));
  EXPECT_EQ(s.edges, 6u);
  EXPECT_EQ(s.loops, 1u);
  EXPECT_TRUE(s.all_closed);
  EXPECT_EQ(s.weight, 2);  // a light-facing and a turned-away face, both casting
}

TEST(ContourEdges, CubeLitFromAboveAFaceHasOneLoopOfFour) {
  const LoopShape s = shape(mesh_of(kCube), Light::point({0.2, 5, -0.1}));
  EXPECT_EQ(s.edges, 4u);
  EXPECT_EQ(s.loops, 1u);
  EXPECT_TRUE(s.all_closed);
  EXPECT_EQ(s.weight, 2);
}

TEST(ContourEdges, FacesEdgeOnToTheLightCastNothing) {
  // Light straight down: the four sides contain the light's direction and cast no volume;
  // the top's and the bottom's volumes are each bounded by their own rim.
  const LoopShape s = shape(mesh_of(kCube), Light::directional({0, -1, 0}));
  EXPECT_EQ(s.edges, 8u);
  EXPECT_EQ(s.loops, 2u);
  EXPECT_TRUE(s.all_closed);
  EXPECT_EQ(s.weight, 1);
}

TEST(ContourEdges, OpenQuadIsBoundedByItsFourBoundaryEdgesFromEitherSide) {
  const Mesh quad = mesh_of(testing::horizontal_quad(-1, 1, -1, 1, 0));
  for (const Light& light : {Light::point({0.3, 4, 0}), Light::point({0.3, -4, 0})}) {
    const LoopShape s = shape(quad, light);
    EXPECT_EQ(s.edges, 4u);
    EXPECT_EQ(s.loops, 1u);
    EXPECT_TRUE(s.all_closed);
    EXPECT_EQ(s.weight, 1);
  }
}

TEST(ContourEdges, TwoCubesInOneMeshGiveTwoLoops) {
  PolygonSoup two = testing::box({-3, 0, 0}, {-1, 2, 2});
  two.append(testing::box({1, 0, 0}, {3, 2, 2}));
  const LoopShape s = shape(mesh_of(two), Light::directional({-1, -2, -3}));
  EXPECT_EQ(s.edges, 12u);
  EXPECT_EQ(s.loops, 2u);
  EXPECT_TRUE(s.all_closed);
}

TEST(ContourEdges, OfSomeFacesAreTheMeshsContourEdgesAlongThem) {
  // A sub-object's faces (the second cube's) give the mesh's contour edges that its faces
  // own, in the same order, and nothing of the other cube.
  PolygonSoup two = testing::box({-3, 0, 0}, {-1, 2, 2});
  two.append(testing::box({1, 0, 0}, {3, 2, 2}));
  const Mesh mesh = mesh_of(two);
  const Light light = Light::point({-5, 6, 7});
  const std::vector<std::uint32_t> second{6, 7, 8, 9, 10, 11};
  std::vector<ContourEdge> of_second;
  find_contour_edges(mesh, second, light, of_second);
  std::vector<std::uint32_t> found, expected;
  for (const ContourEdge& e : of_second) found.push_back(e.edge);
  for (const ContourEdge& e : find_contour_edges(mesh, light)) {
    if (mesh.edge_uses[mesh.edges[e.edge].first_use].face >= 6) expected.push_back(e.edge);
  }
  EXPECT_EQ(found.size(), 6u);
  EXPECT_EQ(found, expected);
  EXPECT_EQ(chain_contour_loops(of_second).size(), 1u);
}

TEST(ContourEdges, OfSomeFacesAreFoundAlikeWhateverTheirEdgeIdsSpan) {
  // 6,000 cubes in a row, 72,000 edges: all faces (ids marked, in parallel runs), and the
  // first and the last cube alone (ids far apart, sorted). Each as the whole mesh's.
  PolygonSoup row;
  for (int i = 0; i < 6000; ++i) row.append(testing::box({3.0 * i, 0, 0}, {3.0 * i + 2, 2, 2}));
  const Mesh mesh = mesh_of(row);
  const Light light = Light::point({-5, 6, 7});
  const std::vector<ContourEdge> whole = find_contour_edges(mesh, light);
  const auto edge_ids = [](const std::vector<ContourEdge>& edges) {
    std::vector<std::uint32_t> ids;
    for (const ContourEdge& e : edges) ids.push_back(e.edge);
    return ids;
  };
  std::vector<std::uint32_t> all(mesh.face_count()), ends{0, 1, 2, 3, 4, 5};
  std::iota(all.begin(), all.end(), 0u);
  for (std::uint32_t f = std::uint32_t(mesh.face_count()) - 6; f < mesh.face_count(); ++f)
    ends.push_back(f);
  std::vector<ContourEdge> found;
  find_contour_edges(mesh, all, light, found);
  EXPECT_EQ(edge_ids(found), edge_ids(whole));
  find_contour_edges(mesh, ends, light, found);
  std::vector<std::uint32_t> expected;
  for (const ContourEdge& e : whole) {
    const std::uint32_t f = mesh.edge_uses[mesh.edges[e.edge].first_use].face;
    if (f < 6 || f >= mesh.face_count() - 6) expected.push_back(e.edge);
  }
  EXPECT_EQ(edge_ids(found), expected);
  EXPECT_GE(expected.size(), 8u);
}

TEST(ContourEdges, NonManifoldEdgeWeighsTheSumOfItsFaces) {
  // Three half-open pages around the spine x = y = 0: two on the same side of the spine's
  // shadow polygon (light above) add up, the third one cancels one of them.
  PolygonSoup pages = testing::polygon({{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}});
  pages.append(testing::polygon({{0, 0, 0}, {0, 0, 1}, {1, -1, 1}, {1, -1, 0}}));
  pages.append(testing::polygon({{0, 0, 0}, {0, 0, 1}, {-1, 0, 1}, {-1, 0, 0}}));
  const Mesh mesh = mesh_of(pages);
  ASSERT_EQ(mesh.nonmanifold_edge_count(), 1u);
  const Light light = Light::point({0, 5, 0.5});
  int spine = 0;
  for (const ContourEdge& e : find_contour_edges(mesh, light)) {
    const MeshEdge& m = mesh.edges[e.edge];
    if (mesh.vertices[m.v0].x == 0 && mesh.vertices[m.v1].x == 0 && mesh.vertices[m.v0].y == 0 &&
        mesh.vertices[m.v1].y == 0) {
      spine = e.weight;
    }
  }
  EXPECT_EQ(spine, 1);
}

}  // namespace
}  // namespace shadowkit::volume
