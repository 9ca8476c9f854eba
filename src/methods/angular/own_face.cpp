#include "own_face.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowkit::angular {
namespace {

// The distance from \p p to the segment [a, b].
double segment_distance(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 d = b - a;
  const double dd = dot(d, d);
  const double t = dd > 0 ? std::clamp(dot(p - a, d) / dd, 0.0, 1.0) : 0.0;
  return length(p - (a + d * t));
}

}  // namespace

double OwnFace::outside(Vec3 local) const {
  const std::uint32_t n = mesh->face_size(face);
  const Vec3 normal = frame->local_direction(mesh->planes[face].normal);
  // Crossings of a ray in the plane that drops the normal's largest axis: odd inside.
  const Vec3 m{std::abs(normal.x), std::abs(normal.y), std::abs(normal.z)};
  const int drop = m.x >= m.y && m.x >= m.z ? 0 : (m.y >= m.z ? 1 : 2);
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  bool inside = false;
  double nearest = std::numeric_limits<double>::infinity();
  Vec3 a = frame->local(mesh->vertices[mesh->face_vertex(face, n - 1)]);
  for (std::uint32_t k = 0; k < n; ++k) {
    const Vec3 b = frame->local(mesh->vertices[mesh->face_vertex(face, k)]);
    if ((a[v] > local[v]) != (b[v] > local[v]) &&
        local[u] < a[u] + (b[u] - a[u]) * (local[v] - a[v]) / (b[v] - a[v])) {
      inside = !inside;
    }
    nearest = std::min(nearest, segment_distance(local, a, b));
    a = b;
  }
  return inside ? 0 : nearest;
}

}  // namespace shadowkit::angular
