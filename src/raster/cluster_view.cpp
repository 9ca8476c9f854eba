#include "shadowkit/raster/cluster_view.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace shadowkit::raster {
namespace {

// Bits of the view frustum's planes that \p v (view space) lies beyond: the near plane, and
// the raster's sides moved out by two pixels. Each side is a half-space (through the eye, for
// a perspective view) that holds the frustum, so a box whose corners share a bit lies
// outside the view, wherever its corners are against the eye.
unsigned outside_bits(Vec3 v, const RasterProjection& view) {
  constexpr double kMargin = 2;
  const double w = view.orthographic ? 1 : v.z;  // the homogeneous coordinate
  const double x = view.scale_x * v.x + view.offset_x * w,
               y = view.offset_y * w - view.scale_y * v.y;
  return unsigned(!(v.z > view.near)) | unsigned(x < -kMargin * w) << 1 |
         unsigned(x > (view.width + kMargin) * w) << 2 | unsigned(y < -kMargin * w) << 3 |
         unsigned(y > (view.height + kMargin) * w) << 4;
}

// Where the box's triangles can draw: its corners' projections bound the projection of all
// of it when it lies wholly past the near plane. A pixel is drawn where its centre lies in a
// triangle whose corners are snapped to 1/256 pixel; the margin of one pixel covers that.
std::optional<ClusterInView> in_view(const Bounds3& box, const RasterProjection& view) {
  const int last_x = view.width - 1, last_y = view.height - 1;
  std::array<Vec3, 8> corners;
  unsigned shared = ~0u, any = 0;
  for (int k = 0; k < 8; ++k) {
    corners[k] = view.to_view(box.corner(k));
    const unsigned bits = outside_bits(corners[k], view);
    shared &= bits, any |= bits;
  }
  if (shared != 0) return std::nullopt;
  ClusterInView c{0, -INFINITY, 0, 0, last_x, last_y};
  if (any & 1) {  // reaches in front of the near plane: no projection bounds it
    c.nearest = INFINITY;
    return c;
  }
  double min_x = INFINITY, max_x = -INFINITY, min_y = INFINITY, max_y = -INFINITY;
  for (const Vec3& v : corners) {
    c.nearest = std::max(c.nearest, view.depth_key(v.z));
    min_x = std::min(min_x, view.pixel_x(v)), max_x = std::max(max_x, view.pixel_x(v));
    min_y = std::min(min_y, view.pixel_y(v)), max_y = std::max(max_y, view.pixel_y(v));
  }
  // The depth key of a face at a pixel is evaluated from its plane, in rounded arithmetic.
  c.nearest += 1e-9 * std::abs(c.nearest);
  const auto first = [](double p) { return std::floor(p - 0.5) - 1; };
  const auto last = [](double p) { return std::ceil(p - 0.5) + 1; };
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
