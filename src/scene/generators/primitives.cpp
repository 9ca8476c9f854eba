#include "primitives.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "shadowkit/core/error.h"

namespace shadowkit::generators {
namespace {

/// Box corner k has x from bit 0, y from bit 1, z from bit 2 (0: low side, 1: high side).
/// Each face lists its corners counter-clockwise seen from outside.
constexpr std::uint32_t kBoxFaces[6][4] = {
    {0, 4, 6, 2},  // -x
    {1, 3, 7, 5},  // +x
    {0, 1, 5, 4},  // -y
    {2, 6, 7, 3},  // +y
    {0, 2, 3, 1},  // -z
    {4, 5, 7, 6},  // +z
};

std::uint32_t next_index(const PolygonSoup& soup) {
  return static_cast<std::uint32_t>(soup.positions.size());
}

/// Appends 8 corners (box corner numbering) and the 6 faces; \p corners must be a
/// right-handed image of the unit cube so that the face table stays counter-clockwise.
void add_box_corners(PolygonSoup& soup, const std::array<Vec3, 8>& corners, Facing facing) {
  const std::uint32_t base = next_index(soup);
  soup.positions.insert(soup.positions.end(), corners.begin(), corners.end());
  for (const auto& face : kBoxFaces) {
    if (facing == Facing::outward) {
      soup.add_face({base + face[0], base + face[1], base + face[2], base + face[3]});
    } else {
      soup.add_face({base + face[3], base + face[2], base + face[1], base + face[0]});
    }
  }
}

/// Newell normal of a polygon (not normalized); robust for any planar polygon.
Vec3 newell_normal(const PolygonSoup& soup, const std::vector<std::uint32_t>& face) {
  Vec3 n;
  for (std::size_t i = 0; i < face.size(); ++i) {
    const Vec3 a = soup.positions[face[i]];
    const Vec3 b = soup.positions[face[(i + 1) % face.size()]];
    n += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  return n;
}

/// Adds \p face, reversed if needed so that its normal points away from \p interior.
void add_face_away_from(PolygonSoup& soup, std::vector<std::uint32_t> face, Vec3 interior) {
  const Vec3 n = newell_normal(soup, face);
  if (dot(n, soup.positions[face[0]] - interior) < 0) std::reverse(face.begin(), face.end());
  soup.add_face(face);
}

}  // namespace

Mat3 rotation_from_quaternion(double w, double x, double y, double z) {
  const double norm = std::sqrt(w * w + x * x + y * y + z * z);
  SHADOWKIT_CHECK(norm > 0);
  w /= norm, x /= norm, y /= norm, z /= norm;
  Mat3 m;
  m.rows[0] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)};
  m.rows[1] = {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)};
  m.rows[2] = {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
  return m;
}

Mat3 quarter_turns_about_y(int quarter_turns) {
  // Rotation by θ about +y maps (x, z) to (x cos θ + z sin θ, -x sin θ + z cos θ).
  constexpr int kCos[4] = {1, 0, -1, 0};
  constexpr int kSin[4] = {0, 1, 0, -1};
  const int k = ((quarter_turns % 4) + 4) % 4;
  Mat3 m;
  m.rows[0] = {double(kCos[k]), 0, double(kSin[k])};
  m.rows[2] = {double(-kSin[k]), 0, double(kCos[k])};
  return m;
}

