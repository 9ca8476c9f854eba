#pragma once
// Convex shadow volumes counted whole (Crow 1977, Sec. VII): where the eye lies outside a
// convex volume, the count of its polygons crossed before a visible point is 1 inside it and
// 0 outside, so a test against its planes takes the place of scan-converting its polygons.
#include <array>
#include <cstdint>
#include <vector>

#include "counting_tile.h"
#include "shadow_polygon.h"
#include "volume_culling.h"

namespace shadowkit {

/// \brief The shadow volume of a closed convex sub-object: the points on the volume's side
/// of every plane of its light-facing faces and contour edges' shadow polygons.
struct ConvexVolume {
  std::uint32_t sub_object = 0;
  int plane_count = 0;
  std::array<Plane, ShadowFrustum::kMaxPlanes> planes{};  ///< the eye on the negative side
  std::array<KeyPlane, ShadowFrustum::kMaxPlanes> keys{};
  std::uint32_t inside_beyond = 0;  ///< bit i: the volume lies beyond plane i

  /// Adds 1 to the count of every pixel of cell (\p band, \p c) whose visible point lies in
  /// the volume, testing pixels only within columns [xa, xb] and rows [ya, yb] (where its
  /// polygons reach) unless the depth keys settle the whole cell. The cell must not show the
  /// sub-object's own faces, whose points lie on the volume's boundary. Returns the pixels
  /// tested one by one.
  std::size_t count_cell(const VisibleFrame& frame, int band, int c, int xa, int xb, int ya, int yb,
                         CountingTile& t) const;
};

/// \brief The ConvexVolume of every sub-object whose volume is counted whole: its frustum is
/// exact (ShadowFrustum::make_exact), its polygons are depth-pass, and its volume misses the
/// eye (\p cullable), so the eye's count holds nothing of it.
class ConvexVolumes {
 public:
  ConvexVolumes(const std::vector<ShadowPolygon>& polygons,
                const std::vector<ShadowFrustum>& frusta, const std::vector<char>& cullable,
                const RayGrid& rays);
  /// Sub-object \p k's volume, or null where its polygons are counted one by one.
  const ConvexVolume* of(std::uint32_t k) const {
    return index_[k] < 0 ? nullptr : &volumes_[std::size_t(index_[k])];
  }
  std::size_t size() const { return volumes_.size(); }

 private:
  std::vector<std::int32_t> index_;
  std::vector<ConvexVolume> volumes_;
};

}  // namespace shadowkit
