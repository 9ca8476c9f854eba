#pragma once
/// \brief Building blocks of the generated scenes: solids and open polygons appended to a
/// PolygonSoup. Solids share their vertices by index and are closed manifolds; every polygon
/// is planar and counter-clockwise seen from the side its normal points to.
#include <array>
#include <cstdint>

#include "shadowkit/core/vec.h"
#include "shadowkit/scene/mesh.h"

namespace shadowkit::generators {

/// \brief A 3x3 matrix acting on column vectors (rows stored).
struct Mat3 {
  std::array<Vec3, 3> rows{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  Vec3 operator*(Vec3 v) const { return {dot(rows[0], v), dot(rows[1], v), dot(rows[2], v)}; }
};

/// Rotation of the quaternion w + xi + yj + zk (normalized here). Uses only arithmetic and
/// one square root, so the result is the same on every platform (unlike sin and cos).
Mat3 rotation_from_quaternion(double w, double x, double y, double z);
/// Rotation about +y by \p quarter_turns × 90° (exact).
Mat3 quarter_turns_about_y(int quarter_turns);

/// Which way a closed surface's normals point: out of the solid, or into a room.
enum class Facing { outward, inward };

/// Axis-aligned box [lo, hi]: 8 vertices, 6 quads.
void add_box(PolygonSoup& soup, Vec3 lo, Vec3 hi, Facing facing = Facing::outward);
/// Box with half extents \p half, rotated by \p rotation (a proper rotation) about its centre.
void add_oriented_box(PolygonSoup& soup, Vec3 center, Vec3 half, const Mat3& rotation);
/// Open horizontal rectangle centred at \p center, size_x × size_z, normal +y: one quad.
void add_horizontal_quad(PolygonSoup& soup, Vec3 center, double size_x, double size_z);
/// The same square as two triangles sharing a diagonal (Chin & Feiner's Tetra ground plane).
void add_horizontal_triangle_pair(PolygonSoup& soup, Vec3 center, double size);
/// Tetrahedron on four corners in any order: 4 triangles, oriented outward from the geometry.
void add_tetrahedron(PolygonSoup& soup, const std::array<Vec3, 4>& corners);
/// Triangular prism: triangle \p base swept along \p extrusion (2 triangles + 3 quads).
void add_prism(PolygonSoup& soup, const std::array<Vec3, 3>& base, Vec3 extrusion);
/// UV sphere: \p segments around y, \p rings from pole to pole; quads (planar isosceles
/// trapezoids) and triangle fans at the poles.
void add_uv_sphere(PolygonSoup& soup, Vec3 center, double radius, int segments, int rings);

/// Corners of a regular tetrahedron with edge \p edge, base horizontal with its centroid at
/// \p base_center and one base corner toward -z, apex up.
std::array<Vec3, 4> regular_tetrahedron(Vec3 base_center, double edge);

/// Maps positions [first, end) of \p soup by p' = translate + rotation · (scale ⊙ p).
/// \p scale must be positive so that orientations are kept.
void transform_positions(PolygonSoup& soup, std::size_t first, Vec3 scale, const Mat3& rotation,
                         Vec3 translate);

}  // namespace shadowkit::generators
