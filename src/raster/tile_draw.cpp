#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "shadowkit/raster/tile_bins.h"

namespace shadowkit::raster {
namespace {

// The largest key of triangle \p t over pixel centres [xa, xb] x [ya, yb], raised past the
// rounding of the per-pixel sums: a linear function peaks at a corner. Rounding to float
// keeps the order, so a triangle hidden in double is hidden in float.
double nearest_key(const ScreenTriangle& t, int xa, int xb, int ya, int yb) {
  const double x = t.key_a > 0 ? xb : xa, y = t.key_b > 0 ? yb : ya;
  const double a = t.key_a * x, b = t.key_b * y;
  return a + b + t.key_c + 1e-12 * (std::abs(a) + std::abs(b) + std::abs(t.key_c));
}

// A tile's sort key of triangle \p id whose nearest key is \p nearest: ascending keys go
// nearest first. The key is rounded to float, whose bits order as sign and magnitude, above
// the id. The order only decides how much the blocks' farthest keys cull; in any order the
// tile gets the same keys and faces.
std::uint64_t nearest_first(double nearest, std::uint32_t id) {
  const auto bits = std::bit_cast<std::uint32_t>(float(nearest));
  const std::uint32_t ascending = (bits & 0x80000000u) != 0 ? ~bits : bits | 0x80000000u;
  return std::uint64_t(~ascending) << 32 | id;
}

// N keys in one vector, and a comparison's result on them (all bits set: true): four for
// the span test, and a register's width (AVX2) for a block's farthest key. Spelled out for
// each: GCC drops a vector size that depends on a template parameter.
template <typename Key, int N>
struct KeyVector;
template <>
struct KeyVector<double, 4> {
  using Keys = double __attribute__((vector_size(32)));
  using Mask = std::int64_t __attribute__((vector_size(32)));
};
template <>
struct KeyVector<float, 4> {
  using Keys = float __attribute__((vector_size(16)));
  using Mask = std::int32_t __attribute__((vector_size(16)));
};
template <>
struct KeyVector<float, 8> {
  using Keys = float __attribute__((vector_size(32)));
  using Mask = std::int32_t __attribute__((vector_size(32)));
};

// draw_span's depth test with faces, four pixels at a time from column \p xa while four
// remain before \p xb; returns the first column left. Each pixel's key and face are stored
// whether taken or not: a select and a plain store. Compilers turn the test written per pixel
// into masked stores, which cost a dozen cycles each on AMD's Zen.
template <typename Key>
int draw_span_by_four(double row, double key_a, std::uint32_t id, int xa, int xb, Key* key,
                      std::uint32_t* face) {
  using Keys = typename KeyVector<Key, 4>::Keys;
  using KeyMask = typename KeyVector<Key, 4>::Mask;
  using Columns = double __attribute__((vector_size(32)));
  using Faces = std::int32_t __attribute__((vector_size(16)));
  using UnsignedFaces = std::uint32_t __attribute__((vector_size(16)));
  const UnsignedFaces ids = {id, id, id, id};
  int px = xa;
  for (; px + 3 <= xb; px += 4) {
    const Columns columns = {double(px), double(px + 1), double(px + 2), double(px + 3)};
    const Keys z = __builtin_convertvector(key_a * columns + row, Keys);
    Keys near;
    UnsignedFaces seen;
    std::memcpy(&near, key + px, sizeof near);
    std::memcpy(&seen, face + px, sizeof seen);
    const KeyMask take =
        (z > near) | ((z == near) & __builtin_convertvector(Faces(ids < seen), KeyMask));
    const KeyMask kept = (take & KeyMask(z)) | (~take & KeyMask(near));
    const Faces take_face = __builtin_convertvector(take, Faces);
    const Faces faces = (take_face & Faces(ids)) | (~take_face & Faces(seen));
    std::memcpy(key + px, &kept, sizeof kept);
    std::memcpy(face + px, &faces, sizeof faces);
  }
  return px;
}

// Pixel \p px of a triangle's row whose keys are \p key_a * x + \p row: depth-tested into
// \p key and, with faces, \p face. Between equally near triangles the lower face id wins,
// which is the first in triangle order whatever order they are drawn in.
template <bool kFaces, typename Key>
void draw_pixel(double row, double key_a, std::uint32_t id, int px, Key* key, std::uint32_t* face) {
  // Summed in double: a float key is the double one rounded, as a map stores it.
  const Key z = Key(key_a * px + row);
  if constexpr (kFaces) {
    if (z > key[px] || (z == key[px] && id < face[px])) {
      key[px] = z;
      face[px] = id;
    }
  } else {
    key[px] = z > key[px] ? z : key[px];
  }
}

// One triangle's span of row py, columns [xa, xb], pixel by pixel as draw_pixel.
template <bool kFaces, typename Key>
void draw_span(const ScreenTriangle& t, int py, int xa, int xb, Key* key, std::uint32_t* face) {
  // Locals, so the compiler need not reload them after every store to the tile.
  const double row = t.key_b * py + t.key_c, key_a = t.key_a;
  const std::uint32_t id = t.face;
  int px = xa;
  if constexpr (kFaces) px = draw_span_by_four(row, key_a, id, xa, xb, key, face);
  for (; px <= xb; ++px) draw_pixel<kFaces>(row, key_a, id, px, key, face);
}

// A triangle with few pixels in its rectangle [xa, xb] x [ya, yb]: each pixel centre tested
// against the three edge functions, stepped by addition. Setting up three EdgeWalkers (two
// divisions each) costs more when the triangle spans a pixel or two, as most of a million do.
template <bool kFaces, typename Key>
void draw_small(const ScreenTriangle& t, int xa, int xb, int ya, int yb, std::ptrdiff_t pitch,
                Key* key, std::uint32_t* face) {
  std::int64_t row[3], step_x[3], step_y[3];
  for (int i = 0; i < 3; ++i) {
    const int j = i == 2 ? 0 : i + 1;
    row[i] = edge_function(t, i, xa, ya);
    // The edge function's steps from one pixel centre to the next (edge_function).
    step_x[i] = -std::int64_t(t.y[j] - t.y[i]) * kSubpixel;
    step_y[i] = std::int64_t(t.x[j] - t.x[i]) * kSubpixel;
  }
  for (int py = ya; py <= yb; ++py) {
    const std::ptrdiff_t at = (py - ya) * pitch;
    const double key_row = t.key_b * py + t.key_c;
    std::int64_t e0 = row[0], e1 = row[1], e2 = row[2];
    for (int px = xa; px <= xb; ++px, e0 += step_x[0], e1 += step_x[1], e2 += step_x[2]) {
      // All three >= 0: no sign bit in their OR.
      if ((e0 | e1 | e2) >= 0)
        draw_pixel<kFaces>(key_row, t.key_a, t.face, px, key + at, kFaces ? face + at : face);
    }
    for (int i = 0; i < 3; ++i) row[i] += step_y[i];
  }
}

}  // namespace

template <typename Key>
void TileDepth<Key>::reset(int x0, int y0, int w, int h, Key* keys, std::uint32_t* faces) {
  x0_ = x0, y0_ = y0, w_ = w, h_ = h, key_ = keys, face_ = faces, stale_ = 0;
  std::fill_n(keys, w * h, -INFINITY);
  if (faces) std::fill_n(faces, w * h, kNoFace);
  std::fill_n(far_, kBlocks * kBlocks, -INFINITY);
}

template <typename Key>
typename TileDepth<Key>::BlockRange TileDepth<Key>::blocks(int xa, int xb, int ya, int yb) const {
  return {(xa - x0_) / kBlock, (xb - x0_) / kBlock, (ya - y0_) / kBlock, (yb - y0_) / kBlock};
}

template <typename Key>
bool TileDepth<Key>::hidden(int xa, int xb, int ya, int yb, double nearest) const {
  return hidden(blocks(xa, xb, ya, yb), nearest);
}

template <typename Key>
bool TileDepth<Key>::hidden(const BlockRange& r, double nearest) const {
  for (int by = r.by0; by <= r.by1; ++by) {
    for (int bx = r.bx0; bx <= r.bx1; ++bx) {
      if (!(nearest < far_[by * kBlocks + bx])) return false;
    }
  }
  return true;
}

// Takes the farthest key of block \p b; background counts as -inf, farther than anything.
// A register's width of a row at a time: the compilers leave a loop over its columns scalar,
// and a tile drawn over by a large face refreshes every block.
template <typename Key>
void TileDepth<Key>::refresh(int b) {
  constexpr int kLanes = 32 / sizeof(Key), kParts = kBlock / kLanes;
  using Lanes = typename KeyVector<Key, kLanes>::Keys;
  using LaneMask = typename KeyVector<Key, kLanes>::Mask;
  stale_ &= ~(std::uint64_t(1) << b);
  const int xa = b % kBlocks * kBlock, ya = b / kBlocks * kBlock;
  const int columns = std::min(w_ - xa, kBlock), yb = std::min(h_, ya + kBlock);
  const Lanes beyond = Lanes{} + Key(INFINITY);  // and columns past the tile's edge
  Lanes far[kParts];
  std::fill_n(far, kParts, beyond);
  for (int y = ya; y < yb; ++y) {
    const Key* keys = key_ + y * w_ + xa;
    for (int part = 0; part < kParts; ++part) {
      Lanes row = beyond;
      if (columns == kBlock) {
        std::memcpy(&row, keys + part * kLanes, sizeof row);
      } else {
        for (int x = part * kLanes; x < std::min(columns, (part + 1) * kLanes); ++x) {
          row[x - part * kLanes] = keys[x];
        }
      }
      const LaneMask nearer = far[part] < row;
      far[part] = Lanes((nearer & LaneMask(far[part])) | (~nearer & LaneMask(row)));
    }
  }
  Key farthest = INFINITY;
  for (const Lanes& lanes : far) {
    for (int x = 0; x < kLanes; ++x) farthest = std::min(farthest, Key(lanes[x]));
  }
  far_[b] = farthest;
}

// The blocks of \p r where triangle \p t may still show: those whose farthest key is not
// beyond the triangle's nearest key over the block. A stale block that seems to show is taken
// again first where the triangle's rectangle in it is large: drawing its pixels costs more
// than reading them. A small one (of a million, most span a pixel or two) is drawn as it is.
template <typename Key>
std::uint64_t TileDepth<Key>::showing(const ScreenTriangle& t, const BlockRange& r) {
  std::uint64_t shows = 0;
  for (int by = r.by0; by <= r.by1; ++by) {
    const int ya = std::max(int(t.min_y), y0_ + by * kBlock);
    const int yb = std::min({int(t.max_y), y0_ + by * kBlock + kBlock - 1, y0_ + h_ - 1});
    for (int bx = r.bx0; bx <= r.bx1; ++bx) {
      const int xa = std::max(int(t.min_x), x0_ + bx * kBlock);
      const int xb = std::min({int(t.max_x), x0_ + bx * kBlock + kBlock - 1, x0_ + w_ - 1});
      const double nearest = nearest_key(t, xa, xb, ya, yb);
      const int b = by * kBlocks + bx;
      if (nearest < far_[b]) continue;
      if ((stale_ >> b & 1) && (xb - xa + 1) * (yb - ya + 1) > kSmallTriangle) {
        refresh(b);
        if (nearest < far_[b]) continue;
      }
      shows |= std::uint64_t(1) << b;
    }
  }
  return shows;
}

template <typename Key>
typename TileDepth<Key>::PixelRange TileDepth<Key>::pixels_of(const ScreenTriangle& t) const {
  return {std::max(x0_, int(t.min_x)), std::min(x0_ + w_ - 1, int(t.max_x)),
          std::max(y0_, int(t.min_y)), std::min(y0_ + h_ - 1, int(t.max_y))};
}

// Large triangles first, nearest first: they hide most of what lies behind them. Small ones
// follow in bin order, their clusters' nearest first: a triangle of a few pixels hides too
// little to pay for sorting it (on terrain:500, nearly all of them, the sort took 12% of the
// scan conversion).
template <typename Key>
template <bool kFaces>
void TileDepth<Key>::draw_triangles(const ScreenTriangles& tris,
                                    std::span<const std::uint32_t> bin) {
  thread_local std::vector<std::uint64_t> large;  // nearest first
  thread_local std::vector<std::uint32_t> small;
  large.clear(), small.clear();
  for (const std::uint32_t id : bin) {
    const ScreenTriangle& t = tris[id];
    const PixelRange p = pixels_of(t);
    if (p.area() <= kSmallTriangle) {
      small.push_back(id);
    } else {
      large.push_back(nearest_first(nearest_key(t, p.xa, p.xb, p.ya, p.yb), id));
    }
  }
  std::sort(large.begin(), large.end());
  for (const std::uint64_t entry : large) draw_triangle<kFaces>(tris[std::uint32_t(entry)]);
  for (const std::uint32_t id : small) draw_triangle<kFaces>(tris[id]);
}

template <typename Key>
template <bool kFaces>
void TileDepth<Key>::draw_triangle(const ScreenTriangle& t) {
  const PixelRange p = pixels_of(t);
  const auto [xa0, xb0, ya, yb] = p;
  // Blocks where nearer surfaces hide the triangle are skipped: a large triangle partly
  // behind others draws only where it may show, and one hidden everywhere not at all.
  const std::uint64_t shows = showing(t, blocks(xa0, xb0, ya, yb));
  if (shows == 0) return;
  if (p.area() <= kSmallTriangle) {
    stale_ |= shows;
    const std::ptrdiff_t row = std::ptrdiff_t(ya - y0_) * w_ - x0_;
    draw_small<kFaces>(t, xa0, xb0, ya, yb, w_, key_ + row, kFaces ? face_ + row : nullptr);
    return;
  }
  // Row py's span [xa, xb], in the blocks that show, as runs of columns.
  const auto draw_row = [&](int py, int xa, int xb) {
    const int by = (py - y0_) / kBlock;
    const std::ptrdiff_t row = std::ptrdiff_t(py - y0_) * w_ - x0_;
    const unsigned in_span = (2u << (xb - x0_) / kBlock) - (1u << (xa - x0_) / kBlock);
    unsigned runs = unsigned(shows >> (by * kBlocks)) & in_span;
    stale_ |= std::uint64_t(runs) << (by * kBlocks);
    while (runs != 0) {
      const int first = std::countr_zero(runs);
      const int end = first + std::countr_one(runs >> first);
      runs &= ~((1u << end) - 1);
      draw_span<kFaces>(t, py, std::max(xa, x0_ + first * kBlock),
                        std::min(xb, x0_ + end * kBlock - 1), key_ + row,
                        kFaces ? face_ + row : nullptr);
    }
  };
  constexpr std::uint64_t kRowOfBlocks = (1u << kBlocks) - 1;
  const auto row_hidden = [&](int py) {
    return (shows >> ((py - y0_) / kBlock * kBlocks) & kRowOfBlocks) == 0;
  };
  if (owns_every_pixel_in(t, xa0, xb0, ya, yb)) {
    for (int py = ya; py <= yb; ++py) {
      if (!row_hidden(py)) draw_row(py, xa0, xb0);
    }
    return;
  }
  SpanWalker walker(t, ya);
  for (int py = ya; py <= yb; ++py, walker.next_row()) {
    int xa = xa0, xb = xb0;
    if (!row_hidden(py) && walker.span(xa, xb)) draw_row(py, xa, xb);
  }
}

template <typename Key>
void TileDepth<Key>::settle() {
  for (int b = 0; stale_ != 0; ++b) {
    if (stale_ >> b & 1) refresh(b);
  }
}

template <typename Key>
void TileDepth<Key>::draw(const ScreenTriangles& tris, std::span<const std::uint32_t> bin) {
  if (face_) {
    draw_triangles<true>(tris, bin);
  } else {
    draw_triangles<false>(tris, bin);
  }
}

template class TileDepth<double>;
template class TileDepth<float>;

}  // namespace shadowkit::raster
