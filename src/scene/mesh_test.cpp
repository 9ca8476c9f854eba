#include "shadowkit/scene/mesh.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "testing/test_scenes.h"

namespace shadowkit {
namespace {

using testing::box;
using testing::polygon;

struct Warnings {
  std::vector<std::string> messages;
  Context ctx() {
    Context c;
    c.warn = [this](const std::string& m) { messages.push_back(m); };
    return c;
  }
};

// Every triangle gets its own three positions, as in an STL file.
PolygonSoup unwelded(const PolygonSoup& soup) {
  PolygonSoup out;
  for (std::size_t f = 0; f < soup.face_count(); ++f) {
    std::vector<std::uint32_t> face;
    for (std::uint32_t k = soup.face_start[f]; k < soup.face_start[f + 1]; ++k) {
      face.push_back(std::uint32_t(out.positions.size()));
      out.positions.push_back(soup.positions[soup.indices[k]]);
    }
    out.add_face(face);
  }
  return out;
}

TEST(Mesh, BoxIsClosedManifoldAndConsistentlyOriented) {
  const Mesh m = Mesh::build(box({0, 0, 0}, {1, 2, 3}), "box", {});
  EXPECT_EQ(m.face_count(), 6u);
  EXPECT_EQ(m.edges.size(), 12u);
  EXPECT_TRUE(m.closed());
  EXPECT_TRUE(m.manifold());
  EXPECT_TRUE(m.consistently_oriented());
  EXPECT_EQ(m.boundary_edge_count(), 0u);
  for (const MeshEdge& e : m.edges) EXPECT_EQ(e.use_count, 2u);
  // Outward normals: the centre is behind every face.
  for (const Plane& p : m.planes) EXPECT_LT(p.distance({0.5, 1, 1.5}), 0);
  EXPECT_DOUBLE_EQ(m.areas[0], 6.0);  // the -x face is 2 x 3
}

TEST(Mesh, WeldsDuplicatedPositions) {
  const Mesh m = Mesh::build(unwelded(box({0, 0, 0}, {1, 1, 1})), "soup", {});
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_TRUE(m.closed());
  EXPECT_TRUE(m.consistently_oriented());
}

TEST(Mesh, TinyAndHugeCoordinatesWeldAlike) {
  for (double scale : {1e-7, 1e7}) {
    PolygonSoup soup = unwelded(box({-scale, -scale, -scale}, {scale, 2 * scale, scale}));
    for (Vec3& p : soup.positions) p = p + Vec3{3 * scale, 0, 0};
    const Mesh m = Mesh::build(soup, "scaled", {});
    EXPECT_EQ(m.vertices.size(), 8u) << scale;
    EXPECT_TRUE(m.closed()) << scale;
    EXPECT_NEAR(m.areas[2], 4 * scale * scale, 1e-9 * scale * scale) << scale;
  }
}

TEST(Mesh, WeldingIsExactFarFromTheOriginAndForASinglePoint) {
  PolygonSoup far = unwelded(box({500, 0, 0}, {500.1, 0.1, 0.1}));
  EXPECT_EQ(Mesh::build(far, "far", {}).vertices.size(), 8u);
  PolygonSoup point;
  point.positions = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  point.add_face({0, 1, 2});
  Warnings w;
  EXPECT_EQ(Mesh::build(point, "point", w.ctx()).face_count(), 0u);
  EXPECT_EQ(w.messages.size(), 1u);
}

TEST(Mesh, OpenQuadHasFourBoundaryEdges) {
  const Mesh m = Mesh::build(polygon({{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}), "q", {});
  EXPECT_EQ(m.boundary_edge_count(), 4u);
  EXPECT_FALSE(m.closed());
  EXPECT_TRUE(m.manifold());
  EXPECT_NEAR(std::abs(m.planes[0].normal.y), 1.0, 1e-15);
}

TEST(Mesh, ThreeFacesOnOneEdgeAreNonManifold) {
  PolygonSoup s;
  s.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}};
  s.add_face({0, 1, 2});
  s.add_face({1, 0, 3});
  s.add_face({0, 1, 4});
  const Mesh m = Mesh::build(s, "fin", {});
  EXPECT_EQ(m.nonmanifold_edge_count(), 1u);
  EXPECT_FALSE(m.manifold());
  EXPECT_FALSE(m.closed());
  EXPECT_EQ(m.boundary_edge_count(), 6u);
  const MeshEdge& shared = m.edges[m.corner_edge[0]];
  EXPECT_EQ(shared.use_count, 3u);
}

TEST(Mesh, ReversedFaceBreaksConsistentOrientation) {
  PolygonSoup s = box({0, 0, 0}, {1, 1, 1});
  std::reverse(s.indices.begin(), s.indices.begin() + 4);
  const Mesh m = Mesh::build(s, "flipped", {});
  EXPECT_TRUE(m.closed());
  EXPECT_FALSE(m.consistently_oriented());
}

TEST(Mesh, DegenerateFacesAreDroppedWithAWarning) {
  PolygonSoup s = polygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  s.positions.push_back({2, 0, 0});
  s.add_face({0, 1, 3});  // collinear: zero area
  s.add_face({0, 0, 1});  // two distinct vertices
  s.add_face({0, 1});     // too few
  Warnings w;
  const Mesh m = Mesh::build(s, "bad.obj", w.ctx());
  EXPECT_EQ(m.face_count(), 1u);
  ASSERT_EQ(w.messages.size(), 1u);
  EXPECT_THAT(w.messages[0], ::testing::HasSubstr("bad.obj: dropped 3 degenerate face(s)"));
}

TEST(Mesh, NonPlanarQuadIsSplitIntoTriangles) {
  Warnings w;
  const Mesh m =
      Mesh::build(polygon({{0, 0, 0}, {1, 0, 0}, {1, 0.3, 1}, {0, 0, 1}}), "warp", w.ctx());
  EXPECT_EQ(m.face_count(), 2u);
  EXPECT_EQ(m.face_size(0), 3u);
  EXPECT_EQ(m.split_face_count(), 1u);
  EXPECT_TRUE(w.messages.empty());
}

TEST(Mesh, CoplanarNeighboursKeepTheirOwnFaces) {
  PolygonSoup s;
  s.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 1}, {1, 0, 1}, {2, 0, 1}};
  s.add_face({0, 3, 4, 1});
  s.add_face({1, 4, 5, 2});
  const Mesh m = Mesh::build(s, "strip", {});
  EXPECT_EQ(m.face_count(), 2u);
  EXPECT_EQ(m.edges.size(), 7u);
  EXPECT_EQ(m.boundary_edge_count(), 6u);
  EXPECT_TRUE(m.consistently_oriented());
}

