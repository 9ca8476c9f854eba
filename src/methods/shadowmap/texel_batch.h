#pragma once
// Williams 1978's second pass for a row of visible points at once: where each point falls in
// the light's maps and the depth it must not pass there, four points at a time. The camera
// pass and the test of a single point both go through it, so that both decide a point alike.
#include <array>
#include <cstddef>
#include <cstdint>

#include "cube_map.h"
#include "depth_map.h"

namespace shadowkit::shadowmap {

/// \brief What a receiver's plane gives its points' biases: constant + per_texel x
/// texel_size(zv) x depth slope, with its slope factor in each map (DepthMap::slope_factor).
/// For a cube map the faces along one world axis share a slope factor: their view normals
/// differ only in sign, and they share the light as their eye. For an orthographic map the
/// whole bias is \p constant.
struct ReceiverBias {
  float constant = 0, per_texel = 0;
  std::array<float, 3> slope_factor{};  ///< in the cube faces along x, y, z
};

/// \brief Up to kSize points in columns, each with its receiver's bias.
struct PointBatch {
  static constexpr std::size_t kSize = 128;
  std::size_t size = 0;
  /// Offset from the light (cube map) or view coordinates (orthographic map).
  std::array<float, kSize> x{}, y{}, z{};
  std::array<float, kSize> constant{}, per_texel{}, slope_x{}, slope_y{}, slope_z{};

  void add(Vec3 p, const ReceiverBias& bias) {
    x[size] = float(p.x), y[size] = float(p.y), z[size] = float(p.z);
    constant[size] = bias.constant, per_texel[size] = bias.per_texel;
    slope_x[size] = bias.slope_factor[0], slope_y[size] = bias.slope_factor[1];
    slope_z[size] = bias.slope_factor[2];
    ++size;
  }
};

/// \brief Where each point of a PointBatch is tested: the map (cube face, or 0), the texel,
/// and the point's depth less its bias, which a lit point's texel must not be nearer than.
struct TexelBatch {
  std::array<std::int32_t, PointBatch::kSize> map, texel_x, texel_y;
  /// The texel's map tile and its place in the tile (DepthMap::tile_texels).
  std::array<std::int32_t, PointBatch::kSize> tile, in_tile;
  std::array<float, PointBatch::kSize> depth;
};

/// The tests of \p points (offsets from the light) in \p cube.
void cube_texels(const CubeMap& cube, const PointBatch& points, TexelBatch& out);
/// The tests of \p points (view coordinates) in the orthographic \p map.
void orthographic_texels(const DepthMap& map, const PointBatch& points, TexelBatch& out);

}  // namespace shadowkit::shadowmap
