#include "convex_volume.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include "shadowkit/core/convex_hull.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace shadowkit::volume {

using raster::FixedPoint;

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

ConvexVolumes::ConvexVolumes(const std::vector<ShadowPolygon>& polygons, const ShadowFrusta& frusta,
                             const std::vector<char>& cullable, const RayGrid& rays,
                             std::span<const raster::ScreenPolygon> screen)
    : index_(frusta.size(), -1) {
  std::vector<char> depth_pass(frusta.size(), 1);
  for (const ShadowPolygon& p : polygons) depth_pass[p.sub_object] &= !p.depth_fail;
  std::vector<std::uint32_t> of_volume;  // sub-object per volume
  for (const ShadowPolygon& p : polygons) {
    const std::uint32_t k = p.sub_object;
    if (index_[k] >= 0 || !depth_pass[k] || !cullable[k] || frusta[k].volume_planes().empty())
      continue;
    index_[k] = std::int32_t(of_volume.size());
    of_volume.push_back(k);
  }
  volumes_.resize(of_volume.size());
  tbb::parallel_for(std::size_t(0), volumes_.size(), [&](std::size_t i) {
    ConvexVolume& v = volumes_[i];
    v.sub_object = of_volume[i];
    for (const Plane& inward : frusta[v.sub_object].volume_planes()) {
      // Depth-pass keeps the eye off these planes (needs_depth_fail, the eye's count).
      const bool eye_outside = inward.distance(rays.eye) < 0;
      const Plane plane = eye_outside ? inward : Plane{-inward.normal, -inward.d};
      v.inside_beyond |= std::uint32_t(eye_outside) << v.plane_count;
      v.keys[v.plane_count] = rays.key_plane(plane.normal, plane.d);
      v.planes[v.plane_count++] = plane;
    }
  });
  // Each volume's outline: the hull of its polygons' corners on screen. Screen polygons
  // follow polygon order, so each volume's lie together.
  polygons_of_.assign(volumes_.size(), {0, 0});
  std::vector<std::uint32_t> corner_start(volumes_.size() + 1, 0);
  for (std::size_t i = 0; i < screen.size(); ++i) {
    const std::int32_t v = index_[polygons[screen[i].face].sub_object];
    if (v < 0) continue;
    auto& [first, last] = polygons_of_[std::size_t(v)];
    if (first == last) first = std::uint32_t(i);
    last = std::uint32_t(i + 1);
    corner_start[std::size_t(v) + 1] += std::uint32_t(screen[i].count);
  }
  for (std::size_t v = 0; v < volumes_.size(); ++v) corner_start[v + 1] += corner_start[v];
  // Per volume, its hull's corners where its polygons' corners were gathered, then its
  // outline edges: both in parallel, the outlines packed by a count in between.
  std::vector<FixedPoint> corners(corner_start.back());
  std::vector<std::uint32_t> outline_count(volumes_.size());
  hulls_.resize(volumes_.size());
  tbb::parallel_for(std::size_t(0), volumes_.size(), [&](std::size_t v) {
    thread_local std::vector<FixedPoint> hull;
    outline_count[v] = std::uint32_t(
        hull_of(v, screen,
                {corners.data() + corner_start[v], corner_start[v + 1] - corner_start[v]}, hull));
  });
  outline_start_.assign(volumes_.size() + 1, 0);
  for (std::size_t v = 0; v < volumes_.size(); ++v) {
    outline_start_[v + 1] = outline_start_[v] + outline_count[v];
  }
  outline_.resize(outline_start_.back());
  tbb::parallel_for(std::size_t(0), volumes_.size(), [&](std::size_t v) {
    const FixedPoint* hull = corners.data() + corner_start[v];
    const std::size_t count = outline_count[v];
    const auto pixels = [](FixedPoint q) {  // a subpixel point in pixel units
      constexpr double kSub = double(raster::kSubpixel);
      return std::pair{(double(q.x) - kSub / 2) / kSub, (double(q.y) - kSub / 2) / kSub};
    };
    for (std::size_t i = 0; i < count; ++i) {
      auto [ax, ay] = pixels(hull[i]);
      auto [bx, by] = pixels(hull[(i + 1) % count]);
      if (ay > by) std::swap(ax, bx), std::swap(ay, by);
      outline_[outline_start_[v] + i] = {ax, ay, bx, by, by > ay ? (bx - ax) / (by - ay) : 0};
    }
  });
}

std::size_t ConvexVolumes::hull_of(std::size_t v, std::span<const raster::ScreenPolygon> screen,
                                   std::span<FixedPoint> corners, std::vector<FixedPoint>& hull) {
  const auto [first, last] = polygons_of_[v];
  raster::ScreenPolygon& out = hulls_[v];
  out.face = first < last ? screen[first].face : 0;
  out.min_x = out.min_y = std::numeric_limits<int>::max();
  out.max_x = out.max_y = std::numeric_limits<int>::min();
  std::size_t n = 0;
  for (std::uint32_t i = first; i < last; ++i) {
    const raster::ScreenPolygon& s = screen[i];
    for (int c = 0; c < s.count; ++c) corners[n++] = s.corners[std::size_t(c)];
    out.min_x = std::min(out.min_x, s.min_x), out.max_x = std::max(out.max_x, s.max_x);
    out.min_y = std::min(out.min_y, s.min_y), out.max_y = std::max(out.max_y, s.max_y);
  }
  const std::size_t count = convex_hull(corners.first(n), hull);
  // Binned whole when its corners fit (the bias does not matter to the bins).
  out.count = count >= 3 && count <= std::size_t(raster::kMaxPolygonCorners) ? int(count) : 0;
  std::copy_n(hull.begin(), count, corners.begin());
  if (out.count > 0) std::copy_n(hull.begin(), count, out.corners.begin());
  return count;
}

