#include "polygon_tiles.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowkit::volume {

using raster::ScreenPolygon;

bool overlaps_rectangle(const ScreenPolygon& s, int x0, int y0, int x1, int y1) {
  for (int i = 0; i < s.count; ++i) {
    const raster::FixedPoint a = s.corners[i], b = s.corners[(i + 1) % s.count];
    const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
    // As EdgeWalker: E = dx (256 py + 128 - y_i) - dy (256 px + 128 - x_i), >= 0 inside.
    const auto e = [&](int px, int py) {
      return dx * (py * raster::kSubpixel + raster::kSubpixel / 2 - a.y) -
             dy * (px * raster::kSubpixel + raster::kSubpixel / 2 - a.x);
    };
    if (std::max({e(x0, y0), e(x1, y0), e(x0, y1), e(x1, y1)}) < 0) return false;
  }
  return true;
}

void narrow_to_strip(const ScreenPolygon& s, bool u_is_x, int ua, int ub, int& va, int& vb) {
  constexpr double kSub = double(raster::kSubpixel);
  const double lo = (ua - 0.5) * kSub, hi = (ub + 1.5) * kSub;  // centres +- one pixel
  double v_min = std::numeric_limits<double>::infinity(), v_max = -v_min;
  for (int i = 0; i < s.count; ++i) {
    const raster::FixedPoint a = s.corners[i], b = s.corners[(i + 1) % s.count];
    double u0 = double(u_is_x ? a.x : a.y), v0 = double(u_is_x ? a.y : a.x);
    double u1 = double(u_is_x ? b.x : b.y), v1 = double(u_is_x ? b.y : b.x);
    if (u0 > u1) std::swap(u0, u1), std::swap(v0, v1);
    if (u1 < lo || u0 > hi) continue;
    // The part of the edge inside the strip; v is linear in u along it.
    const double slope = u1 > u0 ? (v1 - v0) / (u1 - u0) : 0;
    const double va_edge = u0 < lo ? v0 + slope * (lo - u0) : v0;
    const double vb_edge = u1 > hi ? v0 + slope * (hi - u0) : v1;
    v_min = std::min({v_min, va_edge, vb_edge});
    v_max = std::max({v_max, va_edge, vb_edge});
  }
  va = std::max(va, int(std::floor(v_min / kSub)) - 1);
  vb = std::min(vb, int(std::ceil(v_max / kSub)) + 1);
}

PolygonBins::PolygonBins(std::span<const ScreenPolygon* const> polygons, int width, int height)
    : tiles_x((width + kTile - 1) / kTile), tiles_y((height + kTile - 1) / kTile) {
  // (tile, polygon) pairs, chunks of polygons in parallel, kept in order.
  constexpr std::size_t kChunk = 512;
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> chunks(
      (polygons.size() + kChunk - 1) / kChunk);
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t c) {
    for (std::size_t i = c * kChunk; i < std::min(polygons.size(), (c + 1) * kChunk); ++i) {
      const ScreenPolygon& s = *polygons[i];
      for (int ty = s.min_y / kTile; ty <= s.max_y / kTile; ++ty) {
        int xa = s.min_x, xb = s.max_x;
        narrow_to_strip(s, false, std::max(s.min_y, ty * kTile),
                        std::min(s.max_y, ty * kTile + kTile - 1), xa, xb);
        for (int tx = std::max(0, xa) / kTile; tx <= std::min(width - 1, xb) / kTile; ++tx) {
          chunks[c].emplace_back(std::uint32_t(ty * tiles_x + tx), std::uint32_t(i));
        }
      }
    }
  });
  // A counting sort: each chunk counts its pairs per tile, then, from where its tiles' runs
  // begin after the chunks before it, places them; both in parallel.
  const std::size_t tiles = std::size_t(tiles_x) * tiles_y;
  std::vector<std::vector<std::uint32_t>> at(chunks.size());
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t c) {
    at[c].assign(tiles, 0);
    for (const auto& pair : chunks[c]) ++at[c][pair.first];
  });
  start.assign(tiles + 1, 0);
  for (std::size_t t = 0; t < tiles; ++t) {
    std::uint32_t next = start[t];
    for (std::vector<std::uint32_t>& counts : at) {
      const std::uint32_t n = counts[t];
      counts[t] = next;
      next += n;
    }
    start[t + 1] = next;
  }
  items.resize(start.back());
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t c) {
    for (const auto& [tile, polygon] : chunks[c]) items[at[c][tile]++] = polygon;
  });
}

}  // namespace shadowkit::volume
