#include "shadowkit/raster/triangle_setup.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <tuple>

#include "shadowkit/core/error.h"
#include "shadowkit/core/prefetch.h"

namespace shadowkit::raster {
namespace {

constexpr int kClipPlanes = 5;

// a x + b y + c z + e >= 0 in view space keeps a point.
struct ClipPlane {
  double a, b, c, e;
  double eval(Vec3 v) const { return a * v.x + b * v.y + c * v.z + e; }
};

std::array<ClipPlane, kClipPlanes> clip_planes(const RasterProjection& p) {
  const double g = kGuardBand, w = p.width, h = p.height;
  if (p.orthographic) {
    return {{{0, 0, 1, -p.near},
             {p.scale_x, 0, 0, p.offset_x + g},
             {-p.scale_x, 0, 0, w + g - p.offset_x},
             {0, -p.scale_y, 0, p.offset_y + g},
             {0, p.scale_y, 0, h + g - p.offset_y}}};
  }
  return {{{0, 0, 1, -p.near},
           {p.scale_x, 0, p.offset_x + g, 0},
           {-p.scale_x, 0, w + g - p.offset_x, 0},
           {0, -p.scale_y, p.offset_y + g, 0},
           {0, p.scale_y, h + g - p.offset_y, 0}}};
}

struct DepthPlane {
  double a, b, c;
  bool valid;
};

// The depth key of a face is linear in screen space; taking it from the face's exact plane
// makes every triangle of a polygon agree (RasterProjection::depth_key).
DepthPlane depth_plane(const Plane& plane, const RasterProjection& p) {
  const Vec3 n{dot(plane.normal, p.right), dot(plane.normal, p.up), dot(plane.normal, p.forward)};
  const double dv = plane.distance(p.eye);
  DepthPlane k{};
  if (p.orthographic) {
    if (n.z == 0) return k;  // edge-on: covers no area
    k.a = n.x / (p.scale_x * n.z);
    k.b = -n.y / (p.scale_y * n.z);
    k.c = (-n.x * p.offset_x / p.scale_x + n.y * p.offset_y / p.scale_y + dv) / n.z;
  } else {
    if (dv == 0) return k;  // the plane passes through the eye: edge-on
    k.a = -n.x / (p.scale_x * dv);
    k.b = n.y / (p.scale_y * dv);
    k.c = (n.x * p.offset_x / p.scale_x - n.y * p.offset_y / p.scale_y - n.z) / dv;
  }
  // Pixel (px, py) is sampled at its centre (px + 0.5, py + 0.5).
  k.c += 0.5 * (k.a + k.b);
  k.valid = true;
  return k;
}

FixedPoint to_fixed(const RasterProjection& p, Vec3 v) {
  return {round_to_integer(p.pixel_x(v) * double(kSubpixel)),
          round_to_integer(p.pixel_y(v) * double(kSubpixel))};
}

// Where edge (p, q) crosses a clip plane. The endpoints are taken in a canonical order so
// that two triangles sharing the edge get bit-identical points: no cracks after clipping.
Vec3 crossing(Vec3 p, double dp, Vec3 q, double dq) {
  const bool swap = std::tie(q.x, q.y, q.z) < std::tie(p.x, p.y, p.z);
  if (swap) std::swap(p, q), std::swap(dp, dq);
  return p + (q - p) * (dp / (dp - dq));
}

using Polygon = std::vector<Vec3>;

Polygon clip(Polygon poly, const std::array<ClipPlane, kClipPlanes>& planes, unsigned outside) {
  Polygon next;
  for (int i = 0; i < kClipPlanes && poly.size() >= 3; ++i) {
    if (!(outside & (1u << i))) continue;
    next.clear();
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Vec3 a = poly[k], b = poly[(k + 1) % poly.size()];
      const double da = planes[i].eval(a), db = planes[i].eval(b);
      if (da >= 0) next.push_back(a);
      if ((da >= 0) != (db >= 0)) next.push_back(crossing(a, da, b, db));
    }
    poly.swap(next);
  }
  return poly;
}

// Antisymmetric ownership of the pixel centres on edge (from, to): of two triangles on
// either side of it, exactly one owns them (0: this one, 1: the other).
std::int8_t edge_bias(FixedPoint from, FixedPoint to) {
  const std::int64_t dx = to.x - from.x, dy = to.y - from.y;
  return (dy < 0 || (dy == 0 && dx > 0)) ? 0 : 1;
}

class TriangleBuilder {
 public:
  TriangleBuilder(const RasterProjection& view, std::vector<ScreenTriangle>& out)
      : view_(view), out_(out) {}

