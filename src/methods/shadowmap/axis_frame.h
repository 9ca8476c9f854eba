#pragma once
// The frame of a cube face's view, whose axes are signed world axes.
#include <array>

#include "shadowkit/core/vec.h"
#include "shadowkit/raster/projection.h"

namespace shadowkit::shadowmap {

/// \brief The frame of a view whose right, up and forward vectors are signed world axes, as a
/// cube face's are. A point's view coordinates are then signed components of p - eye: what
/// RasterProjection::to_view computes, without its products (but for the sign of a zero,
/// which no projection or depth comparison sees).
class AxisFrame {
 public:
  AxisFrame() = default;
  explicit AxisFrame(const RasterProjection& view);
  /// The view coordinates of the point eye + \p d.
  Vec3 to_view(Vec3 d) const {
    return {sign_[0] * d[index_[0]], sign_[1] * d[index_[1]], sign_[2] * d[index_[2]]};
  }

 private:
  std::array<int, 3> index_{};
  std::array<double, 3> sign_{};
};

}  // namespace shadowkit::shadowmap
