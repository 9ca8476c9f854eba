#pragma once
// Convex polygons in world space and their splitting by a plane: the one clipping
// operation of the SVBSP algorithm (§2: "clips a polygon against a plane").
#include <absl/container/inlined_vector.h>

#include <cstdint>
#include <optional>
#include <span>

#include "shadowkit/core/vec.h"

namespace shadowkit::svbsp {

/// \brief A convex piece of a scene face. Its plane is always the original face's plane
/// (§7): it is never recomputed from the piece's vertices.
struct ConvexPolygon {
  /// Corners held inline up to a hexagon's, so that splitting a polygon in the trees'
  /// inner loops allocates nothing: a quadrilateral cut by two planes has six.
  static constexpr std::size_t kInlineCorners = 6;
  using Corners = absl::InlinedVector<Vec3, kInlineCorners>;
  Corners vertices;
  /// Per edge (vertices[i] -> vertices[i + 1]): the edge lies in a shadow plane that already
  /// bounds the SVBSP cell the polygon has reached, so its own shadow plane would add
  /// nothing (§6: fewer planes, a smaller tree).
  absl::InlinedVector<std::uint8_t, kInlineCorners> edge_in_tree;
  std::uint32_t face = 0;  ///< global id of the original face
};

/// A polygon with the given corners and no edge in the tree.
ConvexPolygon make_polygon(std::span<const Vec3> vertices, std::uint32_t face);
inline ConvexPolygon make_polygon(std::initializer_list<Vec3> vertices, std::uint32_t face) {
  return make_polygon(std::span<const Vec3>(vertices.begin(), vertices.size()), face);
}

/// The bytes \p p takes beyond sizeof(ConvexPolygon): its corners past the inline ones.
std::size_t heap_bytes(const ConvexPolygon& p);

/// The mean of \p p's corners: a point inside it.
Vec3 centroid(const ConvexPolygon& p);

/// Area of a convex (or any simple planar) polygon.
double area(const ConvexPolygon& p);

/// \brief Which sides of a plane a polygon reaches; vertices within the tolerance of the
/// plane belong to both.
struct PlaneSides {
  bool negative = false, positive = false;
  bool touching = false;  ///< some vertex within the tolerance of the plane
  bool on() const { return !negative && !positive; }
  bool spanning() const { return negative && positive; }
};

/// The share of a plane tolerance eps within which a point lies in the plane itself, to the
/// rounding of its distance. A point within eps but beyond that is only near the plane, and
/// a grazing light's shadow plane may meet a receiver at so small an angle that eps spans a
/// wide strip of it.
inline constexpr double kInPlaneShare = 1e-4;

/// Where \p p lies against \p plane with tolerance \p eps (one tolerance everywhere, §7).
/// Inline: the trees' inner loops call it at every node, and a call returning the three
/// flags through memory stalls them.
inline PlaneSides classify(const ConvexPolygon& p, const Plane& plane, double eps) {
  PlaneSides s;
  for (const Vec3& v : p.vertices) {
    const double d = plane.distance(v);
    s.negative = s.negative || d < -eps;
    s.positive = s.positive || d > eps;
    s.touching = s.touching || !(d > eps || d < -eps);
  }
  return s;
}

/// What split_polygon() makes of \p p when it lies on one side of \p plane (tolerance
/// \p eps), in place: edges with both ends within \p within of the plane are flagged
/// edge_in_tree (unless every vertex is within eps: a sliver in the plane bounds nothing).
/// Filtering a polygon that only touches a plane needs no copy (§6: its edges along the plane
/// add no plane of their own).
void mark_edges_in_plane(ConvexPolygon& p, const Plane& plane, double eps, double within);

/// splitPolygon of Fig. 4: the parts of \p p on the negative and the positive side of
/// \p plane. A polygon on one side (or wholly within eps of the plane: positive) is copied
/// to that side only; the other output is left empty. With \p mark_within, edges that end up
/// along the plane (the cut and edges with both ends on it) are flagged edge_in_tree when
/// both their ends lie within *mark_within of it. Cut points are computed from the edge's end
/// points in a canonical order, so the two polygons sharing an edge are cut at bit-identical
/// points (no cracks, §7).
void split_polygon(const ConvexPolygon& p, const Plane& plane, double eps,
                   std::optional<double> mark_within, ConvexPolygon& negative,
                   ConvexPolygon& positive);

}  // namespace shadowkit::svbsp
