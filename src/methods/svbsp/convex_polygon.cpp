#include "convex_polygon.h"

#include <cmath>
#include <optional>
#include <tuple>

namespace shadowkit::svbsp {
namespace {

int side_of(double d, double eps) {
  return d > eps ? 1 : (d < -eps ? -1 : 0);
}

// The point where segment a-b crosses the plane, independent of the segment's direction.
Vec3 crossing(Vec3 a, double da, Vec3 b, double db) {
  if (std::tie(b.x, b.y, b.z) < std::tie(a.x, a.y, a.z)) std::swap(a, b), std::swap(da, db);
  return a + (b - a) * (da / (da - db));
}

// Sutherland-Hodgman for one side s (+1 or -1), keeping the per-edge flags: each emitted
// vertex carries the flag of the edge that leaves it. With \p mark, an emitted edge along the
// plane (an edge with both ends on it, or the cut) is flagged when both its ends lie within
// \p *mark of it.
void clip_side(const ConvexPolygon& p, std::span<const double> d, std::span<const int> side, int s,
               std::optional<double> mark, ConvexPolygon& out) {
  out.vertices.clear();
  out.edge_in_tree.clear();
  out.face = p.face;
  absl::InlinedVector<bool, 8> along, exact;  // per emitted edge; per emitted vertex
  const std::size_t n = p.vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const int sa = side[i] * s, sb = side[j] * s;
    const bool flag = p.edge_in_tree[i];
    if (sa >= 0) {
      out.vertices.push_back(p.vertices[i]);
      exact.push_back(mark && std::abs(d[i]) <= *mark);
      // Kept edge: its own flag, along the plane if both ends are on it. Leaving edge from an
      // on-vertex: the next vertex emitted is on the plane too, so that edge is the cut.
      out.edge_in_tree.push_back(sb >= 0 || sa != 0 ? flag : 0);
      along.push_back(sa == 0 && sb <= 0);
    }
    if (sa * sb < 0) {
      out.vertices.push_back(crossing(p.vertices[i], d[i], p.vertices[j], d[j]));
      exact.push_back(true);
      out.edge_in_tree.push_back(sb > 0 ? flag : 0);
      along.push_back(sb < 0);
    }
  }
  if (!mark) return;
  const std::size_t m = out.vertices.size();
  for (std::size_t k = 0; k < m; ++k) {
    if (along[k] && exact[k] && exact[(k + 1) % m]) out.edge_in_tree[k] = 1;
  }
}

// Flags the edges of \p p whose ends both lie within \p within of the plane.
void mark_on_edges(ConvexPolygon& p, std::span<const double> d, double within) {
  const std::size_t n = p.vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (std::abs(d[i]) <= within && std::abs(d[(i + 1) % n]) <= within) p.edge_in_tree[i] = 1;
  }
}

}  // namespace

ConvexPolygon make_polygon(std::span<const Vec3> vertices, std::uint32_t face) {
  ConvexPolygon p;
  p.edge_in_tree.assign(vertices.size(), 0);
  p.vertices.assign(vertices.begin(), vertices.end());
  p.face = face;
  return p;
}

std::size_t heap_bytes(const ConvexPolygon& p) {
  const auto spilled = [](const auto& v) {
    return v.capacity() > ConvexPolygon::kInlineCorners ? v.capacity() * sizeof(v[0]) : 0;
  };
  return spilled(p.vertices) + spilled(p.edge_in_tree);
}

Vec3 centroid(const ConvexPolygon& p) {
  Vec3 sum;
  for (const Vec3& v : p.vertices) sum += v;
  return sum / double(p.vertices.size());
}

double area(const ConvexPolygon& p) {
  Vec3 sum;
  for (std::size_t i = 1; i + 1 < p.vertices.size(); ++i) {
    sum += cross(p.vertices[i] - p.vertices[0], p.vertices[i + 1] - p.vertices[0]);
  }
  return 0.5 * length(sum);
}

void mark_edges_in_plane(ConvexPolygon& p, const Plane& plane, double eps, double within) {
  const std::size_t n = p.vertices.size();
  absl::InlinedVector<double, 8> d(n);
  bool off = false;
  for (std::size_t i = 0; i < n; ++i) {
    d[i] = plane.distance(p.vertices[i]);
    off = off || side_of(d[i], eps) != 0;
  }
  if (off) mark_on_edges(p, d, within);
}

void split_polygon(const ConvexPolygon& p, const Plane& plane, double eps,
                   std::optional<double> mark_within, ConvexPolygon& negative,
                   ConvexPolygon& positive) {
  const std::size_t n = p.vertices.size();
  absl::InlinedVector<double, 8> d(n);
  absl::InlinedVector<int, 8> side(n);
  bool any_negative = false, any_positive = false, any_on = false;
  for (std::size_t i = 0; i < n; ++i) {
    d[i] = plane.distance(p.vertices[i]);
    side[i] = side_of(d[i], eps);
    any_negative = any_negative || side[i] < 0;
    any_positive = any_positive || side[i] > 0;
    any_on = any_on || side[i] == 0;
  }
  negative.vertices.clear();
  positive.vertices.clear();
  // A sliver within eps of the plane has no edge that bounds the cell: mark nothing.
  const std::optional<double> mark =
      any_negative || any_positive ? mark_within : std::optional<double>();
  if (!any_negative || !any_positive) {  // one side: the polygon whole, its edges on the plane
    ConvexPolygon& out = any_negative ? negative : positive;
    out = p;
    if (mark && any_on) mark_on_edges(out, d, *mark);
    return;
  }
  clip_side(p, d, side, -1, mark, negative);
  clip_side(p, d, side, 1, mark, positive);
}

}  // namespace shadowkit::svbsp