  void emit(FixedPoint v0, FixedPoint v1, FixedPoint v2, const DepthPlane& k, std::uint32_t face) {
    const std::int64_t area = (v1.x - v0.x) * (v2.y - v0.y) - (v1.y - v0.y) * (v2.x - v0.x);
    if (area == 0) return;
    if (area < 0) std::swap(v1, v2);
    const auto lo = [](std::int64_t a) {
      return int((a - kSubpixel / 2 + kSubpixel - 1) >> kSubpixelBits);
    };
    const auto hi = [](std::int64_t a) { return int((a - kSubpixel / 2) >> kSubpixelBits); };
    const int min_x = std::max(0, lo(std::min({v0.x, v1.x, v2.x})));
    const int min_y = std::max(0, lo(std::min({v0.y, v1.y, v2.y})));
    const int max_x = std::min(view_.width - 1, hi(std::max({v0.x, v1.x, v2.x})));
    const int max_y = std::min(view_.height - 1, hi(std::max({v0.y, v1.y, v2.y})));
    if (min_x > max_x || min_y > max_y) return;
    // Built in place, corner by corner from the arguments' registers: a temporary, or an
    // array of the corners, stalls on its own stores (a tenth of a million-triangle frame).
    ScreenTriangle& t = out_.emplace_back();
    t.key_a = k.a, t.key_b = k.b, t.key_c = k.c;
    t.x[0] = std::int32_t(v0.x), t.x[1] = std::int32_t(v1.x), t.x[2] = std::int32_t(v2.x);
    t.y[0] = std::int32_t(v0.y), t.y[1] = std::int32_t(v1.y), t.y[2] = std::int32_t(v2.y);
    t.min_x = std::int16_t(min_x), t.min_y = std::int16_t(min_y);
    t.max_x = std::int16_t(max_x), t.max_y = std::int16_t(max_y);
    t.face = face;
    t.bias[0] = edge_bias(v0, v1), t.bias[1] = edge_bias(v1, v2), t.bias[2] = edge_bias(v2, v0);
  }

 private:
  const RasterProjection& view_;
  std::vector<ScreenTriangle>& out_;
};

// A view-space point in homogeneous coordinates.
struct Vec4 {
  double x, y, z, w;
  Vec3 xyz() const { return {x, y, z}; }
};

double eval(const ClipPlane& plane, const Vec4& v) {
  return plane.a * v.x + plane.b * v.y + plane.c * v.z + plane.e * v.w;
}

// As crossing() above, in homogeneous coordinates.
Vec4 crossing(Vec4 p, double dp, Vec4 q, double dq) {
  if (std::tie(q.x, q.y, q.z, q.w) < std::tie(p.x, p.y, p.z, p.w))
    std::swap(p, q), std::swap(dp, dq);
  const double t = dp / (dp - dq);
  return {p.x + (q.x - p.x) * t, p.y + (q.y - p.y) * t, p.z + (q.z - p.z) * t,
          p.w + (q.w - p.w) * t};
}

// Clips \p poly in place; \p next is scratch.
void clip(std::vector<Vec4>& poly, std::vector<Vec4>& next,
          const std::array<ClipPlane, kClipPlanes>& planes) {
  for (int i = 0; i < kClipPlanes && poly.size() >= 3; ++i) {
    next.clear();
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Vec4 a = poly[k], b = poly[(k + 1) % poly.size()];
      const double da = eval(planes[i], a), db = eval(planes[i], b);
      if (da >= 0) next.push_back(a);
      if ((da >= 0) != (db >= 0)) next.push_back(crossing(a, da, b, db));
    }
    poly.swap(next);
  }
}

}  // namespace

