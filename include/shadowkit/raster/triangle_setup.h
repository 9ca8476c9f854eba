#pragma once
// Triangle setup for the scan converter: clipping in view space and fixed-point edges.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "shadowkit/raster/projection.h"
#include "shadowkit/scene/limits.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::raster {

/// Sub-pixel precision: 1/256 pixel. Pixel centres sit at 256 x + 128.
inline constexpr int kSubpixelBits = 8;
inline constexpr std::int64_t kSubpixel = 1 << kSubpixelBits;
/// Triangles are clipped to the raster plus this margin in pixels, which keeps fixed-point
/// edge functions well inside 64 bits.
inline constexpr double kGuardBand = 4096;

/// std::llround(\p x), halves away from zero, for |x| < 2^52, inline where the library's is a
/// call per coordinate: the sum rounds across an integer only where x + 1/2 reaches it
/// (0.5 - 2^-54 is the double just below a half).
inline std::int64_t round_to_integer(double x) {
  return std::int64_t(std::trunc(x + std::copysign(0.49999999999999994, x)));
}

/// \brief A triangle ready for scan conversion: positively oriented fixed-point vertices (in
/// pixel coordinates, y down; clockwise as seen on screen) with
/// the top-left rule folded into the edge biases, and the depth-key plane of its face.
/// One cache line: a frame sets up and bins hundreds of thousands, and reads each several
/// times. Fixed-point corners fit 32 bits within the guard band; edge functions take them to
/// 64. Pixel bounds fit 16 bits on the largest raster.
struct alignas(64) ScreenTriangle {
  // Corners within the guard band of the largest raster, a camera's image or a depth map.
  static_assert((limits::kImageSide + 2 * kGuardBand) * kSubpixel < 2147483647.0);
  static_assert(limits::kImageSide <= 32767);
  double key_a, key_b, key_c;  ///< depth key = a * px + b * py + c at pixel centre (px, py)
  std::int32_t x[3], y[3];     ///< fixed point
  std::int16_t min_x, min_y, max_x, max_y;  ///< pixel bounds, clamped to the raster
  std::uint32_t face;
  std::int8_t bias[3];  ///< 0 if the edge owns pixel centres on it, 1 otherwise
};
static_assert(sizeof(ScreenTriangle) == 64);

/// Edge \p i's function at the centre of pixel (\p px, \p py): the triangle owns the pixel
/// where all three are >= 0 (EdgeWalker follows where they change sign).
inline std::int64_t edge_function(const ScreenTriangle& t, int i, std::int64_t px,
                                  std::int64_t py) {
  const int j = i == 2 ? 0 : i + 1;
  const std::int64_t xi = t.x[i], yi = t.y[i];
  return (t.x[j] - xi) * (py * kSubpixel + kSubpixel / 2 - yi) -
         (t.y[j] - yi) * (px * kSubpixel + kSubpixel / 2 - xi) - t.bias[i];
}

/// Whether triangle \p t may own a pixel centre in columns [xa, xb] and rows [ya, yb]: false
/// only when one edge has the whole rectangle outside it (its edge function peaks at a
/// corner). A triangle's bounds hold many tiles that a thin slanted triangle never reaches.
bool may_own_pixel_in(const ScreenTriangle& t, int xa, int xb, int ya, int yb);

/// Whether triangle \p t owns every pixel centre in columns [xa, xb] and rows [ya, yb]: each
/// edge function is >= 0 at the rectangle's corner where it is least. A large face owns the
/// whole of most tiles it reaches, row after row, without walking its edges.
bool owns_every_pixel_in(const ScreenTriangle& t, int xa, int xb, int ya, int yb);

/// \brief Screen triangles in chunks, as they were set up in parallel, never copied into one
/// array: at 360k triangles that copy and the page faults of its fresh storage cost more
/// than the set-up. An id holds the chunk and the place in it; ids follow triangle order.
class ScreenTriangles {
 public:
  static constexpr int kPlaceBits = 12;
  static constexpr std::size_t kChunkSize = std::size_t(1) << kPlaceBits;

  const ScreenTriangle& operator[](std::uint32_t id) const {
    return chunks_[id >> kPlaceBits][id & (kChunkSize - 1)];
  }
  /// Calls fn(id, triangle) for every triangle, in id order.
  template <class Fn>
  void for_each(Fn&& fn) const {
    for (std::uint32_t c = 0; c < chunks_.size(); ++c) for_each_in_chunk(c, fn);
  }
  /// Calls fn(id, triangle) for the triangles of chunk \p c, in id order.
  template <class Fn>
  void for_each_in_chunk(std::uint32_t c, Fn&& fn) const {
    for (std::uint32_t i = 0; i < chunks_[c].size(); ++i) fn(c << kPlaceBits | i, chunks_[c][i]);
  }
  std::uint32_t chunk_count() const { return std::uint32_t(chunks_.size()); }

