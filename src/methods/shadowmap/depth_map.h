#pragma once
// One shadow-map depth image: the light's view of the scene, reduced to the linear depth of the
// nearest surface per texel (Williams 1978's "light-source z-buffer").
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "shadowkit/core/context.h"
#include "shadowkit/core/huge_pages.h"
#include "shadowkit/core/vec.h"
#include "shadowkit/raster/projection.h"
#include "shadowkit/raster/scan_converter.h"
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
/// reaches is not stored: it refers to one shared tile of +infinity. Tiles may be drawn only
/// where the lookups need them (draw()); the others are not drawn at all.
class DepthMap {
 public:
  /// Texels per side of a tile, the unit in which the map is drawn and stored.
  static constexpr int kTile = 64;
  static constexpr std::size_t kTileTexels = std::size_t(kTile) * kTile;

  /// Sets the map up for \p view with no tile drawn.
  void start(const RasterProjection& view);
  /// Renders \p scene into the tiles \p wanted marks (every tile when it is empty) with the
  /// scan converter (its depth tiles), each drawn at most once since start().
  void draw(const Scene& scene, const Context& ctx, ScanConverter::TileMask wanted = {});
  /// Tiles per row and in all (rows of tiles_x()), the units of draw()'s \p wanted.
  int tiles_x() const { return tiles_x_; }
  std::size_t tile_count() const { return slot_.size(); }
  /// Whether the tile of texel (x, y) has been drawn since start().
  bool drawn(int x, int y) const {
    return drawn_[std::size_t(unsigned(y) / kTile) * tiles_x_ + unsigned(x) / kTile] != 0;
  }

  const RasterProjection& view() const { return view_; }
  int width() const { return view_.width; }
  int height() const { return view_.height; }
  std::size_t texel_count() const { return std::size_t(view_.width) * view_.height; }
  /// Texels where some surface was drawn.
  std::size_t covered_texels() const { return covered_; }
  /// Tiles drawn since start().
  std::size_t drawn_tiles() const;
  std::size_t memory_bytes() const;

  /// Stored linear depth of texel (x, y); +infinity where nothing was drawn.
  const float& depth(int x, int y) const {
    const unsigned ux = unsigned(x), uy = unsigned(y);
    return tile_texels(std::size_t(uy / kTile) * tiles_x_ +
                       ux / kTile)[(uy % kTile) * kTile + ux % kTile];
  }
  /// The texels of map tile \p tile (rows of kTile, tiles row by row), as depth() finds them.
  const float* tile_texels(std::size_t tile) const {
    return texels_.get() + std::size_t(slot_[tile]) * kTileTexels;
  }

  /// \brief The view's projection onto texels, in float for the lookups (texel_batch.h):
  /// a texel's width on the image plane is far above float's rounding there.
  struct TexelGrid {
    float offset_x, offset_y, scale_x, scale_y;
    int width, height;
    /// The texel whose span [i, i + 1) holds \p x (RasterProjection::pixel_x and pixel_y),
    /// clamped to the map, NaN to 0: texel_batch.h's lanes compute
    /// min(max(offset_x + scale_x u, 0), width - 1) and the same for offset_y - scale_y w.
  };
  const TexelGrid& texel_grid() const { return grid_; }

  /// World size of one texel at view depth \p zv: the larger side of its footprint on the plane
  /// zv = const (2 zv / resolution for a 90° face, the fitted extent / resolution for an
  /// orthographic map).
  double texel_size(double zv) const { return view_.orthographic ? texel_side_ : texel_side_ * zv; }

  /// What the depth slope of a receiver's plane depends on beside the point: for the plane
  /// with normal \p n in view space (unit) at signed distance \p eye_distance from the view's
  /// eye. On the plane n · v = c (c = -eye_distance), zv = c / (n · d) along the ray v = zv d,
  /// d = (u, w, 1) with (u, w) the screen position: moving a lateral distance s at depth zv
  /// changes (u, w) by s / zv and zv by s (n.x, n.y) / (n · d), a slope of
  /// |(n.x, n.y)| zv / |c|. Orthographic: d = (0, 0, 1), a slope of |(n.x, n.y)| / |n.z|.
  double slope_factor(Vec3 n, double eye_distance) const {
    // n is a unit vector: no overflow for std::hypot to guard against, at a tenth of its cost.
    return std::sqrt(n.x * n.x + n.y * n.y) / std::abs(view_.orthographic ? n.z : eye_distance);
  }

  /// Williams 1978, second pass, with percentage-closer filtering: of the kernel x kernel
  /// texels centred on texel (\p x, \p y) (kernel odd; texels past the map's edge are
  /// clamped to it), how many store a depth no nearer than \p depth, a point's depth less
  /// its bias: a point no farther from the light than the nearest surface the light sees in
  /// its direction is lit.
  int passing_tests(int x, int y, float depth, int kernel) const {
    if (kernel == 1) return depth <= this->depth(x, y);
    const int r = kernel / 2;
    int passed = 0;
    for (int dy = -r; dy <= r; ++dy) {
      const int ty = std::clamp(y + dy, 0, view_.height - 1);
      for (int dx = -r; dx <= r; ++dx) {
        passed += depth <= this->depth(std::clamp(x + dx, 0, view_.width - 1), ty);
      }
    }
    return passed;
  }

  /// The linear depth a texel stores for the scan converter's depth \p key
  /// (RasterProjection::depth_key), +infinity for -infinity (nothing drawn).
  template <bool kOrthographic>
  static float linear_depth(float key) {
    return kOrthographic ? -key : 1.0f / std::max(key, 0.0f);
  }

 private:
  std::size_t store(const DepthTile& tile, std::uint32_t slot);
  template <bool kOrthographic>
  static int store_row(const float* key, int n, float* depth);

  RasterProjection view_;
  double texel_side_ = 0;
  TexelGrid grid_{};
  int tiles_x_ = 0;
  std::vector<std::uint32_t> slot_;  ///< storage tile per map tile; slot 0 is all +infinity
  std::vector<std::uint8_t> drawn_;  ///< per map tile, whether draw() has drawn it
  /// kTileTexels per slot, room for a slot per map tile: left uninitialized, so only the
  /// slots drawn take memory. On huge pages: the lookups land all over a point light's six
  /// faces. Only grows, to be reused.
  HugePageArray<float> texels_;
  std::size_t capacity_ = 0;  ///< slots texels_ has room for
  std::size_t slots_ = 0;     ///< slots in use
  std::size_t covered_ = 0;
};

}  // namespace shadowkit::shadowmap
