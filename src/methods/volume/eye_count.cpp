#include "eye_count.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>

#include "contour_edges.h"
#include "segment_distance.h"

namespace shadowkit::volume {
namespace {

enum class Inside { no, yes, unsure };

// Point \p x of face f's plane against the face: even-odd rule in the plane's dominant
// projection, unsure within \p tolerance of an edge.
Inside inside_face(const Mesh& mesh, std::size_t f, Vec3 x, double tolerance) {
  const Vec3 n = mesh.planes[f].normal;
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  const int drop = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
  const int i = drop == 0 ? 1 : 0, j = drop == 2 ? 1 : 2;
  bool inside = false;
  const std::uint32_t size = mesh.face_size(f);
  for (std::uint32_t k = 0; k < size; ++k) {
    const Vec3 a = mesh.vertices[mesh.face_vertex(f, k)];
    const Vec3 b = mesh.vertices[mesh.face_vertex(f, (k + 1) % size)];
    if (segment_distance(x, a, b) <= tolerance) return Inside::unsure;
    if ((a[j] > x[j]) != (b[j] > x[j]) &&
        x[i] < a[i] + (b[i] - a[i]) * (x[j] - a[j]) / (b[j] - a[j])) {
      inside = !inside;
    }
  }
  return inside ? Inside::yes : Inside::no;
}

}  // namespace

std::optional<int> faces_between_eye_and_light(const Mesh& mesh,
                                               std::span<const std::uint32_t> faces,
                                               const Bounds3& box, Vec3 eye, const Light& light) {
  // Hazard: a relative tolerance; closer calls are left to depth-fail counting.
  const double tolerance = 1e-9 * std::max(box.diagonal(), length(eye - box.center()));
  // The faces [first, last) that the way to the light crosses, or none if one is too close
  // to tell.
  const auto count_in = [&](std::size_t first, std::size_t last) -> std::optional<int> {
    int count = 0;
    for (std::size_t i = first; i < last; ++i) {
      const std::uint32_t f = faces[i];
      const Plane& plane = mesh.planes[f];
      const double l = light_side(plane, light);
      if (l == 0) continue;  // casts no volume
      const double e = plane.distance(eye);
      if (std::abs(e) <= tolerance) return std::nullopt;
      if ((e > 0) == (l > 0)) continue;
      // Where the way to the light crosses the plane.
      const Vec3 x = light.type == Light::Type::point ? eye + (light.position - eye) * (e / (e - l))
                                                      : eye - light.direction * (-e / l);
      const Inside in = inside_face(mesh, f, x, tolerance);
      if (in == Inside::unsure) return std::nullopt;
      count += in == Inside::yes;
    }
    return count;
  };
  const auto sum = [](std::optional<int> a, std::optional<int> b) -> std::optional<int> {
    if (!a || !b) return std::nullopt;
    return *a + *b;
  };
  // A large part (a scanned or finely tessellated surface is one) in parallel, isolated:
  // while it waits, this thread must not take up another part, whose build would reuse the
  // caller's thread_local buffers.
  constexpr std::size_t kGrain = 16384;
  if (faces.size() <= kGrain) return count_in(0, faces.size());
  return tbb::this_task_arena::isolate([&] {
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, faces.size(), kGrain), std::optional<int>(0),
        [&](const tbb::blocked_range<std::size_t>& r, std::optional<int> acc) {
          return acc ? sum(acc, count_in(r.begin(), r.end())) : acc;
        },
        sum);
  });
}

}  // namespace shadowkit::volume
