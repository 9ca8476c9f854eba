#pragma once
// One shadow-map depth image: the light's view of the scene, reduced to the linear depth of the
// nearest surface per texel (Williams 1978's "light-source z-buffer").
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "shadowkit/core/context.h"
#include "shadowkit/core/vec.h"
#include "shadowkit/raster/projection.h"
#include "shadowkit/raster/triangle_setup.h"
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
///
/// The texels are stored in square tiles, each contiguous, so that the few texels a run of
/// neighbouring visible points looks up share cache lines and pages. A tile that no triangle
/// reaches is not stored: it refers to one shared tile of +infinity.
class DepthMap {
 public:
  /// Texels per side of a tile, the unit in which the map is drawn and stored.
  static constexpr int kTile = 64;
  static constexpr std::size_t kTileTexels = std::size_t(kTile) * kTile;

  /// \brief A map to draw and the triangles set up for its view (as raster::setup_triangles
  /// sets them up; their order does not matter, the nearest depth wins).
  struct Drawing {
    DepthMap* map;
    RasterProjection view;
    std::vector<raster::ScreenTriangle> triangles;
  };

  /// Renders \p scene through \p view with the scan converter's triangle setup.
  void render(const Scene& scene, const RasterProjection& view, const Context& ctx);
  /// Draws every map of \p drawings, all their tiles in one parallel pass.
  static void draw(std::span<Drawing> drawings, const Context& ctx);

  const RasterProjection& view() const { return view_; }
  int width() const { return view_.width; }
  int height() const { return view_.height; }
  std::size_t texel_count() const { return std::size_t(view_.width) * view_.height; }
  /// Texels where some surface was drawn.
  std::size_t covered_texels() const { return covered_; }
  std::size_t memory_bytes() const;

  /// Stored linear depth of texel (x, y); +infinity where nothing was drawn.
  float depth(int x, int y) const {
    const unsigned ux = unsigned(x), uy = unsigned(y);
    const std::size_t tile = std::size_t(uy / kTile) * tiles_x_ + ux / kTile;
    return texels_[std::size_t(slot_[tile]) * kTileTexels + (uy % kTile) * kTile + ux % kTile];
  }

  /// The texel (x, y) whose footprint contains view-space point \p v; points off the map (and
  /// points on its outer edges) take the nearest edge texel.
  void texel_of(Vec3 v, int& x, int& y) const;

  /// World size of one texel at view depth \p zv: the larger side of its footprint on the plane
  /// zv = const (2 zv / resolution for a 90° face, the fitted extent / resolution for an
  /// orthographic map).
  double texel_size(double zv) const { return view_.orthographic ? texel_side_ : texel_side_ * zv; }

  /// How fast the view depth zv of the receiver's plane changes per unit of lateral distance
  /// near the view-space point \p v, given the plane's normal \p n in view space, capped at
  /// kMaxSlope. For an orthographic map it is tan(angle between normal and light direction);
  /// for a perspective face it is |(n.x, n.y)| / |n · (v / v.z)|, which is the same tangent on
  /// the face's axis and the exact zv gradient off it.
  double depth_slope(Vec3 n, Vec3 v) const { return depth_slope(n, lateral(n), v); }
  /// The same, given lateral(n).
  double depth_slope(Vec3 n, double lateral_n, Vec3 v) const;
  /// |(n.x, n.y)|, the part of depth_slope() that depends on the receiver alone.
  static double lateral(Vec3 n);

  /// Depth tests of a kernel x kernel block of texels centred on the texel of \p v (kernel
  /// odd; texels past the map's edge are clamped to it): how many have v.z <= stored + bias.
  int passing_tests(Vec3 v, double bias, int kernel) const;

 private:
  void allocate(const RasterProjection& view, std::span<const std::uint32_t> bin_start);
  std::size_t draw_tile(int tile, const std::vector<raster::ScreenTriangle>& triangles,
                        std::span<const std::uint32_t> bin);

  RasterProjection view_;
  double texel_side_ = 0;
  int tiles_x_ = 0;
  std::vector<std::uint32_t> slot_;  ///< storage tile per map tile; slot 0 is all +infinity
  std::vector<float> texels_;        ///< kTileTexels per slot; only grows, to be reused
  std::size_t covered_ = 0;
};

}  // namespace shadowkit::shadowmap
