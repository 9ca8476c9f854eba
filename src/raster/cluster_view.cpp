#include "shadowkit/raster/cluster_view.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace shadowkit::raster {
namespace {

// Where the box's triangles can draw: its corners' projections bound the projection of all
// of it when it lies wholly past the near plane. A pixel is drawn where its centre lies in a
// triangle whose corners are snapped to 1/256 pixel; the margin of one pixel covers that.
std::optional<ClusterInView> in_view(const Bounds3& box, const RasterProjection& view) {
  const int last_x = view.width - 1, last_y = view.height - 1;
  ClusterInView c{0, -INFINITY, 0, 0, last_x, last_y};
  double min_x = INFINITY, max_x = -INFINITY, min_y = INFINITY, max_y = -INFINITY;
  for (int k = 0; k < 8; ++k) {
    const Vec3 v = view.to_view(box.corner(k));
    if (!(v.z > view.near)) {
      c.nearest = INFINITY;
      return c;
    }
    c.nearest = std::max(c.nearest, view.depth_key(v.z));
    min_x = std::min(min_x, view.pixel_x(v)), max_x = std::max(max_x, view.pixel_x(v));
    min_y = std::min(min_y, view.pixel_y(v)), max_y = std::max(max_y, view.pixel_y(v));
  }
  // The depth key of a face at a pixel is evaluated from its plane, in rounded arithmetic.
  c.nearest += 1e-9 * std::abs(c.nearest);
  const auto first = [](double p) { return std::floor(p - 0.5) - 1; };
  const auto last = [](double p) { return std::ceil(p - 0.5) + 1; };
  if (first(min_x) > last_x || last(max_x) < 0 || first(min_y) > last_y || last(max_y) < 0) {
    return std::nullopt;
  }
  c.x0 = int(std::max(0.0, first(min_x)));
  c.x1 = int(std::min(double(last_x), last(max_x)));
  c.y0 = int(std::max(0.0, first(min_y)));
  c.y1 = int(std::min(double(last_y), last(max_y)));
  return c;
}

}  // namespace

std::vector<ClusterInView> clusters_in_view(const Scene& scene, const RasterProjection& view) {
  const TriangleClusters& clusters = scene.triangles().clusters;
  std::vector<std::optional<ClusterInView>> seen(clusters.size());
  tbb::parallel_for(std::size_t(0), clusters.size(), [&](std::size_t c) {
    seen[c] = in_view(clusters.bounds[c], view);
    if (seen[c]) seen[c]->cluster = std::uint32_t(c);
  });
  std::vector<ClusterInView> out;
  for (const auto& c : seen) {
    if (c) out.push_back(*c);
  }
  tbb::parallel_sort(out.begin(), out.end(), [](const ClusterInView& a, const ClusterInView& b) {
    return a.nearest > b.nearest || (a.nearest == b.nearest && a.cluster < b.cluster);
  });
  return out;
}

}  // namespace shadowkit::raster
