#include "shadowkit/raster/scan_converter.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "shadowkit/core/error.h"

#include "triangle_setup.h"

namespace shadowkit {
namespace {

using raster::kSubpixel;
using raster::ScreenTriangle;
constexpr int kTile = ScanConverter::kTileSize;

// Counting sort of triangle indices into the tiles their bounds overlap; each bin keeps
// triangle order.
struct TileBins {
  int tiles_x = 0, tiles_y = 0;
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> items;

  TileBins(const std::vector<ScreenTriangle>& tris, int width, int height)
      : tiles_x((width + kTile - 1) / kTile), tiles_y((height + kTile - 1) / kTile) {
    std::vector<std::uint32_t> count(std::size_t(tiles_x) * tiles_y + 1, 0);
    for_each_tile(tris, [&](std::size_t tile, std::uint32_t) { ++count[tile + 1]; });
    std::uint64_t total = 0;
    for (std::size_t i = 1; i < count.size(); ++i) total += count[i];
    SHADOWKIT_CHECK(total < std::numeric_limits<std::uint32_t>::max());
    for (std::size_t i = 1; i < count.size(); ++i) count[i] += count[i - 1];
    start = count;
    items.resize(count.back());
    for_each_tile(tris, [&](std::size_t tile, std::uint32_t t) { items[count[tile]++] = t; });
  }

  template <class Fn>
  void for_each_tile(const std::vector<ScreenTriangle>& tris, Fn&& fn) const {
    for (std::uint32_t t = 0; t < tris.size(); ++t) {
      const ScreenTriangle& s = tris[t];
      for (int ty = s.min_y / kTile; ty <= s.max_y / kTile; ++ty) {
        for (int tx = s.min_x / kTile; tx <= s.max_x / kTile; ++tx) {
          fn(std::size_t(ty) * tiles_x + tx, t);
        }
      }
    }
  }
};

struct TileBuffers {
  double key[kTile * kTile];
  std::uint32_t face[kTile * kTile];
};

void raster_tile(const std::vector<ScreenTriangle>& tris, const std::uint32_t* bin,
                 std::size_t bin_size, int x0, int y0, int w, int h, TileBuffers& buf) {
  std::fill_n(buf.key, w * h, -INFINITY);
  std::fill_n(buf.face, w * h, kNoFace);
  for (std::size_t k = 0; k < bin_size; ++k) {
    const ScreenTriangle& t = tris[bin[k]];
    const int ya = std::max(y0, t.min_y), yb = std::min(y0 + h - 1, t.max_y);
    raster::SpanWalker walker(t, ya);
    for (int py = ya; py <= yb; ++py, walker.next_row()) {
      int xa = std::max(x0, t.min_x), xb = std::min(x0 + w - 1, t.max_x);
      if (!walker.span(xa, xb)) continue;
      double* key = buf.key + (py - y0) * w - x0;
      std::uint32_t* face = buf.face + (py - y0) * w - x0;
      // Locals, so the compiler need not reload them after every store to the tile.
      const double row = t.key_b * py + t.key_c, key_a = t.key_a;
      const std::uint32_t id = t.face;
      for (int px = xa; px <= xb; ++px) {
        const double z = key_a * px + row;
        if (z > key[px]) {
          key[px] = z;
          face[px] = id;
        }
      }
    }
  }
}

}  // namespace

void ScanConverter::rasterize_tiles(const RasterProjection& view, const Context& /*ctx*/,
                                    const std::function<void(const RasterTile&)>& fn) const {
  const std::vector<ScreenTriangle> tris = raster::setup_triangles(scene_, view);
  const TileBins bins(tris, view.width, view.height);
  const int tile_count = bins.tiles_x * bins.tiles_y;
  tbb::parallel_for(0, tile_count, [&](int tile) {
    thread_local TileBuffers buf;
    const int x0 = (tile % bins.tiles_x) * kTile, y0 = (tile / bins.tiles_x) * kTile;
    const int w = std::min(kTile, view.width - x0), h = std::min(kTile, view.height - y0);
    raster_tile(tris, bins.items.data() + bins.start[tile], bins.start[tile + 1] - bins.start[tile],
                x0, y0, w, h, buf);
    fn(RasterTile{x0, y0, w, h, buf.key, buf.face});
  });
}

DepthFaceBuffer ScanConverter::rasterize(const RasterProjection& view, const Context& ctx) const {
  DepthFaceBuffer out;
  out.width = view.width;
  out.height = view.height;
  out.depth_key.resize(std::size_t(view.width) * view.height);
  out.face.resize(out.depth_key.size());
  rasterize_tiles(view, ctx, [&](const RasterTile& tile) {
    for (int y = 0; y < tile.height; ++y) {
      const std::size_t dst = std::size_t(tile.y0 + y) * view.width + tile.x0;
      std::transform(tile.depth_key + y * tile.width, tile.depth_key + (y + 1) * tile.width,
                     out.depth_key.begin() + std::ptrdiff_t(dst), [](double k) { return float(k); });
      std::copy_n(tile.face + y * tile.width, tile.width, out.face.begin() + dst);
    }
  });
  return out;
}

}  // namespace shadowkit