void snapped_polygon(std::span<const HomogeneousPoint> corners, const RasterProjection& view,
                     std::vector<FixedPoint>& fixed) {
  // Points at infinity project like any other: pixel = offset + scale * x / z needs no w.
  SHADOWKIT_CHECK(!view.orthographic);
  // Scratch kept per thread: this runs per shadow polygon, hundreds of thousands a frame.
  thread_local std::vector<Vec4> poly, next;
  poly.clear();
  for (const HomogeneousPoint& c : corners) {
    const Vec3 v = c.xyz - view.eye * c.w;
    poly.push_back({dot(v, view.right), dot(v, view.up), dot(v, view.forward), c.w});
  }
  const auto planes = clip_planes(view);
  const bool inside = std::all_of(poly.begin(), poly.end(), [&](const Vec4& v) {
    return std::all_of(planes.begin(), planes.end(),
                       [&](const ClipPlane& plane) { return eval(plane, v) >= 0; });
  });
  if (!inside) clip(poly, next, planes);  // else clipping would keep it as it is
  fixed.clear();
  if (poly.size() < 3) return;
  for (const Vec4& p : poly) fixed.push_back(to_fixed(view, p.xyz()));
}

void setup_polygon(std::span<const HomogeneousPoint> corners, std::uint32_t id,
                   const RasterProjection& view, std::vector<ScreenTriangle>& out) {
  thread_local std::vector<FixedPoint> fixed;
  snapped_polygon(corners, view, fixed);
  TriangleBuilder builder(view, out);
  const DepthPlane none{0, 0, 0, true};
  for (std::size_t i = 2; i < fixed.size(); ++i)
    builder.emit(fixed[0], fixed[i - 1], fixed[i], none, id);
}

// The pixel columns of row `py` whose centres satisfy all three edge functions.
EdgeWalker::EdgeWalker(const ScreenTriangle& t, int edge, int first_row)
    : EdgeWalker({t.x[edge], t.y[edge]}, {t.x[(edge + 1) % 3], t.y[(edge + 1) % 3]}, t.bias[edge],
                 first_row) {}

EdgeWalker::EdgeWalker(FixedPoint from, FixedPoint to, std::int64_t bias, int first_row)
    : a_(0), abs_a_(0), c_(0), step_c_(0), q_(0), r_(0), step_q_(0), step_r_(0) {
  const std::int64_t dx = to.x - from.x, dy = to.y - from.y;
  // E(px, py) = dx (256 py + 128 - y_i) - dy (256 px + 128 - x_i) - bias = c(py) + a px.
  a_ = -dy * kSubpixel;
  const std::int64_t cy = std::int64_t(first_row) * kSubpixel + kSubpixel / 2;
  const std::int64_t c = dx * (cy - from.y) - dy * (kSubpixel / 2 - from.x) - bias;
  if (a_ == 0) {
    c_ = c;
    step_c_ = dx * kSubpixel;
    return;
  }
  // The boundary is -c / a; keep it as quotient and remainder (0 <= r < |a|) so that each
  // row only adds: exact, with no division per row.
  const std::int64_t m = abs_a_ = a_ > 0 ? a_ : -a_;
  const std::int64_t num = a_ > 0 ? -c : c;  // boundary = num / a (a > 0) or num / |a|
  split(num, m, q_, r_);
  split(a_ > 0 ? -dx * kSubpixel : dx * kSubpixel, m, step_q_, step_r_);
}

void EdgeWalker::split(std::int64_t num, std::int64_t den, std::int64_t& q, std::int64_t& r) {
  // |num| < 2^53, so the double quotient is within one of the floor; integers fix it up.
  // (Much faster than a 64-bit integer division, and this runs per triangle and tile.)
  q = std::int64_t(std::floor(double(num) / double(den)));
  r = num - q * den;
  if (r < 0) r += den, q -= 1;
  if (r >= den) r -= den, q += 1;
}

SpanWalker::SpanWalker(const ScreenTriangle& t, int first_row)
    : edges_{EdgeWalker(t, 0, first_row), EdgeWalker(t, 1, first_row),
             EdgeWalker(t, 2, first_row)} {}

