#include "shadowkit/scene/triangulate.h"

#include <cmath>

namespace shadowkit {
namespace {

// Projects onto the coordinate plane that drops the normal's dominant axis, keeping the
// polygon's orientation counter-clockwise in 2D.
struct Projector {
  int u = 0, v = 1;
  explicit Projector(Vec3 n) {
    const Vec3 a{std::abs(n.x), std::abs(n.y), std::abs(n.z)};
    const int drop = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    u = (drop + 1) % 3;
    v = (drop + 2) % 3;
    if (n[drop] < 0) std::swap(u, v);
  }
  double cross2(Vec3 a, Vec3 b, Vec3 c) const {
    return (b[u] - a[u]) * (c[v] - a[v]) - (b[v] - a[v]) * (c[u] - a[u]);
  }
};

bool is_convex(std::span<const Vec3> p, std::span<const std::uint32_t> loop, const Projector& pr) {
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (pr.cross2(p[loop[i]], p[loop[(i + 1) % n]], p[loop[(i + 2) % n]]) < 0) return false;
  }
  return true;
}

bool inside_triangle(const Projector& pr, Vec3 a, Vec3 b, Vec3 c, Vec3 q) {
  return pr.cross2(a, b, q) >= 0 && pr.cross2(b, c, q) >= 0 && pr.cross2(c, a, q) >= 0;
}

// Ear clipping, O(n^2): polygons from files are small. A reflex-free ear that contains no
// other vertex is cut; if none is found (a self-touching polygon), the flattest vertex is cut
// so that the loop always terminates.
void clip_ears(std::span<const Vec3> p, std::vector<std::uint32_t> ring, const Projector& pr,
               std::vector<std::array<std::uint32_t, 3>>& out) {
  while (ring.size() > 3) {
    const std::size_t n = ring.size();
    std::size_t cut = n;
    double best_flat = -INFINITY;
    std::size_t flattest = 0;
    for (std::size_t i = 0; i < n && cut == n; ++i) {
      const std::uint32_t a = ring[(i + n - 1) % n], b = ring[i], c = ring[(i + 1) % n];
      const double turn = pr.cross2(p[a], p[b], p[c]);
      if (turn > best_flat) best_flat = turn, flattest = i;
      if (turn <= 0) continue;
      bool empty = true;
      for (std::size_t k = 0; k < n && empty; ++k) {
        const std::uint32_t q = ring[k];
        if (q == a || q == b || q == c) continue;
        empty = !inside_triangle(pr, p[a], p[b], p[c], p[q]);
      }
      if (empty) cut = i;
    }
    if (cut == n) cut = flattest;
    out.push_back({ring[(cut + n - 1) % n], ring[cut], ring[(cut + 1) % n]});
    ring.erase(ring.begin() + std::ptrdiff_t(cut));
  }
  out.push_back({ring[0], ring[1], ring[2]});
}

}  // namespace

Vec3 newell_normal(std::span<const Vec3> p, std::span<const std::uint32_t> loop) {
  Vec3 n;
  const std::size_t count = loop.size();
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3 a = p[loop[i]], b = p[loop[(i + 1) % count]];
    n += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
  }
  return n;
}

void triangulate_polygon(std::span<const Vec3> positions, std::span<const std::uint32_t> loop,
                         Vec3 normal, std::vector<std::array<std::uint32_t, 3>>& out) {
  const Projector pr(normal);
  if (loop.size() == 3 || is_convex(positions, loop, pr)) {
    for (std::size_t i = 1; i + 1 < loop.size(); ++i)
      out.push_back({loop[0], loop[i], loop[i + 1]});
    return;
  }
  clip_ears(positions, {loop.begin(), loop.end()}, pr, out);
}

}  // namespace shadowkit
