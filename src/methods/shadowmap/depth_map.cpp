#include "depth_map.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "shadowkit/raster/scan_converter.h"

namespace shadowkit::shadowmap {
namespace {

// Index of the texel whose span [i, i + 1) contains continuous coordinate s, clamped to
// [0, n - 1]; NaN goes to 0.
int texel_index(double s, int n) {
  if (!(s > 0)) return 0;
  if (s >= n) return n - 1;
  return int(s);
}

}  // namespace

void DepthMap::render(const Scene& scene, const RasterProjection& view, const Context& ctx) {
  view_ = view;
  depth_.assign(std::size_t(view.width) * view.height, std::numeric_limits<float>::infinity());
  std::atomic<std::size_t> covered{0};
  // Williams 1978, first pass: a z-buffer rendering of the scene from the light, keeping only
  // depth. Each finished tile is converted to linear depth while it is in cache.
  ScanConverter(scene).rasterize_tiles(view, ctx, [&](const RasterTile& tile) {
    std::size_t drawn = 0;
    for (int y = 0; y < tile.height; ++y) {
      float* row = depth_.data() + std::size_t(tile.y0 + y) * view.width + tile.x0;
      for (int x = 0; x < tile.width; ++x) {
        const int k = y * tile.width + x;
        if (tile.face[k] == kNoFace) continue;
        const double key = tile.depth_key[k];
        row[x] = float(view.orthographic ? -key : 1.0 / key);
        ++drawn;
      }
    }
    covered.fetch_add(drawn, std::memory_order_relaxed);
  });
  covered_ = covered.load();
}

void DepthMap::texel_of(Vec3 v, int& x, int& y) const {
  x = texel_index(view_.pixel_x(v), view_.width);
  y = texel_index(view_.pixel_y(v), view_.height);
}

double DepthMap::texel_size(double zv) const {
  const double size = std::max(1.0 / view_.scale_x, 1.0 / view_.scale_y);
  return view_.orthographic ? size : size * zv;
}

double DepthMap::depth_slope(Vec3 n, Vec3 v) const {
  // On the plane n · x = c (view space), zv = c / (n · d) along the ray x = zv d, d = (u, w, 1)
  // with (u, w) the screen position: moving a lateral distance s at depth zv changes (u, w) by
  // s / zv and zv by s (n.x, n.y) / (n · d). Orthographic: d = (0, 0, 1).
  if (!view_.orthographic && !(v.z > 0)) return kMaxSlope;
  const Vec3 d = view_.orthographic ? Vec3{0, 0, 1} : Vec3{v.x / v.z, v.y / v.z, 1};
  const double along = std::abs(dot(n, d));
  const double across = std::hypot(n.x, n.y);
  return across >= kMaxSlope * along ? kMaxSlope : across / along;
}

int DepthMap::passing_tests(Vec3 v, double bias, int kernel) const {
  int cx = 0, cy = 0;
  texel_of(v, cx, cy);
  const int r = kernel / 2;
  int passed = 0;
  for (int dy = -r; dy <= r; ++dy) {
    const int y = std::clamp(cy + dy, 0, view_.height - 1);
    for (int dx = -r; dx <= r; ++dx) {
      const int x = std::clamp(cx + dx, 0, view_.width - 1);
      // Williams 1978, second pass: the point is lit when it is not farther from the light
      // than the nearest surface the light sees in its direction (within the bias).
      if (v.z <= double(depth(x, y)) + bias) ++passed;
    }
  }
  return passed;
}

}  // namespace shadowkit::shadowmap
