#pragma once
// The scene's triangle clusters as one view sees them: which can draw where, and how near.
#include <cstdint>
#include <vector>

#include "shadowkit/raster/projection.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::raster {

/// \brief A cluster (TriangleClusters) that can draw pixels of a view.
struct ClusterInView {
  std::uint32_t cluster;
  /// At least the depth key of any pixel its triangles draw; +inf when its bounds reach
  /// in front of the near plane, where they cannot be projected.
  double nearest;
  int x0, y0, x1, y1;  ///< the pixels its triangles can draw, inclusive, on the raster
};

/// The clusters of \p scene whose bounds reach \p view's raster, nearest first: the order to
/// draw them in for nearer ones to hide farther ones.
std::vector<ClusterInView> clusters_in_view(const Scene& scene, const RasterProjection& view);

}  // namespace shadowkit::raster
