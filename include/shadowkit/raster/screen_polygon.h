#pragma once
// Convex polygons scan-converted whole, with the same fill rule as their fans of triangles.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "shadowkit/raster/triangle_setup.h"

namespace shadowkit::raster {

/// Corners a ScreenPolygon can hold: a quadrilateral clipped by the six faces of a box and
/// the five planes of setup_polygon's clipping, or anything smaller.
inline constexpr int kMaxPolygonCorners = 16;

/// \brief A convex polygon ready for scan conversion: positively oriented fixed-point corners
/// (clockwise as seen on screen, y down) and, per edge (corner i to corner i + 1), the
/// fill-rule bias of ScreenTriangle. It owns exactly the pixel centres that setup_polygon's
/// fan of triangles owns: the top-left rule decides a centre on an edge as if it were moved
/// by a fixed infinitesimal step, which makes coverage independent of how a polygon is cut
/// into triangles.
struct ScreenPolygon {
  std::array<FixedPoint, kMaxPolygonCorners> corners;
  std::uint16_t bias_bits = 0;  ///< bit i: the bias of the edge from corner i to the next
  int count = 0;
  int min_x, min_y, max_x, max_y;  ///< pixel bounds, clamped to the raster
  std::uint32_t face;              ///< the caller's id, as ScreenTriangle::face

  /// The bias of the edge from corner \p i to the next, as ScreenTriangle::bias.
  std::int64_t bias(int i) const { return (bias_bits >> i) & 1; }
};
static_assert(kMaxPolygonCorners <= 16, "ScreenPolygon::bias_bits holds a bit per edge");

/// Clips and snaps \p corners as setup_polygon does and appends them to \p out as one
/// ScreenPolygon; or, where snapping has left them not convex, as the triangles that
/// setup_polygon draws, three corners each. Either way \p out gains exactly the pixel
/// centres that setup_polygon's triangles own.
void setup_convex_polygon(std::span<const HomogeneousPoint> corners, std::uint32_t id,
                          const RasterProjection& view, std::vector<ScreenPolygon>& out);

/// \brief The pixel columns a ScreenPolygon owns, row by row over rows
/// [first_row, last_row]: as SpanWalker, with only the edges that reach those rows (on a
/// convex polygon the others bound nothing there).
class PolygonSpanWalker {
 public:
  PolygonSpanWalker(const ScreenPolygon& p, int first_row, int last_row);
  /// Narrows [x_lo, x_hi] to the current row's owned columns; false if none.
  bool span(int& x_lo, int& x_hi) const {
    if (empty_) return false;
    std::int64_t lo = x_lo, hi = x_hi;
    for (int i = 0; i < count_; ++i) edges_[i].clip(lo, hi);
    x_lo = int(lo);
    x_hi = int(hi);
    return lo <= hi;
  }
  void next_row() {
    for (int i = 0; i < count_; ++i) edges_[i].next_row();
  }

 private:
  std::array<EdgeWalker, kMaxPolygonCorners> edges_;
  int count_ = 0;
  bool empty_ = false;
};

}  // namespace shadowkit::raster
