#pragma once
// One shadow-map depth image: the light's view of the scene, reduced to the linear depth of the
// nearest surface per texel (Williams 1978's "light-source z-buffer").
#include <cstddef>
#include <vector>

#include "shadowkit/core/context.h"
#include "shadowkit/core/vec.h"
#include "shadowkit/raster/projection.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::shadowmap {

/// The largest receiver slope (depth change per unit of lateral distance) the slope bias
/// follows: tan 84.3°. Beyond it the bias stops growing, so grazing surfaces show acne rather
/// than lifting their whole neighbourhood out of shadow.
inline constexpr double kMaxSlope = 10.0;

/// \brief A depth image seen from a light, with the projection that made it.
///
/// Depth is stored in a linear metric, the view-space depth zv along the view's forward axis
/// (1 / key for a perspective view, -key for an orthographic one; RasterProjection::depth_key),
/// as float: a comparison then needs no knowledge of the projection, and the bias is in world
/// units. Texels where nothing was drawn hold +infinity (nothing there casts a shadow).
class DepthMap {
 public:
  /// Renders \p scene through \p view with the shared ScanConverter.
  void render(const Scene& scene, const RasterProjection& view, const Context& ctx);

  const RasterProjection& view() const { return view_; }
  int width() const { return view_.width; }
  int height() const { return view_.height; }
  std::size_t texel_count() const { return depth_.size(); }
  /// Texels where some surface was drawn.
  std::size_t covered_texels() const { return covered_; }
  std::size_t memory_bytes() const { return depth_.capacity() * sizeof(float); }

  /// Stored linear depth of texel (x, y); +infinity where nothing was drawn.
  float depth(int x, int y) const { return depth_[std::size_t(y) * view_.width + x]; }

  /// The texel (x, y) whose footprint contains view-space point \p v; points off the map (and
  /// points on its outer edges) take the nearest edge texel.
  void texel_of(Vec3 v, int& x, int& y) const;

  /// World size of one texel at view depth \p zv: the larger side of its footprint on the plane
  /// zv = const (2 zv / resolution for a 90° face, the fitted extent / resolution for an
  /// orthographic map).
  double texel_size(double zv) const;

  /// How fast the view depth zv of the receiver's plane changes per unit of lateral distance
  /// near the view-space point \p v, given the plane's normal \p n in view space, capped at
  /// kMaxSlope. For an orthographic map it is tan(angle between normal and light direction);
  /// for a perspective face it is |(n.x, n.y)| / |n · (v / v.z)|, which is the same tangent on
  /// the face's axis and the exact zv gradient off it.
  double depth_slope(Vec3 n, Vec3 v) const;

  /// Depth tests of a kernel x kernel block of texels centred on the texel of \p v (kernel
  /// odd; texels past the map's edge are clamped to it): how many have v.z <= stored + bias.
  int passing_tests(Vec3 v, double bias, int kernel) const;

 private:
  RasterProjection view_;
  std::vector<float> depth_;
  std::size_t covered_ = 0;
};

}  // namespace shadowkit::shadowmap