 private:
  friend ScreenTriangles setup_triangles(const Scene& scene, const RasterProjection& view,
                                         const std::function<bool(std::uint32_t)>& keep);
  friend ScreenTriangles setup_cluster_triangles(const Scene& scene, const RasterProjection& view,
                                                 std::span<const std::uint32_t> entries);
  std::vector<std::vector<ScreenTriangle>> chunks_;
};

/// Clips and sets up every triangle of \p scene for \p view, in triangle order (so that the
/// tie rule "lower triangle index wins" survives binning). Runs in parallel.
ScreenTriangles setup_triangles(const Scene& scene, const RasterProjection& view);
/// As above, for the triangles t (indices into the scene's TriangleList) with keep(t) only;
/// only their vertices are transformed. A cube face of a shadow map takes the sixth of the
/// scene that can reach it.
ScreenTriangles setup_triangles(const Scene& scene, const RasterProjection& view,
                                const std::function<bool(std::uint32_t)>& keep);
/// As above, for the triangles at \p entries of the scene's TriangleClusters, in that order:
/// ids follow \p entries. Each triangle transforms its own corners, which costs less than a
/// pass over every vertex when the triangles are few of the scene's.
ScreenTriangles setup_cluster_triangles(const Scene& scene, const RasterProjection& view,
                                        std::span<const std::uint32_t> entries);

/// \brief A point in fixed-point pixel coordinates (1/kSubpixel pixel, y down).
struct FixedPoint {
  std::int64_t x, y;
};

/// \brief A world-space point in homogeneous coordinates: w = 1 for a point, w = 0 for a
/// direction, the point at infinity where parallel lines meet (shadow polygons reach there).
struct HomogeneousPoint {
  Vec3 xyz;
  double w = 1;
};

/// Clips the convex polygon \p corners (world space, homogeneous) against the near plane and
/// the guard band of the perspective \p view, fans it into triangles and appends them to
/// \p out with face = \p id and a zero depth plane: for polygons that are not scene faces
/// (shadow polygons). Equal corners of two polygons clip and snap bit-identically, so the
/// fill rule counts a pixel centre on their shared edge once.
void setup_polygon(std::span<const HomogeneousPoint> corners, std::uint32_t id,
                   const RasterProjection& view, std::vector<ScreenTriangle>& out);

/// The corners that setup_polygon fans into triangles: \p corners clipped against the near
/// plane and the guard band of the perspective \p view and snapped to fixed point, in order,
/// into \p fixed.
void snapped_polygon(std::span<const HomogeneousPoint> corners, const RasterProjection& view,
                     std::vector<FixedPoint>& fixed);

/// \brief One edge's boundary column, row after row, in exact integer arithmetic.
class EdgeWalker {
 public:
  EdgeWalker() = default;
  EdgeWalker(const ScreenTriangle& t, int edge, int first_row);
  /// The edge from \p from to \p to of a positively oriented polygon, with its fill-rule
  /// \p bias (as ScreenTriangle::bias).
  EdgeWalker(FixedPoint from, FixedPoint to, std::int64_t bias, int first_row);
  /// Narrows [lo, hi] to the columns on the inner side of the edge in the current row.
  void clip(std::int64_t& lo, std::int64_t& hi) const {
    if (a_ == 0) {
      if (c_ < 0) lo = hi + 1;  // the whole row is outside this edge
    } else if (a_ > 0) {
      lo = std::max(lo, q_ + (r_ > 0));  // first column with E >= 0: ceil(-c / a)
    } else {
      hi = std::min(hi, q_);  // last column with E >= 0: floor(c / -a)
    }
  }
  void next_row() {
    if (a_ == 0) {
      c_ += step_c_;
      return;
    }
    // Without a branch: whether the remainder carries is as good as random from row to row.
    const std::int64_t r = r_ + step_r_;
    const std::int64_t carry = r >= abs_a_;
    r_ = r - (abs_a_ & -carry);
    q_ += step_q_ + carry;
  }

 private:
  static void split(std::int64_t num, std::int64_t den, std::int64_t& q, std::int64_t& r);
  // Left uninitialized by the default constructor, so that arrays of walkers cost nothing
  // until an edge is set up in them; the other constructors set every field.
  std::int64_t a_, abs_a_;   // change of the edge function per column
  std::int64_t c_, step_c_;  // horizontal edges: the edge function and its row step
  std::int64_t q_, r_;       // boundary as quotient and remainder
  std::int64_t step_q_, step_r_;
};

/// \brief The pixel columns a triangle owns under the fill rule, row by row from
/// \p first_row: the scan converter's inner loop, without a division per row.
class SpanWalker {
 public:
  SpanWalker(const ScreenTriangle& t, int first_row);
  /// Narrows [x_lo, x_hi] to the current row's owned columns; false if none.
  bool span(int& x_lo, int& x_hi) const {
    std::int64_t lo = x_lo, hi = x_hi;
    for (const EdgeWalker& e : edges_) e.clip(lo, hi);
    x_lo = int(lo);
    x_hi = int(hi);
    return lo <= hi;
  }
  void next_row() {
    for (EdgeWalker& e : edges_) e.next_row();
  }

 private:
  EdgeWalker edges_[3];
};

}  // namespace shadowkit::raster