namespace {

// Whether every edge function of \p t is >= 0 at the corner of [xa, xb] x [ya, yb] where it
// is largest (\p largest) or least: a linear function peaks at a corner.
bool edges_at_corners(const ScreenTriangle& t, int xa, int xb, int ya, int yb, bool largest) {
  for (int i = 0; i < 3; ++i) {
    const int j = i == 2 ? 0 : i + 1;
    const bool right = (t.y[j] < t.y[i]) == largest, below = (t.x[j] > t.x[i]) == largest;
    if (edge_function(t, i, right ? xb : xa, below ? yb : ya) < 0) return false;
  }
  return true;
}

}  // namespace

bool may_own_pixel_in(const ScreenTriangle& t, int xa, int xb, int ya, int yb) {
  return edges_at_corners(t, xa, xb, ya, yb, true);
}

bool owns_every_pixel_in(const ScreenTriangle& t, int xa, int xb, int ya, int yb) {
  return edges_at_corners(t, xa, xb, ya, yb, false);
}

ScreenTriangles setup_triangles(const Scene& scene, const RasterProjection& view) {
  return setup_triangles(scene, view, std::function<bool(std::uint32_t)>());
}

namespace {

// A triangle corner in view space: its position, the clip planes it is outside of and, when
// inside them all, its fixed-point pixel position. The same point always gives the same
// corner, so every triangle sharing a vertex snaps it identically.
struct Corner {
  Vec3 view_pos;
  unsigned outcode;
  FixedPoint fixed;
};

Corner corner(const RasterProjection& view, const std::array<ClipPlane, kClipPlanes>& planes,
              Vec3 position) {
  Corner c{view.to_view(position), 0, {}};
  for (int k = 0; k < kClipPlanes; ++k) c.outcode |= (planes[k].eval(c.view_pos) < 0) << k;
  if (c.outcode == 0) c.fixed = to_fixed(view, c.view_pos);
  return c;
}

// Sets up a triangle of \p scene's face \p face from its corners: dropped outside the clip
// planes, clipped where it crosses them.
void setup_triangle(const Scene& scene, const RasterProjection& view,
                    const std::array<ClipPlane, kClipPlanes>& planes, std::uint32_t face,
                    const Corner& c0, const Corner& c1, const Corner& c2,
                    TriangleBuilder& builder) {
  if (c0.outcode & c1.outcode & c2.outcode) return;
  const DepthPlane k = depth_plane(scene.face_plane(face), view);
  if (!k.valid) return;
  const unsigned any_out = c0.outcode | c1.outcode | c2.outcode;
  if (!any_out) return builder.emit(c0.fixed, c1.fixed, c2.fixed, k, face);
  thread_local Polygon poly;
  poly = clip({c0.view_pos, c1.view_pos, c2.view_pos}, planes, any_out);
  if (poly.size() < 3) return;
  const FixedPoint f0 = to_fixed(view, poly[0]);
  FixedPoint prev = to_fixed(view, poly[1]);
  for (std::size_t i = 2; i < poly.size(); ++i) {
    const FixedPoint cur = to_fixed(view, poly[i]);
    builder.emit(f0, prev, cur, k, face);
    prev = cur;
  }
}

// The corners a run of triangles met last, by vertex: the triangles of a cluster share
// vertices (a cube's twelve have eight), so most corners are computed once.
class CornerCache {
 public:
  CornerCache(const RasterProjection& view, const std::array<ClipPlane, kClipPlanes>& planes,
              const std::vector<Vec3>& positions)
      : view_(view), planes_(planes), positions_(positions) {
    vertex_.fill(std::numeric_limits<std::uint32_t>::max());
  }
  Corner operator()(std::uint32_t v) {
    const std::size_t slot = v % kSlots;
    if (vertex_[slot] != v)
      vertex_[slot] = v, corner_[slot] = corner(view_, planes_, positions_[v]);
    return corner_[slot];
  }

