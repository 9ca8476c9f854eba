#pragma once
// An independent estimate of how much of a polygon a light reaches: stratified points on the
// polygon, each tested with an Embree shadow ray. The object-space results (svbsp's lit and
// shadowed areas, the sun study's sunlit fractions) are checked against it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "shadowkit/methods/raytrace.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::testing {

inline constexpr int kSampleGrid = 200;  // 200 x 200 strata over the polygon's bounding rectangle

// Crossing-number test in the polygon's 2D frame.
inline bool inside_polygon(const std::vector<std::pair<double, double>>& poly, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const auto [xi, yi] = poly[i];
    const auto [xj, yj] = poly[j];
    if ((yi > y) != (yj > y) && x < xi + (y - yi) * (xj - xi) / (yj - yi)) in = !in;
  }
  return in;
}

// Shadowed fraction of global face \p face for \p light from stratified samples, each
// lifted off the face toward the light by a tiny fraction of the scene's size.
inline double sampled_shadowed_fraction(const Scene& scene, const raytrace::ShadowRays& rays,
                                        std::uint32_t face, const Light& light) {
  const Mesh& mesh = scene.objects[scene.object_of_face(face)].mesh;
  const std::uint32_t f = scene.local_face(face);
  const Plane& plane = scene.face_plane(face);
  const Vec3 origin = mesh.vertices[mesh.face_vertex(f, 0)];
  const Vec3 u = normalize(mesh.vertices[mesh.face_vertex(f, 1)] - origin);
  const Vec3 v = cross(plane.normal, u);
  std::vector<std::pair<double, double>> poly;
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  for (std::uint32_t k = 0; k < mesh.face_size(f); ++k) {
    const Vec3 p = mesh.vertices[mesh.face_vertex(f, k)] - origin;
    poly.push_back({dot(p, u), dot(p, v)});
    x0 = std::min(x0, poly.back().first), x1 = std::max(x1, poly.back().first);
    y0 = std::min(y0, poly.back().second), y1 = std::max(y1, poly.back().second);
  }
  const Vec3 lift =
      plane.normal * std::copysign(1e-7 * scene.bounds().diagonal(), light_side(plane, light));
  std::mt19937 rng(face);
  std::uniform_real_distribution<double> jitter(0, 1);
  std::size_t in = 0, shadowed = 0;
  for (int i = 0; i < kSampleGrid; ++i) {
    for (int j = 0; j < kSampleGrid; ++j) {
      const double x = x0 + (x1 - x0) * (i + jitter(rng)) / kSampleGrid;
      const double y = y0 + (y1 - y0) * (j + jitter(rng)) / kSampleGrid;
      if (!inside_polygon(poly, x, y)) continue;
      ++in;
      shadowed += rays.occluded(origin + u * x + v * y + lift, light);
    }
  }
  return double(shadowed) / double(in);
}

}  // namespace shadowkit::testing
