#include "axis_frame.h"

namespace shadowkit::shadowmap {

AxisFrame::AxisFrame(const RasterProjection& view) {
  const Vec3 axes[3] = {view.right, view.up, view.forward};
  for (int k = 0; k < 3; ++k) {
    index_[k] = axes[k].x != 0 ? 0 : (axes[k].y != 0 ? 1 : 2);
    sign_[k] = axes[k][index_[k]];
  }
}

}  // namespace shadowkit::shadowmap
