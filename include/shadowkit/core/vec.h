#pragma once
/// \brief Small fixed-size vector types used throughout shadowkit.
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace shadowkit {

/// \brief A 3-vector of doubles: positions, directions and normals in world space.
struct Vec3 {
  double x = 0, y = 0, z = 0;

  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  friend constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend constexpr Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
  friend constexpr Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
  friend constexpr Vec3 operator*(double s, Vec3 a) { return a * s; }
  friend constexpr Vec3 operator/(Vec3 a, double s) { return {a.x / s, a.y / s, a.z / s}; }
  constexpr Vec3& operator+=(Vec3 b) { return *this = *this + b; }
  constexpr Vec3& operator-=(Vec3 b) { return *this = *this - b; }
  friend constexpr bool operator==(Vec3 a, Vec3 b) = default;
};

constexpr double dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(Vec3 a) {
  return std::sqrt(dot(a, a));
}
inline Vec3 normalize(Vec3 a) {
  return a / length(a);
}
inline Vec3 min(Vec3 a, Vec3 b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
inline Vec3 max(Vec3 a, Vec3 b) {
  return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
inline double max_abs_component(Vec3 a) {
  return std::max({std::abs(a.x), std::abs(a.y), std::abs(a.z)});
}
inline bool is_finite(Vec3 a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

/// \brief Axis-aligned bounding box; empty until a point is added.
struct Bounds3 {
  Vec3 lo{INFINITY, INFINITY, INFINITY};
  Vec3 hi{-INFINITY, -INFINITY, -INFINITY};

  void add(Vec3 p) { lo = min(lo, p), hi = max(hi, p); }
  void add(const Bounds3& b) { lo = min(lo, b.lo), hi = max(hi, b.hi); }
  bool empty() const { return lo.x > hi.x; }
  Vec3 center() const { return (lo + hi) * 0.5; }
  Vec3 extent() const { return hi - lo; }
  double diagonal() const { return empty() ? 0.0 : length(hi - lo); }
  /// Corner \p c in 0..7: bit 0 picks hi.x over lo.x, bit 1 hi.y, bit 2 hi.z.
  Vec3 corner(int c) const {
    return {c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z};
  }
  /// Distance from \p p to the nearest point of the box (0 inside).
  double distance(Vec3 p) const { return length(p - max(lo, min(p, hi))); }
};

/// \brief The plane n·p + d = 0 with a unit normal n.
struct Plane {
  Vec3 normal;
  double d = 0;
  double distance(Vec3 p) const { return dot(normal, p) + d; }
};

/// Whether two planes are the same set of points: equal bit for bit, either way round.
inline bool same_plane(const Plane& a, const Plane& b) {
  return (a.normal == b.normal && a.d == b.d) || (a.normal == -b.normal && a.d == -b.d);
}

}  // namespace shadowkit
