#include "convex_volume.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace shadowkit {
namespace {

struct Point2 {
  double x, y;
};

// The convex hull of \p p, counter-clockwise (Andrew's monotone chain); \p p is reordered.
std::vector<Point2> convex_hull(std::vector<Point2>& p) {
  std::sort(p.begin(), p.end(),
            [](Point2 a, Point2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  const auto turn = [](Point2 o, Point2 a, Point2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  if (p.size() < 3) return p;
  std::vector<Point2> hull(2 * p.size());
  std::size_t n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (n >= 2 && turn(hull[n - 2], hull[n - 1], p[i]) <= 0) --n;
    hull[n++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = n + 1; i-- > 0;) {
    while (n >= lower && turn(hull[n - 2], hull[n - 1], p[i]) <= 0) --n;
    hull[n++] = p[i];
  }
  hull.resize(n - 1);
  return hull;
}

}  // namespace

bool outline_columns(std::span<const OutlineEdge> outline, int ya, int yb, int& xa, int& xb) {
  // Rows widened by a pixel: the corners were snapped, the centres' coverage is the raster's.
  const double lo_y = ya - 1.0, hi_y = yb + 1.0;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const OutlineEdge& e : outline) {
    if (e.y1 < lo_y || e.y0 > hi_y) continue;
    const double xs = e.y0 < lo_y ? e.x0 + e.slope * (lo_y - e.y0) : e.x0;
    const double xe = e.y1 > hi_y ? e.x0 + e.slope * (hi_y - e.y0) : e.x1;
    lo = std::min({lo, xs, xe}), hi = std::max({hi, xs, xe});
  }
  if (!(lo <= hi)) return false;
  xa = std::max(xa, int(std::floor(lo)) - 1);
  xb = std::min(xb, int(std::ceil(hi)) + 1);
  return xa <= xb;
}

ConvexVolumes::ConvexVolumes(const std::vector<ShadowPolygon>& polygons,
                             const std::vector<ShadowFrustum>& frusta,
                             const std::vector<char>& cullable, const RayGrid& rays,
                             std::span<const raster::ScreenPolygon> screen)
    : index_(frusta.size(), -1) {
  std::vector<char> depth_pass(frusta.size(), 1);
  for (const ShadowPolygon& p : polygons) depth_pass[p.sub_object] &= !p.depth_fail;
  for (const ShadowPolygon& p : polygons) {
    const std::uint32_t k = p.sub_object;
    const std::span<const Plane> planes = frusta[k].volume_planes();
    if (index_[k] >= 0 || !depth_pass[k] || !cullable[k] || planes.empty()) continue;
    ConvexVolume v;
    v.sub_object = k;
    for (const Plane& inward : planes) {
      // Depth-pass keeps the eye off these planes (needs_depth_fail, the eye's count).
      const bool eye_outside = inward.distance(rays.eye) < 0;
      const Plane plane = eye_outside ? inward : Plane{-inward.normal, -inward.d};
      v.inside_beyond |= std::uint32_t(eye_outside) << v.plane_count;
      v.keys[v.plane_count] = rays.key_plane(plane.normal, plane.d);
      v.planes[v.plane_count++] = plane;
    }
    index_[k] = std::int32_t(volumes_.size());
    volumes_.push_back(v);
  }
  // Each volume's outline: the hull of its polygons' corners on screen.
  std::vector<std::vector<Point2>> corners(volumes_.size());
  for (const raster::ScreenPolygon& s : screen) {
    const std::int32_t v = index_[polygons[s.face].sub_object];
    if (v < 0) continue;
    for (int i = 0; i < s.count; ++i) {
      const raster::FixedPoint q = s.corners[std::size_t(i)].p;
      constexpr double kSub = double(raster::kSubpixel);
      corners[std::size_t(v)].push_back(
          {(double(q.x) - kSub / 2) / kSub, (double(q.y) - kSub / 2) / kSub});
    }
  }
  outline_start_.push_back(0);
  for (std::vector<Point2>& c : corners) {
    const std::vector<Point2> hull = convex_hull(c);
    for (std::size_t i = 0; i < hull.size(); ++i) {
      Point2 a = hull[i], b = hull[(i + 1) % hull.size()];
      if (a.y > b.y) std::swap(a, b);
      outline_.push_back({a.x, a.y, b.x, b.y, b.y > a.y ? (b.x - a.x) / (b.y - a.y) : 0});
    }
    outline_start_.push_back(outline_.size());
  }
}

std::size_t ConvexVolume::count_cell(const VisibleFrame& frame, int band, int c, int xa, int xb,
                                     int ya, int yb, CountingTile& t) const {
  const int cx0 = t.x0 + c * kBlock, cx1 = std::min(t.x0 + t.w, cx0 + kBlock) - 1;
  const int cy0 = t.y0 + band * kBand, cy1 = std::min(t.y0 + t.h, cy0 + kBand) - 1;
  // Each plane against the cell's visible keys: all beyond it, none, or mixed (left to the
  // pixels).
  std::uint32_t mixed = 0;
  for (int i = 0; i < plane_count; ++i) {
    const Crossing cross = classify_rectangle(keys[i], cx0, cx1, cy0, cy1, t.cell_keys[band][c]);
    if (cross == Crossing::mixed) {
      mixed |= 1u << i;
    } else if ((cross == Crossing::all_before) != bool(inside_beyond >> i & 1)) {
      return 0;  // every visible point of the cell outside this plane
    }
  }
  if (!mixed) {  // every visible point of the cell in the volume: shadowed, whatever else
    t.shadowed |= std::uint64_t(1) << (band * kCellColumns + c);
    return 0;
  }
  std::size_t tested = 0;
  const int a = std::max(xa, cx0), b = std::min(xb, cx1);
  for (int py = std::max(ya, cy0); py <= std::min(yb, cy1); ++py) {
    const int row = py - t.y0;
    // The run of the row the same way, then its pixels against the planes still mixed.
    std::uint32_t run_mixed = 0;
    bool outside = false;
    for (std::uint32_t m = mixed; m && !outside; m &= m - 1) {
      const int i = std::countr_zero(m);
      const double ka = keys[i].at(a, py), kb = keys[i].at(b, py);
      const Crossing cross =
          classify(std::min(ka, kb), std::max(ka, kb), keys[i].slack, t.run_keys[row][c]);
      if (cross == Crossing::mixed) {
        run_mixed |= 1u << i;
      } else {
        outside = (cross == Crossing::all_before) != bool(inside_beyond >> i & 1);
      }
    }
    if (outside) continue;
    if (!run_mixed) {
      int* delta = t.delta + row * (kTile + 1) - t.x0;
      ++delta[a], --delta[b + 1];
      continue;
    }
    for (int px = a; px <= b; ++px) {
      const int i = row * t.w + px - t.x0;
      if (t.face[i] == kNoFace) continue;
      ++tested;
      bool inside = true;
      for (std::uint32_t m = run_mixed; m && inside; m &= m - 1) {
        const int k = std::countr_zero(m);
        inside = beyond_plane(planes[k], keys[k], frame, px, py, t.key[i]) ==
                 bool(inside_beyond >> k & 1);
      }
      t.count[i] += inside;
    }
  }
  return tested;
}

}  // namespace shadowkit
