#include "convex_polygon.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace shadowkit::svbsp {
namespace {

ConvexPolygon unit_square() {
  return make_polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, 7);
}

TEST(ConvexPolygon, SplitConservesAreaAndKeepsTheFace) {
  ConvexPolygon neg, pos;
  const Plane plane{normalize(Vec3{1, 0.3, 0}), -0.4};
  split_polygon(unit_square(), plane, 1e-12, std::nullopt, neg, pos);
  ASSERT_GE(neg.vertices.size(), 3u);
  ASSERT_GE(pos.vertices.size(), 3u);
  EXPECT_NEAR(area(neg) + area(pos), 1.0, 1e-14);
  EXPECT_EQ(neg.face, 7u);
  EXPECT_EQ(pos.face, 7u);
  for (const Vec3& v : pos.vertices) EXPECT_GE(plane.distance(v), -1e-12);
  for (const Vec3& v : neg.vertices) EXPECT_LE(plane.distance(v), 1e-12);
}

TEST(ConvexPolygon, SplitThroughTwoVerticesGivesTwoTrianglesSharingTheFlaggedCut) {
  ConvexPolygon neg, pos;
  const Plane diagonal{normalize(Vec3{1, -1, 0}), 0};
  split_polygon(unit_square(), diagonal, 1e-12, 1e-12, neg, pos);
  ASSERT_EQ(neg.vertices.size(), 3u);
  ASSERT_EQ(pos.vertices.size(), 3u);
  EXPECT_NEAR(area(neg), 0.5, 1e-15);
  EXPECT_NEAR(area(pos), 0.5, 1e-15);
  // Exactly one edge of each triangle is the diagonal, and only it is flagged.
  for (const ConvexPolygon* p : {&neg, &pos}) {
    int flagged = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      const Vec3 a = p->vertices[i], b = p->vertices[(i + 1) % 3];
      const bool on =
          std::abs(diagonal.distance(a)) < 1e-12 && std::abs(diagonal.distance(b)) < 1e-12;
      EXPECT_EQ(bool(p->edge_in_tree[i]), on);
      flagged += p->edge_in_tree[i];
    }
    EXPECT_EQ(flagged, 1);
  }
}

TEST(ConvexPolygon, AnEdgeLyingInThePlaneIsFlaggedWithoutASplit) {
  ConvexPolygon neg, pos;
  const Plane x0{{1, 0, 0}, 0};  // holds the edge (0,1,0) -> (0,0,0)
  split_polygon(unit_square(), x0, 1e-12, 1e-12, neg, pos);
  EXPECT_TRUE(neg.vertices.empty());
  ASSERT_EQ(pos.vertices.size(), 4u);
  EXPECT_THAT(pos.edge_in_tree, ::testing::ElementsAre(0, 0, 0, 1));
}

TEST(ConvexPolygon, NeighboursAreCutAtBitIdenticalPoints) {
  // Two triangles share the edge a-b, walked in opposite directions.
  const Vec3 a{0.1, 0.2, 0.3}, b{1.7, 0.9, -0.4};
  const ConvexPolygon t0 = make_polygon({a, b, {0, 2, 0}}, 0);
  const ConvexPolygon t1 = make_polygon({b, a, {1, -2, 0}}, 1);
  const Plane plane{normalize(Vec3{1, 0.1, 0.2}), -0.77};
  ConvexPolygon n0, p0, n1, p1;
  split_polygon(t0, plane, 1e-12, std::nullopt, n0, p0);
  split_polygon(t1, plane, 1e-12, std::nullopt, n1, p1);
  std::vector<Vec3> cuts0, cuts1;
  for (const Vec3& v : p0.vertices)
    if (v != a && v != b && v != Vec3{0, 2, 0}) cuts0.push_back(v);
  for (const Vec3& v : p1.vertices)
    if (v != a && v != b && v != Vec3{1, -2, 0}) cuts1.push_back(v);
  // The cut on the shared edge appears in both, bit for bit.
  bool shared = false;
  for (const Vec3& u : cuts0)
    for (const Vec3& v : cuts1) shared = shared || u == v;
  EXPECT_TRUE(shared);
}

TEST(ConvexPolygon, MarkingEdgesInAPlaneIsWhatSplittingAPolygonOnOneSideGives) {
  // The square's edge y = 0 lies in the plane; a plane through one corner holds no edge; a
  // plane holding the whole square (a sliver) bounds nothing.
  const std::vector<std::pair<Plane, std::vector<std::uint8_t>>> cases = {
      {Plane{{0, 1, 0}, 0}, {1, 0, 0, 0}},
      {Plane{{0, -1, 0}, 0}, {1, 0, 0, 0}},
      {Plane{normalize(Vec3{1, 1, 0}), 0}, {0, 0, 0, 0}},
      {Plane{{0, 0, 1}, 0}, {0, 0, 0, 0}}};
  for (const auto& [plane, flags] : cases) {
    ConvexPolygon marked = unit_square();
    mark_edges_in_plane(marked, plane, 1e-12, 1e-12);
    EXPECT_THAT(marked.edge_in_tree, ::testing::ElementsAreArray(flags));
    ConvexPolygon neg, pos;
    split_polygon(unit_square(), plane, 1e-12, 1e-12, neg, pos);
    const ConvexPolygon& side = neg.vertices.empty() ? pos : neg;
    EXPECT_TRUE((neg.vertices.empty()) != (pos.vertices.empty()));
    EXPECT_THAT(side.edge_in_tree, ::testing::ElementsAreArray(flags));
    EXPECT_THAT(side.vertices, ::testing::ElementsAreArray(marked.vertices));
  }
}

TEST(ConvexPolygon, AnEdgeNearThePlaneButNotInItIsNotFlagged) {
  // The plane rises 1e-9 across the square's edge y = 0: the edge is within eps = 1e-8 of it
  // at both ends, but runs at an angle to it, so it stands for no plane but its own.
  const Plane tilted{normalize(Vec3{-1e-9, 1, 0}), 0};
  const double eps = 1e-8, within = eps * kInPlaneShare;
  ConvexPolygon marked = unit_square();
  mark_edges_in_plane(marked, tilted, eps, within);
  EXPECT_THAT(marked.edge_in_tree, ::testing::ElementsAre(0, 0, 0, 0));
  ConvexPolygon neg, pos;
  split_polygon(unit_square(), tilted, eps, within, neg, pos);
  EXPECT_TRUE(neg.vertices.empty());
  EXPECT_THAT(pos.edge_in_tree, ::testing::ElementsAre(0, 0, 0, 0));
  // A cut from the corner (1, 0, 0), within eps of the plane but off it, is not in it either;
  // the same cut from a corner in the plane is.
  for (const double off : {1e-9, 0.0}) {
    const Plane through_corner{normalize(Vec3{1, 1, 0}), -(1 + off) / std::sqrt(2.0)};
    split_polygon(unit_square(), through_corner, eps, within, neg, pos);
    ASSERT_EQ(neg.vertices.size(), 3u);
    int flagged = 0;
    for (const std::uint8_t f : neg.edge_in_tree) flagged += f;
    EXPECT_EQ(flagged, off == 0 ? 1 : 0) << off;
  }
}

}  // namespace
}  // namespace shadowkit::svbsp
