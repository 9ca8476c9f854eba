#pragma once
/// \brief Polygon meshes: raw polygon soups as read from files, and welded meshes with
/// planes and edge adjacency.
#include <cstdint>
#include <string>
#include <vector>

#include "shadowkit/core/context.h"
#include "shadowkit/core/vec.h"

namespace shadowkit {

/// A face stays whole while every corner lies within this of its own diameter from its plane;
/// a face less planar is split into triangles. So a face's corners may lie off its plane by
/// this much, far more than the methods' plane tolerances.
inline constexpr double kPlanarTolerance = 1e-5;

/// \brief Polygons as a file gives them: positions and, per face, a list of vertex indices
/// (compressed rows: face f uses indices[face_start[f] .. face_start[f+1])).
struct PolygonSoup {
  std::vector<Vec3> positions;
  std::vector<std::uint32_t> face_start{0};
  std::vector<std::uint32_t> indices;

  std::size_t face_count() const { return face_start.size() - 1; }
  /// Appends one polygon whose vertex indices are given.
  void add_face(std::initializer_list<std::uint32_t> face);
  void add_face(const std::vector<std::uint32_t>& face);
  /// Appends another soup's faces after this one's.
  void append(const PolygonSoup& other);
};

/// The soup with positions merged as Mesh::build merges them (within 1e-9 of the bounding-box
/// diagonal), unused positions dropped and repeated consecutive vertices removed from every
/// face. Faces keep their order and count, even those left with fewer than three vertices.
PolygonSoup welded_soup(const PolygonSoup& soup);

/// \brief An undirected mesh edge and the faces around it.
struct MeshEdge {
  std::uint32_t v0 = 0, v1 = 0;  ///< v0 < v1
  std::uint32_t first_use = 0;   ///< into Mesh::edge_uses
  std::uint32_t use_count = 0;   ///< 1: boundary, 2: manifold, >2: non-manifold
};

/// \brief One face's use of an edge; `forward` when the face walks the edge from v0 to v1.
struct EdgeUse {
  std::uint32_t face = 0;
  bool forward = false;
};

/// \brief A welded, cleaned polygon mesh with planar faces and edge adjacency.
///
/// Faces are planar convex or non-convex simple polygons; a face whose vertices are not
/// coplanar (within a relative tolerance) is split into triangles when the mesh is built.
class Mesh {
 public:
  /// Welds coincident vertices, drops degenerate faces (warning through \p ctx), splits
  /// non-planar faces into triangles (counted, not warned: the surface is unchanged),
  /// computes planes and adjacency. \p name labels warnings.
  static Mesh build(const PolygonSoup& soup, const std::string& name, const Context& ctx);

  std::vector<Vec3> vertices;
  std::vector<std::uint32_t> face_start{0};  ///< compressed rows, as in PolygonSoup
  std::vector<std::uint32_t> face_vertices;
  std::vector<Plane> planes;  ///< per face; normal follows the vertex order
  std::vector<double> areas;  ///< per face
  /// Per face: 1 when it turns the same way about its normal at every corner, so that a
  /// plane cuts it in one segment at most.
  std::vector<char> convex;
  /// Per face: the index of the soup face it was built from. Faces keep the soup's order; a
  /// non-planar soup face gives several (its triangles), a degenerate one none. What the
  /// sun-study contract's polygons (the faces as read from the file) map back through.
  std::vector<std::uint32_t> input_faces;

  std::vector<MeshEdge> edges;
  std::vector<EdgeUse> edge_uses;
  /// Per face corner (same layout as face_vertices): the edge from that corner to the next.
  std::vector<std::uint32_t> corner_edge;

  std::size_t face_count() const { return planes.size(); }
  std::uint32_t face_size(std::size_t f) const { return face_start[f + 1] - face_start[f]; }
  std::uint32_t face_vertex(std::size_t f, std::uint32_t k) const {
    return face_vertices[face_start[f] + k];
  }
  Bounds3 bounds() const;

  std::size_t boundary_edge_count() const { return boundary_edges_; }
  std::size_t nonmanifold_edge_count() const { return nonmanifold_edges_; }
  /// Every edge is used by exactly two faces.
  bool closed() const { return boundary_edges_ == 0 && nonmanifold_edges_ == 0; }
  /// No edge is used by more than two faces.
  bool manifold() const { return nonmanifold_edges_ == 0; }
  /// Every two-face edge is walked in opposite directions by its faces.
  bool consistently_oriented() const { return consistently_oriented_; }
  /// Input polygons that were not planar and are kept as triangles instead.
  std::size_t split_face_count() const { return split_faces_; }
  /// Input polygons dropped as degenerate (fewer than 3 distinct vertices, or no area).
  std::size_t dropped_face_count() const { return dropped_faces_; }
  /// The soup's face count, dropped faces included.
  std::size_t input_face_count() const { return input_face_count_; }

 private:
  void build_adjacency();
  std::size_t boundary_edges_ = 0;
  std::size_t nonmanifold_edges_ = 0;
  std::size_t split_faces_ = 0;
  std::size_t dropped_faces_ = 0;
  std::size_t input_face_count_ = 0;
  bool consistently_oriented_ = true;
};

}  // namespace shadowkit
