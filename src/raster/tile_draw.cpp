#include <algorithm>
#include <cmath>
#include <vector>

#include "shadowkit/raster/tile_bins.h"

namespace shadowkit::raster {
namespace {

constexpr int kTile = TileBins::kTile;

// One level of hierarchical depth (Greene, Kass & Miller 1993) over blocks of a tile: each block's
// farthest key so far. Triangles go nearest first, so that most of those hidden behind the nearer
// ones meet full blocks and are dropped whole: a cube field seen at a low angle stacks
// dozens of triangles on a pixel.
constexpr int kBlock = 8, kBlocks = kTile / kBlock;
static_assert(kBlocks * kBlocks <= 64, "a bit per block");

// A tile's keys, w x h in rows of w, with their blocks' farthest keys.
struct DepthBlocks {
  double* key = nullptr;
  int w = 0, h = 0;
  double far[kBlocks * kBlocks];
  std::uint64_t stale = 0;  ///< blocks drawn into since their farthest key was taken

  // The farthest key of block b; background counts as -inf, farther than anything.
  double far_key(int b) const {
    const int bx = (b % kBlocks) * kBlock, by = (b / kBlocks) * kBlock;
    double out = INFINITY;
    for (int y = by; y < std::min(h, by + kBlock); ++y) {
      for (int x = bx; x < std::min(w, bx + kBlock); ++x) out = std::min(out, key[y * w + x]);
    }
    return out;
  }
};

// The pixels [xa, xb] x [ya, yb] of a tile at (x0, y0) as a rectangle of blocks.
struct BlockRange {
  int bx0, bx1, by0, by1;
  BlockRange(int xa, int xb, int ya, int yb, int x0, int y0)
      : bx0((xa - x0) / kBlock),
        bx1((xb - x0) / kBlock),
        by0((ya - y0) / kBlock),
        by1((yb - y0) / kBlock) {}
};

// Whether every block of \p r has its farthest key beyond \p nearest: nothing with keys at
// most \p nearest can show there.
bool hidden(DepthBlocks& d, const BlockRange& r, double nearest) {
  for (int by = r.by0; by <= r.by1; ++by) {
    for (int bx = r.bx0; bx <= r.bx1; ++bx) {
      const int b = by * kBlocks + bx;
      if (d.stale >> b & 1) {
        d.far[b] = d.far_key(b);
        d.stale &= ~(std::uint64_t(1) << b);
      }
      if (!(nearest < d.far[b])) return false;
    }
  }
  return true;
}

void mark_stale(DepthBlocks& d, const BlockRange& r) {
  for (int by = r.by0; by <= r.by1; ++by) {
    for (int bx = r.bx0; bx <= r.bx1; ++bx) d.stale |= std::uint64_t(1) << (by * kBlocks + bx);
  }
}

// The largest key of triangle \p t over pixel centres [xa, xb] x [ya, yb], raised past the
// rounding of the per-pixel sums: a linear function peaks at a corner.
double nearest_key(const ScreenTriangle& t, int xa, int xb, int ya, int yb) {
  const double x = t.key_a > 0 ? xb : xa, y = t.key_b > 0 ? yb : ya;
  const double a = t.key_a * x, b = t.key_b * y;
  return a + b + t.key_c + 1e-12 * (std::abs(a) + std::abs(b) + std::abs(t.key_c));
}

// One triangle's span of row py, columns [xa, xb]: depth-tested into \p key and, with faces,
// \p face. Between equally near triangles the lower face id wins, which is the first in
// triangle order whatever order they are drawn in.
template <bool kFaces>
void draw_span(const ScreenTriangle& t, int py, int xa, int xb, double* key, std::uint32_t* face) {
  // Locals, so the compiler need not reload them after every store to the tile.
  const double row = t.key_b * py + t.key_c, key_a = t.key_a;
  const std::uint32_t id = t.face;
  for (int px = xa; px <= xb; ++px) {
    const double z = key_a * px + row;
    if constexpr (kFaces) {
      if (z > key[px] || (z == key[px] && id < face[px])) {
        key[px] = z;
        face[px] = id;
      }
    } else {
      key[px] = z > key[px] ? z : key[px];
    }
  }
}

template <bool kFaces>
void draw(const ScreenTriangles& tris, std::span<const std::uint32_t> bin, int x0, int y0, int w,
          int h, double* keys, std::uint32_t* faces) {
  thread_local DepthBlocks d;
  thread_local std::vector<std::pair<double, std::uint32_t>> order;  // nearest first
  d.key = keys, d.w = w, d.h = h, d.stale = 0;
  std::fill_n(keys, w * h, -INFINITY);
  if constexpr (kFaces) std::fill_n(faces, w * h, kNoFace);
  std::fill_n(d.far, kBlocks * kBlocks, -INFINITY);
  order.clear();
  for (const std::uint32_t id : bin) {
    const ScreenTriangle& t = tris[id];
    order.emplace_back(nearest_key(t, std::max(x0, t.min_x), std::min(x0 + w - 1, t.max_x),
                                   std::max(y0, t.min_y), std::min(y0 + h - 1, t.max_y)),
                       id);
  }
  std::sort(order.begin(), order.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [unused, id] : order) {
    const ScreenTriangle& t = tris[id];
    const int ya = std::max(y0, t.min_y), yb = std::min(y0 + h - 1, t.max_y);
    const int xa0 = std::max(x0, t.min_x), xb0 = std::min(x0 + w - 1, t.max_x);
    const BlockRange blocks(xa0, xb0, ya, yb, x0, y0);
    if (hidden(d, blocks, nearest_key(t, xa0, xb0, ya, yb))) continue;
    mark_stale(d, blocks);
    SpanWalker walker(t, ya);
    for (int py = ya; py <= yb; ++py, walker.next_row()) {
      int xa = xa0, xb = xb0;
      if (!walker.span(xa, xb)) continue;
      const std::ptrdiff_t row = std::ptrdiff_t(py - y0) * w - x0;
      draw_span<kFaces>(t, py, xa, xb, keys + row, kFaces ? faces + row : nullptr);
    }
  }
}

}  // namespace

void draw_tile(const ScreenTriangles& tris, std::span<const std::uint32_t> bin, int x0, int y0,
               int w, int h, double* keys, std::uint32_t* faces) {
  if (faces) {
    draw<true>(tris, bin, x0, y0, w, h, keys, faces);
  } else {
    draw<false>(tris, bin, x0, y0, w, h, keys, nullptr);
  }
}

}  // namespace shadowkit::raster
