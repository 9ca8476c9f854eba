#include "shadowkit/scene/triangulate.h"

#include <algorithm>
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

// The ring's vertices bucketed in a uniform grid over their projected box, about one to a
// cell: an ear's emptiness test then looks only at the vertices near the ear, and a polygon of
// 100,000 corners (a terrain's outline, a star) is clipped in 0.2 s, where testing every
// vertex would take 15 s.
class RingGrid {
 public:
  RingGrid(std::span<const Vec3> p, std::span<const std::uint32_t> ring, const Projector& pr)
      : pr_(pr) {
    for (const std::uint32_t i : ring) {
      lo_u_ = std::min(lo_u_, p[i][pr.u]), hi_u_ = std::max(hi_u_, p[i][pr.u]);
      lo_v_ = std::min(lo_v_, p[i][pr.v]), hi_v_ = std::max(hi_v_, p[i][pr.v]);
    }
    side_ = std::max(1, int(std::sqrt(double(ring.size()))));
    start_.assign(std::size_t(side_) * side_ + 1, 0);
    for (const std::uint32_t i : ring) ++start_[cell(p[i]) + 1];
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    slots_.resize(ring.size());
    std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
    for (std::uint32_t s = 0; s < ring.size(); ++s) slots_[next[cell(p[ring[s]])]++] = s;
  }

  /// Whether \p test holds for a ring slot in a cell that the triangle (a, b, c) overlaps.
  template <class Test>
  bool any_near(Vec3 a, Vec3 b, Vec3 c, const Test& test) const {
    const int u0 = column(std::min({a[pr_.u], b[pr_.u], c[pr_.u]}));
    const int u1 = column(std::max({a[pr_.u], b[pr_.u], c[pr_.u]}));
    const int v0 = row(std::min({a[pr_.v], b[pr_.v], c[pr_.v]}));
    const int v1 = row(std::max({a[pr_.v], b[pr_.v], c[pr_.v]}));
    for (int v = v0; v <= v1; ++v) {
      for (int u = u0; u <= u1; ++u) {
        const std::size_t c0 = std::size_t(v) * side_ + u;
        for (std::uint32_t k = start_[c0]; k < start_[c0 + 1]; ++k) {
          if (test(slots_[k])) return true;
        }
      }
    }
    return false;
  }

 private:
  static int bucket(double x, double lo, double hi, int side) {
    const double t = hi > lo ? (x - lo) / (hi - lo) : 0;
    return std::clamp(int(t * side), 0, side - 1);
  }
  int column(double x) const { return bucket(x, lo_u_, hi_u_, side_); }
  int row(double x) const { return bucket(x, lo_v_, hi_v_, side_); }
  std::size_t cell(Vec3 q) const { return std::size_t(row(q[pr_.v])) * side_ + column(q[pr_.u]); }

  const Projector& pr_;
  double lo_u_ = INFINITY, hi_u_ = -INFINITY, lo_v_ = INFINITY, hi_v_ = -INFINITY;
  int side_ = 1;
  std::vector<std::uint32_t> start_;  ///< per cell, into slots_
  std::vector<std::uint32_t> slots_;  ///< ring slots, cell by cell
};

// Ear clipping. A reflex-free ear that contains no other vertex is cut, and the search goes on
// past the vertex after it: lap by lap, a convex stretch is cut into ever larger but local
// triangles rather than into a fan of long ones around one corner, each of which the grid
// would search across. Once no reflex corner is left, what remains is convex and is cut as a
// fan, with no search. If a whole lap finds no ear (a self-touching polygon), the flattest
// vertex is cut, so that the loop always terminates.
void clip_ears(std::span<const Vec3> p, std::span<const std::uint32_t> ring, const Projector& pr,
               std::vector<std::array<std::uint32_t, 3>>& out) {
  const std::uint32_t n = std::uint32_t(ring.size());
  const RingGrid grid(p, ring, pr);
  std::vector<std::uint32_t> prev(n), next(n);
  for (std::uint32_t s = 0; s < n; ++s) prev[s] = (s + n - 1) % n, next[s] = (s + 1) % n;
  const auto turn = [&](std::uint32_t s) {
    return pr.cross2(p[ring[prev[s]]], p[ring[s]], p[ring[next[s]]]);
  };
  std::vector<bool> clipped(n, false), reflex(n, false);
  std::uint32_t reflexes = 0;
  const auto classify = [&](std::uint32_t s) {
    const bool r = turn(s) < 0;  // as is_convex() takes it
    reflexes += std::uint32_t(r) - std::uint32_t(reflex[s]);
    reflex[s] = r;
  };
  for (std::uint32_t s = 0; s < n; ++s) classify(s);
  const auto cut = [&](std::uint32_t b) {
    out.push_back({ring[prev[b]], ring[b], ring[next[b]]});
    clipped[b] = true;
    reflexes -= std::uint32_t(reflex[b]);
    next[prev[b]] = next[b], prev[next[b]] = prev[b];
    classify(prev[b]), classify(next[b]);
  };
  std::uint32_t b = 0, flattest = 0;
  double best_flat = -INFINITY;
  for (std::uint32_t left = n, failed = 0; left > 3 && reflexes > 0;) {
    if (failed == left) {  // a whole lap without an ear
      cut(flattest);
      b = flattest = prev[flattest], --left, failed = 0, best_flat = -INFINITY;
      continue;
    }
    const std::uint32_t a = ring[prev[b]], v = ring[b], c = ring[next[b]];
    const double t = turn(b);
    if (t > best_flat) best_flat = t, flattest = b;
    const bool ear = t > 0 && !grid.any_near(p[a], p[v], p[c], [&](std::uint32_t s) {
      const std::uint32_t q = ring[s];
      return !clipped[s] && q != a && q != v && q != c &&
             inside_triangle(pr, p[a], p[v], p[c], p[q]);
    });
    if (!ear) {
      b = next[b], ++failed;
      continue;
    }
    cut(b);
    b = flattest = next[next[b]], --left, failed = 0, best_flat = -INFINITY;
  }
  for (std::uint32_t s = next[b]; next[s] != b; s = next[s]) {
    out.push_back({ring[b], ring[s], ring[next[s]]});
  }
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
  clip_ears(positions, loop, pr, out);
}

}  // namespace shadowkit