TEST(Mesh, NonConvexPolygonKeepsItsShape) {
  // An L-shaped hexagon: area 3.
  const Mesh m = Mesh::build(
      polygon({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}}), "L", {});
  ASSERT_EQ(m.face_count(), 1u);
  EXPECT_EQ(m.face_size(0), 6u);
  EXPECT_DOUBLE_EQ(m.areas[0], 3.0);
  EXPECT_EQ(m.convex, std::vector<char>{0});
}

TEST(Mesh, ConvexFacesAreMarkedWhicheverWayTheyTurn) {
  EXPECT_EQ(Mesh::build(box({0, 0, 0}, {1, 2, 3}), "box", {}).convex, std::vector<char>(6, 1));
  // A pentagon with a straight corner, and the same walked the other way.
  const PolygonSoup pentagon = polygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}});
  EXPECT_EQ(Mesh::build(pentagon, "pentagon", {}).convex, std::vector<char>{1});
  const PolygonSoup reversed = polygon({{0, 1, 0}, {2, 1, 0}, {2, 0, 0}, {1, 0, 0}, {0, 0, 0}});
  EXPECT_EQ(Mesh::build(reversed, "reversed", {}).convex, std::vector<char>{1});
}

TEST(Mesh, FacesMapBackToTheSoupFacesTheyCameFrom) {
  PolygonSoup soup;
  soup.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 1, 1}, {2, 0, 0}};
  soup.add_face({0, 1});        // 0: two vertices, dropped
  soup.add_face({0, 1, 2, 3});  // 1: planar, kept whole
  soup.add_face({0, 1, 2, 1});  // 2: no area, dropped
  soup.add_face({0, 1, 4, 3});  // 3: not planar, kept as two triangles
  soup.add_face({1, 5, 2});     // 4: a triangle
  soup.add_face({0, 0, 0});     // 5: one distinct vertex, dropped
  const Mesh m = Mesh::build(soup, "mapped", {});
  EXPECT_EQ(m.input_face_count(), 6u);
  EXPECT_EQ(m.input_faces, (std::vector<std::uint32_t>{1, 3, 3, 4}));
}

}  // namespace
}  // namespace shadowkit