void add_box(PolygonSoup& soup, Vec3 lo, Vec3 hi, Facing facing) {
  std::array<Vec3, 8> corners;
  for (int k = 0; k < 8; ++k) {
    corners[k] = {(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z};
  }
  add_box_corners(soup, corners, facing);
}

void add_oriented_box(PolygonSoup& soup, Vec3 center, Vec3 half, const Mat3& rotation) {
  std::array<Vec3, 8> corners;
  for (int k = 0; k < 8; ++k) {
    const Vec3 local{(k & 1) ? half.x : -half.x, (k & 2) ? half.y : -half.y,
                     (k & 4) ? half.z : -half.z};
    corners[k] = center + rotation * local;
  }
  add_box_corners(soup, corners, Facing::outward);
}

void add_horizontal_quad(PolygonSoup& soup, Vec3 center, double size_x, double size_z) {
  const double hx = size_x / 2, hz = size_z / 2;
  const std::uint32_t base = next_index(soup);
  // Counter-clockwise seen from above: -x-z, -x+z, +x+z, +x-z gives normal +y.
  soup.positions.push_back(center + Vec3{-hx, 0, -hz});
  soup.positions.push_back(center + Vec3{-hx, 0, hz});
  soup.positions.push_back(center + Vec3{hx, 0, hz});
  soup.positions.push_back(center + Vec3{hx, 0, -hz});
  soup.add_face({base, base + 1, base + 2, base + 3});
}

void add_horizontal_triangle_pair(PolygonSoup& soup, Vec3 center, double size) {
  const std::uint32_t base = next_index(soup);
  add_horizontal_quad(soup, center, size, size);
  // Replace the quad just added by two triangles over the same four vertices.
  soup.face_start.pop_back();
  soup.indices.resize(soup.face_start.back());
  soup.add_face({base, base + 1, base + 2});
  soup.add_face({base, base + 2, base + 3});
}

void add_tetrahedron(PolygonSoup& soup, const std::array<Vec3, 4>& corners) {
  const std::uint32_t base = next_index(soup);
  soup.positions.insert(soup.positions.end(), corners.begin(), corners.end());
  const Vec3 centroid = (corners[0] + corners[1] + corners[2] + corners[3]) / 4;
  // Face k leaves out corner k.
  for (std::uint32_t k = 0; k < 4; ++k) {
    std::vector<std::uint32_t> face;
    for (std::uint32_t j = 0; j < 4; ++j) {
      if (j != k) face.push_back(base + j);
    }
    add_face_away_from(soup, face, centroid);
  }
}

void add_prism(PolygonSoup& soup, const std::array<Vec3, 3>& base, Vec3 extrusion) {
  const std::uint32_t b = next_index(soup);
  for (const Vec3& p : base) soup.positions.push_back(p);
  for (const Vec3& p : base) soup.positions.push_back(p + extrusion);
  const Vec3 centroid = (base[0] + base[1] + base[2]) / 3 + extrusion / 2;
  add_face_away_from(soup, {b, b + 1, b + 2}, centroid);
  add_face_away_from(soup, {b + 3, b + 4, b + 5}, centroid);
  for (std::uint32_t i = 0; i < 3; ++i) {
    const std::uint32_t j = (i + 1) % 3;
    add_face_away_from(soup, {b + i, b + j, b + 3 + j, b + 3 + i}, centroid);
  }
}

void add_uv_sphere(PolygonSoup& soup, Vec3 center, double radius, int segments, int rings) {
  SHADOWKIT_CHECK(segments >= 3 && rings >= 2);
  const std::uint32_t south = next_index(soup);
  soup.positions.push_back(center - Vec3{0, radius, 0});
  // Ring r (1 .. rings-1) at polar angle π r / rings from the south pole.
  for (int r = 1; r < rings; ++r) {
    const double polar = std::numbers::pi * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double azimuth = 2 * std::numbers::pi * s / segments;
      soup.positions.push_back(center + radius * Vec3{std::sin(polar) * std::cos(azimuth),
                                                      -std::cos(polar),
                                                      -std::sin(polar) * std::sin(azimuth)});
    }
  }
  const std::uint32_t north = next_index(soup);
  soup.positions.push_back(center + Vec3{0, radius, 0});
  const auto ring_vertex = [&](int r, int s) {
    return south + 1 + std::uint32_t((r - 1) * segments + (s % segments));
  };
  // Azimuth runs counter-clockwise seen from above (+x toward -z), so seen from outside a
  // quad (r, s), (r, s+1), (r+1, s+1), (r+1, s) is counter-clockwise.
  for (int s = 0; s < segments; ++s) {
    soup.add_face({south, ring_vertex(1, s + 1), ring_vertex(1, s)});
    for (int r = 1; r + 1 < rings; ++r) {
      soup.add_face({ring_vertex(r, s), ring_vertex(r, s + 1), ring_vertex(r + 1, s + 1),
                     ring_vertex(r + 1, s)});
    }
    soup.add_face({north, ring_vertex(rings - 1, s), ring_vertex(rings - 1, s + 1)});
  }
}

std::array<Vec3, 4> regular_tetrahedron(Vec3 base_center, double edge) {
  // Circumradius of the base triangle e/√3 and height e·√(2/3); the corners at 120° steps
  // use cos 120° = -1/2 and sin 120° = √3/2, exact up to one rounding.
  const double r = edge / std::sqrt(3.0);
  const double h = edge * std::sqrt(2.0 / 3.0);
  const double s = r * std::sqrt(3.0) / 2;
  return {base_center + Vec3{0, 0, -r}, base_center + Vec3{s, 0, r / 2},
          base_center + Vec3{-s, 0, r / 2}, base_center + Vec3{0, h, 0}};
}

void transform_positions(PolygonSoup& soup, std::size_t first, Vec3 scale, const Mat3& rotation,
                         Vec3 translate) {
  SHADOWKIT_CHECK(scale.x > 0 && scale.y > 0 && scale.z > 0);
  for (std::size_t i = first; i < soup.positions.size(); ++i) {
    const Vec3 p = soup.positions[i];
    soup.positions[i] = translate + rotation * Vec3{p.x * scale.x, p.y * scale.y, p.z * scale.z};
  }
}

}  // namespace shadowkit::generators