 private:
  static constexpr std::size_t kSlots = 64;
  const RasterProjection& view_;
  const std::array<ClipPlane, kClipPlanes>& planes_;
  const std::vector<Vec3>& positions_;
  std::array<std::uint32_t, kSlots> vertex_;
  std::array<Corner, kSlots> corner_;
};

// How many triangles ahead setup_cluster_triangles loads a face plane and vertices.
constexpr std::size_t kLoadAhead = 8;

// A triangle clipped by the five planes has at most eight corners: six triangles.
constexpr std::size_t kChunkTriangles = ScreenTriangles::kChunkSize / 6;

}  // namespace

ScreenTriangles setup_triangles(const Scene& scene, const RasterProjection& view,
                                const std::function<bool(std::uint32_t)>& keep) {
  const TriangleList& list = scene.triangles();
  const auto planes = clip_planes(view);
  const std::size_t nt = list.triangles.size();
  const std::size_t nv = list.positions.size();
  // With a filter, the vertices of the triangles kept (several threads may store a 1).
  std::vector<std::uint8_t> used(keep ? nv : 0);
  if (keep) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nt, 4096), [&](const auto& r) {
      for (std::size_t t = r.begin(); t != r.end(); ++t) {
        if (!keep(std::uint32_t(t))) continue;
        for (const std::uint32_t v : list.triangles[t]) {
          std::atomic_ref<std::uint8_t>(used[v]).store(1, std::memory_order_relaxed);
        }
      }
    });
  }

  // Per vertex, once.
  std::vector<Corner> corners(nv);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 4096), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      if (!keep || used[i]) corners[i] = corner(view, planes, list.positions[i]);
    }
  });

  ScreenTriangles out;
  auto& chunks = out.chunks_;
  chunks.resize((nt + kChunkTriangles - 1) / kChunkTriangles);
  SHADOWKIT_CHECK(chunks.size() < (std::size_t(1) << (32 - ScreenTriangles::kPlaceBits)));
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t c) {
    TriangleBuilder builder(view, chunks[c]);
    for (std::size_t t = c * kChunkTriangles; t < std::min(nt, (c + 1) * kChunkTriangles); ++t) {
      if (keep && !keep(std::uint32_t(t))) continue;
      const auto& tri = list.triangles[t];
      setup_triangle(scene, view, planes, list.triangle_face[t], corners[tri[0]], corners[tri[1]],
                     corners[tri[2]], builder);
    }
  });
  return out;
}

ScreenTriangles setup_cluster_triangles(const Scene& scene, const RasterProjection& view,
                                        std::span<const std::uint32_t> entries) {
  const TriangleClusters& clusters = scene.triangles().clusters;
  const auto planes = clip_planes(view);
  ScreenTriangles out;
  auto& chunks = out.chunks_;
  chunks.resize((entries.size() + kChunkTriangles - 1) / kChunkTriangles);
  SHADOWKIT_CHECK(chunks.size() < (std::size_t(1) << (32 - ScreenTriangles::kPlaceBits)));
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t c) {
    TriangleBuilder builder(view, chunks[c]);
    const std::vector<Vec3>& positions = scene.triangles().positions;
    CornerCache corners(view, planes, positions);
    const std::size_t end = std::min(entries.size(), (c + 1) * kChunkTriangles);
    chunks[c].reserve(end - c * kChunkTriangles);
    for (std::size_t i = c * kChunkTriangles; i < end; ++i) {
      // In cluster order, triangles are scattered over the scene's face planes and vertex
      // positions: those of a triangle a few ahead start loading now, and the entry of a
      // triangle twice as far ahead, which names them (the next cluster's, at its start).
      if (i + 2 * kLoadAhead < end) {
        const std::uint32_t further = entries[i + 2 * kLoadAhead];
        prefetch(clusters.faces[further]);
        prefetch(clusters.corners[further]);
      }
      if (i + kLoadAhead < end) {
        const std::uint32_t ahead = entries[i + kLoadAhead];
        prefetch(scene.face_plane(clusters.faces[ahead]));
        for (const std::uint32_t v : clusters.corners[ahead]) prefetch(positions[v]);
      }
      const auto& [a, b, d] = clusters.corners[entries[i]];
      setup_triangle(scene, view, planes, clusters.faces[entries[i]], corners(a), corners(b),
                     corners(d), builder);
    }
  });
  return out;
}

}  // namespace shadowkit::raster
