#include "shadowkit/raster/scan_converter.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "shadowkit/core/error.h"
#include "shadowkit/raster/tile_bins.h"
#include "shadowkit/raster/triangle_setup.h"

namespace shadowkit {
namespace {

using raster::kSubpixel;
using raster::ScreenTriangle;
using raster::TileBins;
constexpr int kTile = ScanConverter::kTileSize;

// One level of hierarchical depth (Greene, Kass & Miller 1993) over blocks of a tile: each
// block's farthest key so far. Triangles go nearest first, so that most of those hidden
// behind the nearer ones meet full blocks and are dropped whole: a cube field seen
// at a low angle stacks dozens of triangles on a pixel.
constexpr int kBlock = 8, kBlocks = kTile / kBlock;
static_assert(kBlocks * kBlocks <= 64, "a bit per block");

struct TileBuffers {
  double key[kTile * kTile];
  std::uint32_t face[kTile * kTile];
  double block_far[kBlocks * kBlocks];
  std::uint64_t stale = 0;  ///< blocks drawn into since their farthest key was taken
  std::vector<std::pair<double, std::uint32_t>> order;  ///< (nearest key, triangle), nearest first
};

// The pixels [xa, xb] x [ya, yb] of a tile of width w at (x0, y0) as a rectangle of blocks.
struct BlockRange {
  int bx0, bx1, by0, by1;
  BlockRange(int xa, int xb, int ya, int yb, int x0, int y0)
      : bx0((xa - x0) / kBlock),
        bx1((xb - x0) / kBlock),
        by0((ya - y0) / kBlock),
        by1((yb - y0) / kBlock) {}
};

// The farthest key of block b; background counts as -inf, farther than anything.
double block_far_key(const TileBuffers& buf, int b, int w, int h) {
  const int bx = (b % kBlocks) * kBlock, by = (b / kBlocks) * kBlock;
  double far = INFINITY;
  for (int y = by; y < std::min(h, by + kBlock); ++y) {
    for (int x = bx; x < std::min(w, bx + kBlock); ++x) far = std::min(far, buf.key[y * w + x]);
  }
  return far;
}

// Whether every block of \p r has its farthest key beyond \p nearest: nothing with keys at
// most \p nearest can show there.
bool hidden(TileBuffers& buf, const BlockRange& r, double nearest, int w, int h) {
  for (int by = r.by0; by <= r.by1; ++by) {
    for (int bx = r.bx0; bx <= r.bx1; ++bx) {
      const int b = by * kBlocks + bx;
      if (buf.stale >> b & 1) {
        buf.block_far[b] = block_far_key(buf, b, w, h);
        buf.stale &= ~(std::uint64_t(1) << b);
      }
      if (!(nearest < buf.block_far[b])) return false;
    }
  }
  return true;
}

void mark_stale(TileBuffers& buf, const BlockRange& r) {
  for (int by = r.by0; by <= r.by1; ++by) {
    for (int bx = r.bx0; bx <= r.bx1; ++bx) buf.stale |= std::uint64_t(1) << (by * kBlocks + bx);
  }
}

// The largest key of triangle \p t over pixel centres [xa, xb] x [ya, yb], raised past the
// rounding of the per-pixel sums: a linear function peaks at a corner.
double nearest_key(const ScreenTriangle& t, int xa, int xb, int ya, int yb) {
  const double x = t.key_a > 0 ? xb : xa, y = t.key_b > 0 ? yb : ya;
  const double a = t.key_a * x, b = t.key_b * y;
  return a + b + t.key_c + 1e-12 * (std::abs(a) + std::abs(b) + std::abs(t.key_c));
}

// Depth-tests the triangles \p bin over one tile. The winner of a pixel is the nearest
// triangle and, between equally near ones, the lowest face id: the first in triangle order,
// whatever order they are drawn in.
void raster_tile(const raster::ScreenTriangles& tris, const std::uint32_t* bin,
                 std::size_t bin_size, int x0, int y0, int w, int h, TileBuffers& buf) {
  std::fill_n(buf.key, w * h, -INFINITY);
  std::fill_n(buf.face, w * h, kNoFace);
  std::fill_n(buf.block_far, kBlocks * kBlocks, -INFINITY);
  buf.stale = 0;
  buf.order.clear();
  for (std::size_t k = 0; k < bin_size; ++k) {
    const ScreenTriangle& t = tris[bin[k]];
    buf.order.emplace_back(nearest_key(t, std::max(x0, t.min_x), std::min(x0 + w - 1, t.max_x),
                                       std::max(y0, t.min_y), std::min(y0 + h - 1, t.max_y)),
                           bin[k]);
  }
  std::sort(buf.order.begin(), buf.order.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [unused, index] : buf.order) {
    const ScreenTriangle& t = tris[index];
    const int ya = std::max(y0, t.min_y), yb = std::min(y0 + h - 1, t.max_y);
    const int xa0 = std::max(x0, t.min_x), xb0 = std::min(x0 + w - 1, t.max_x);
    const BlockRange blocks(xa0, xb0, ya, yb, x0, y0);
    if (hidden(buf, blocks, nearest_key(t, xa0, xb0, ya, yb), w, h)) continue;
    mark_stale(buf, blocks);
    raster::SpanWalker walker(t, ya);
    for (int py = ya; py <= yb; ++py, walker.next_row()) {
      int xa = xa0, xb = xb0;
      if (!walker.span(xa, xb)) continue;
      double* key = buf.key + (py - y0) * w - x0;
      std::uint32_t* face = buf.face + (py - y0) * w - x0;
      // Locals, so the compiler need not reload them after every store to the tile.
      const double row = t.key_b * py + t.key_c, key_a = t.key_a;
      const std::uint32_t id = t.face;
      for (int px = xa; px <= xb; ++px) {
        const double z = key_a * px + row;
        if (z > key[px] || (z == key[px] && id < face[px])) {
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
  const raster::ScreenTriangles tris = raster::setup_triangles(scene_, view);
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
                     out.depth_key.begin() + std::ptrdiff_t(dst),
                     [](double k) { return float(k); });
      std::copy_n(tile.face + y * tile.width, tile.width, out.face.begin() + dst);
    }
  });
  return out;
}

}  // namespace shadowkit
