#pragma once
// Convex shadow volumes counted whole (Crow 1977, Sec. VII): where the eye lies outside a
// convex volume, the count of its polygons crossed before a visible point is 1 inside it and
// 0 outside, so a test against its planes takes the place of scan-converting its polygons.
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "counting_tile.h"
#include "shadow_polygon.h"
#include "shadowkit/raster/screen_polygon.h"
#include "volume_culling.h"

namespace shadowkit::volume {

/// \brief The shadow volume of a closed convex sub-object: the points on the volume's side
/// of every plane of its light-facing faces and contour edges' shadow polygons.
struct ConvexVolume {
  std::uint32_t sub_object = 0;
  int plane_count = 0;
  std::array<Plane, ShadowFrustum::kMaxPlanes> planes{};  ///< the eye on the negative side
  std::array<KeyPlane, ShadowFrustum::kMaxPlanes> keys{};
  std::uint32_t inside_beyond = 0;  ///< bit i: the volume lies beyond plane i

  /// Adds 1 to the count of every pixel of cell (\p band, \p c), not settled yet
  /// (CountingTile::settled), whose visible point lies in the volume, and settles it; a cell
  /// left with every pixel settled is shadowed (CountingTile::shadowed). Tests pixels only within
  /// columns [xa, xb] and rows [ya, yb] (where its outline reaches) unless the depth keys settle
  /// the whole cell. The sub-object's own faces need no exception: a point on a face turned
  /// to the light lies in one of the planes, and beyond_plane puts it outside; one turned away
  /// is settled in shadow (contract condition 1) before any volume. Returns the pixels tested
  /// one by one.
  std::size_t count_cell(const VisibleFrame& frame, int band, int c, int xa, int xb, int ya, int yb,
                         CountingTile& t) const;

 private:
  /// Two pixels' depth keys, and their comparisons (all bits set: true).
  using Lanes = double __attribute__((vector_size(16)));
  using LaneMask = std::int64_t __attribute__((vector_size(16)));
  static constexpr int kLaneVectors = 4;
  /// Bit j: lane j of \p m (kLaneVectors vectors) is true.
  static unsigned lane_bits(const LaneMask* m);
  /// Adds 1 to the count of every pixel of tile row \p row in cell column \p c, among the
  /// \p pending ones (bit j: the cell's column j), whose visible point lies in the volume,
  /// testing the planes \p mixed there, and settles them (CountingTile::settled).
  std::size_t count_run(const VisibleFrame& frame, int row, int c, unsigned pending,
                        std::uint32_t mixed, CountingTile& t) const;
};

/// \brief One edge of a volume's outline on screen, in pixel units (column x's centre at x),
/// from its upper end (y0) down to its lower end (y1).
struct OutlineEdge {
  double x0, y0, x1, y1, slope;  ///< slope: dx / dy (0 for a horizontal edge)
};

/// Narrows columns [xa, xb] to those whose pixel centres, widened by a pixel, the convex
/// \p outline can hold on rows [ya, yb]; false when none.
bool outline_columns(std::span<const OutlineEdge> outline, int ya, int yb, int& xa, int& xb);

/// \brief The ConvexVolume of every sub-object whose volume is counted whole: its frustum is
/// exact (ShadowFrustum::make_exact), its polygons are depth-pass, and its volume misses the
/// eye (\p cullable), so the eye's count holds nothing of it.
class ConvexVolumes {
 public:
  ConvexVolumes(const std::vector<ShadowPolygon>& polygons, const ShadowFrusta& frusta,
                const std::vector<char>& cullable, const RayGrid& rays,
                std::span<const raster::ScreenPolygon> screen);
  /// Sub-object \p k's volume, or null where its polygons are counted one by one.
  const ConvexVolume* of(std::uint32_t k) const {
    return index_[k] < 0 ? nullptr : &volumes_[std::size_t(index_[k])];
  }
  std::size_t size() const { return volumes_.size(); }
  /// The convex hull on screen of sub-object \p k's shadow polygons (their scan-converted
  /// corners): a visible point in its volume, in a pixel that does not show the sub-object,
  /// lies behind a crossing with one of its polygons, so its pixel centre lies within the
  /// hull up to the corners' snapping.
  std::span<const OutlineEdge> outline(std::uint32_t k) const {
    const std::size_t v = std::size_t(index_[k]);
    return {outline_.data() + outline_start_[v], outline_start_[v + 1] - outline_start_[v]};
  }
  /// The same hull as one ScreenPolygon, to bin the volume by (its face: the index of one of
  /// the sub-object's polygons; no fill-rule bias), or none (count 0) where it has more
  /// corners than a ScreenPolygon holds.
  const raster::ScreenPolygon& hull(std::uint32_t k) const {
    return hulls_[std::size_t(index_[k])];
  }
  /// Sub-object \p k's volume is binned by its hull, one item for all its polygons.
  bool binned_by_hull(std::uint32_t k) const { return of(k) && hull(k).count > 0; }
  /// Sub-object \p k's screen polygons: [first, last) in the list the volumes were made from.
  std::pair<std::uint32_t, std::uint32_t> screen_polygons(std::uint32_t k) const {
    return polygons_of_[std::size_t(index_[k])];
  }

 private:
  /// Volume \p v's hull on screen (hulls_[v]) from its polygons' corners, gathered in
  /// \p corners, where its hull's corners are left; returns their count.
  std::size_t hull_of(std::size_t v, std::span<const raster::ScreenPolygon> screen,
                      std::span<raster::FixedPoint> corners, std::vector<raster::FixedPoint>& hull);

  std::vector<std::int32_t> index_;
  std::vector<ConvexVolume> volumes_;
  std::vector<std::size_t> outline_start_;
  std::vector<OutlineEdge> outline_;
  std::vector<raster::ScreenPolygon> hulls_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> polygons_of_;
};

}  // namespace shadowkit::volume