unsigned ConvexVolume::lane_bits(const LaneMask* m) {
#if defined(__SSE2__)
  unsigned out = 0;
  for (int v = 0; v < kLaneVectors; ++v) {
    out |= unsigned(_mm_movemask_pd(_mm_castsi128_pd(__m128i(m[v])))) << (2 * v);
  }
  return out;
#else
  unsigned out = 0;
  for (int v = 0; v < kLaneVectors; ++v) {
    out |= unsigned(m[v][0] & 1) << (2 * v) | unsigned(m[v][1] & 1) << (2 * v + 1);
  }
  return out;
#endif
}

std::size_t ConvexVolume::count_run(const VisibleFrame& frame, int row, int c, unsigned pending,
                                    std::uint32_t mixed, CountingTile& t) const {
  // The cell's run of the row at once, two pixels a vector: per plane, the pixels certainly
  // on the volume's side of it (the key beyond its slack) and those certainly outside.
  static_assert(kBlock == 2 * kLaneVectors);
  const int py = t.y0 + row, x0 = t.x0 + c * kBlock, first = row * t.w - t.x0 + x0;
  const int width = std::min(kBlock, t.x0 + t.w - x0);
  // The visible keys, and their negatives for the planes the volume lies in front of: there
  // the volume's side is where the negated key exceeds the negated visible one.
  Lanes visible[2][kLaneVectors];
  if (width == kBlock) {
    std::memcpy(visible[1], t.key + first, sizeof visible[1]);
  } else {
    for (int j = 0; j < kBlock; ++j) {
      visible[1][j / 2][j % 2] =
          j < width ? t.key[first + j] : std::numeric_limits<double>::quiet_NaN();
    }
  }
  for (int v = 0; v < kLaneVectors; ++v) visible[0][v] = -visible[1][v];
  LaneMask inside[kLaneVectors], outside[kLaneVectors] = {};
  for (LaneMask& m : inside) m = ~LaneMask{};
  for (std::uint32_t m = mixed; m; m &= m - 1) {
    const int k = std::countr_zero(m);
    const KeyPlane& key = keys[k];
    const bool beyond = inside_beyond >> k & 1;
    const double sign = beyond ? 1 : -1, at = sign * key.at(x0, py), a = sign * key.a;
    Lanes lane_key = Lanes{at, at + a};
    const Lanes step = Lanes{2 * a, 2 * a};
    const Lanes* seen = visible[beyond];
    for (int v = 0; v < kLaneVectors; ++v, lane_key += step) {
      inside[v] &= lane_key - key.slack > seen[v];
      outside[v] |= lane_key + key.slack < seen[v];
    }
  }
  LaneMask shown[kLaneVectors];
  for (int v = 0; v < kLaneVectors; ++v) shown[v] = visible[1][v] == visible[1][v];
  const unsigned tested = lane_bits(shown) & pending;  // not background
  unsigned in = lane_bits(inside) & tested;
  // Pixels near a plane: the exact test.
  for (unsigned near = tested & ~in & ~lane_bits(outside); near; near &= near - 1) {
    const int j = std::countr_zero(near);
    bool in_volume = true;
    for (std::uint32_t m = mixed; m && in_volume; m &= m - 1) {
      const int k = std::countr_zero(m);
      in_volume = beyond_plane(planes[k], keys[k], frame, x0 + j, py, t.key[first + j]) ==
                  bool(inside_beyond >> k & 1);
    }
    in |= unsigned(in_volume) << j;
  }
  for (unsigned m = in; m; m &= m - 1) ++t.count[first + std::countr_zero(m)];
  t.settled[row] |= std::uint64_t(in) << (x0 - t.x0);
  return std::size_t(std::popcount(tested));
}

std::size_t ConvexVolume::count_cell(const VisibleFrame& frame, int band, int c, int xa, int xb,
                                     int ya, int yb, CountingTile& t) const {
  const int cx0 = t.x0 + c * kBlock, cx1 = std::min(t.x0 + t.w, cx0 + kBlock) - 1;
  const int cy0 = t.y0 + band * kBand, cy1 = std::min(t.y0 + t.h, cy0 + kBand) - 1;
  const std::uint64_t cell_bit = std::uint64_t(1) << (band * kCellColumns + c);
  // Pixels settled before: skipped; all of the cell's: the cell is.
  const auto settled_cell = [&] {
    for (int row = cy0 - t.y0; row <= cy1 - t.y0; ++row) {
      if ((t.settled[row] >> (cx0 - t.x0) & 0xFF) != 0xFF) return false;
    }
    t.shadowed |= cell_bit;
    return true;
  };
  if (settled_cell()) return 0;
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
    t.shadowed |= cell_bit;
    return 0;
  }
  std::size_t tested = 0;
  const int a = std::max(xa, cx0), b = std::min(xb, cx1);
  for (int py = std::max(ya, cy0); py <= std::min(yb, cy1); ++py) {
    const int row = py - t.y0;
    const unsigned pending =
        (((2u << (b - a)) - 1) << (a - cx0)) & ~unsigned(t.settled[row] >> (cx0 - t.x0) & 0xFF);
    if (!pending) continue;
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
      t.settled[row] |= std::uint64_t(pending) << (cx0 - t.x0);
      continue;
    }
    tested += count_run(frame, row, c, pending, run_mixed, t);
  }
  settled_cell();
  return tested;
}

}  // namespace shadowkit::volume
