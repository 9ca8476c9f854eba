#pragma once
// Control meshes for the subdivision tests: each exercises a kind of vertex or face.
#include <cmath>
#include <numbers>

#include "shadowkit/scene/mesh.h"

namespace shadowkit::test {

/// Closed cube [-0.5, 0.5]^3, faces outward: eight valence-3 vertices, four on every face.
inline PolygonSoup cube_control() {
  PolygonSoup s;
  for (int k = 0; k < 8; ++k)
    s.positions.push_back({k & 1 ? 0.5 : -0.5, k & 2 ? 0.5 : -0.5, k & 4 ? 0.5 : -0.5});
  s.add_face({0, 2, 3, 1});
  s.add_face({4, 5, 7, 6});
  s.add_face({0, 1, 5, 4});
  s.add_face({2, 6, 7, 3});
  s.add_face({0, 4, 6, 2});
  s.add_face({1, 3, 7, 5});
  return s;
}

/// Open fan of \p valence warped quads around one interior vertex of that valence, facing +z:
/// boundary vertices on two faces and sharp corners on one.
inline PolygonSoup fan_control(int valence) {
  PolygonSoup s;
  s.positions.push_back({0, 0, 0.3});
  for (int k = 0; k < valence; ++k) {
    const double a = 2 * std::numbers::pi * k / valence, b = a + std::numbers::pi / valence;
    s.positions.push_back({std::cos(a), std::sin(a), 0.1 * k});
    s.positions.push_back({1.6 * std::cos(b), 1.6 * std::sin(b), 0.2 * (k % 2)});
  }
  const auto n = std::uint32_t(valence);
  for (std::uint32_t k = 0; k < n; ++k)
    s.add_face({0, 1 + 2 * k, 2 + 2 * k, 1 + 2 * ((k + 1) % n)});
  return s;
}

/// Closed square pyramid, faces outward: four triangles and a quad.
inline PolygonSoup pyramid_control() {
  PolygonSoup s;
  s.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, {0, 1.5, 0}};
  s.add_face({0, 1, 2, 3});
  for (std::uint32_t k = 0; k < 4; ++k) s.add_face({k, 4, (k + 1) % 4});
  return s;
}

/// Closed genus-1 quad grid, \p around x \p tube quads, faces outward; every vertex valence 4.
inline PolygonSoup torus_control(int around = 6, int tube = 4) {
  PolygonSoup s;
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < tube; ++j) {
      const double a = 2 * std::numbers::pi * i / around, b = 2 * std::numbers::pi * j / tube;
      const double r = 2 + 0.8 * std::cos(b);
      s.positions.push_back({r * std::cos(a), 0.8 * std::sin(b), r * std::sin(a)});
    }
  }
  auto id = [&](int i, int j) { return std::uint32_t((i % around) * tube + j % tube); };
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < tube; ++j)
      s.add_face({id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)});
  }
  return s;
}

/// Open \p n x \p n quad grid in the plane z = 0, interior vertices jittered within the plane.
inline PolygonSoup planar_grid_control(int n) {
  PolygonSoup s;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const bool inner = i > 0 && j > 0 && i < n && j < n;
      s.positions.push_back({i + (inner ? 0.3 * std::sin(7.0 * j + i) : 0.0),
                             j + (inner ? 0.3 * std::cos(5.0 * i + j) : 0.0), 0});
    }
  }
  auto id = [&](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i)
      s.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  }
  return s;
}

/// \p soup with every position multiplied by \p scale.
inline PolygonSoup scaled(PolygonSoup soup, double scale) {
  for (Vec3& p : soup.positions) p = p * scale;
  return soup;
}

}  // namespace shadowkit::test
