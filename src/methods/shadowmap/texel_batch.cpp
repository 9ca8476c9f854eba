#include "texel_batch.h"

#include <bit>
#include <cstring>

namespace shadowkit::shadowmap {
namespace {

// Four lanes of GCC's (and Clang's) vector extension: SSE on the x86-64-v2 baseline, without
// intrinsics. A batch runs in whole groups of four; lanes past its size compute what their
// zeroed or earlier entries give, and nothing reads them.
using Floats = float __attribute__((vector_size(16)));
using Ints = std::int32_t __attribute__((vector_size(16)));
constexpr std::size_t kLanes = 4;
static_assert(PointBatch::kSize % kLanes == 0);

Floats load(const float* p) {
  Floats v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <class Vector, class T>
void store(T* p, Vector v) {
  std::memcpy(p, &v, sizeof v);
}
Floats splat(float x) {
  return Floats{} + x;
}
Floats abs(Floats v) {
  return Floats(Ints(v) & 0x7fffffff);
}
// As std::min and std::max: the first argument where the comparison fails (NaN).
Floats min(Floats a, Floats b) {
  return b < a ? b : a;
}
Floats max(Floats a, Floats b) {
  return a < b ? b : a;
}
// DepthMap::TexelGrid::clamped, in lanes.
Ints clamped(Floats x, int n) {
  return __builtin_convertvector(min(x > 0 ? x : Floats{}, splat(float(n - 1))), Ints);
}

// The tile of texels (x, y) and their place in it, as DepthMap::depth() finds them.
void store_tile(TexelBatch& out, std::size_t k, Ints x, Ints y, int width) {
  constexpr int kShift = std::countr_zero(unsigned(DepthMap::kTile));
  static_assert(DepthMap::kTile == 1 << kShift);
  const int tiles_x = (width + DepthMap::kTile - 1) / DepthMap::kTile;
  store(&out.tile[k], (y >> kShift) * tiles_x + (x >> kShift));
  store(&out.in_tile[k], ((y & (DepthMap::kTile - 1)) << kShift) + (x & (DepthMap::kTile - 1)));
}

}  // namespace

// The face of the dominant axis (CubeMap::face_of, ties to x, then y) and the view
// coordinates in it (RasterProjection::to_view of CubeMap::face_view), by selection. Right is
// forward x up: +X sees (z, y), -X (-z, y), +Y (x, z), -Y (-x, z), +Z (-x, y), -Z (x, y).
void cube_texels(const CubeMap& cube, const PointBatch& points, TexelBatch& out) {
  const DepthMap::TexelGrid grid = cube.face(0).texel_grid();
  for (std::size_t k = 0; k < points.size; k += kLanes) {
    const Floats dx = load(&points.x[k]), dy = load(&points.y[k]), dz = load(&points.z[k]);
    const Floats ax = abs(dx), ay = abs(dy), az = abs(dz);
    const Ints y_over_z = ay >= az, on_x = ax >= max(ay, az), on_y = ~on_x & y_over_z;
    const Floats major = on_x ? dx : (y_over_z ? dy : dz);
    const Floats zv = abs(major), sign = major >= 0 ? splat(1) : splat(-1);
    const Floats xv = on_x ? sign * dz : (y_over_z ? sign : -sign) * dx;
    const Floats yv = on_y ? dz : dy;
    const Floats inverse = 1.0f / zv;
    const Ints axis = on_x ? Ints{} : (y_over_z ? Ints{} + 1 : Ints{} + 2);
    store(&out.map[k], 2 * axis + (major < 0 ? Ints{} + 1 : Ints{}));
    const Ints x = clamped(grid.offset_x + grid.scale_x * (xv * inverse), grid.width);
    const Ints y = clamped(grid.offset_y - grid.scale_y * (yv * inverse), grid.height);
    store(&out.texel_x[k], x);
    store(&out.texel_y[k], y);
    store_tile(out, k, x, y, grid.width);
    const Floats slope = on_x ? load(&points.slope_x[k])
                              : (y_over_z ? load(&points.slope_y[k]) : load(&points.slope_z[k]));
    // How fast the face's depth zv of the receiver's plane changes per unit of lateral
    // distance at the point, capped at kMaxSlope: the tangent of the angle between normal
    // and light direction on the face's axis, the exact zv gradient off it. NaN gives
    // kMaxSlope: a plane through the light is seen edge-on.
    const Floats depth_slope =
        zv > 0 ? min(splat(float(kMaxSlope)), slope * zv) : splat(float(kMaxSlope));
    store(&out.depth[k],
          zv - (load(&points.constant[k]) + load(&points.per_texel[k]) * zv * depth_slope));
  }
}

void orthographic_texels(const DepthMap& map, const PointBatch& points, TexelBatch& out) {
  const DepthMap::TexelGrid grid = map.texel_grid();
  for (std::size_t k = 0; k < points.size; k += kLanes) {
    store(&out.map[k], Ints{});
    const Ints x = clamped(grid.offset_x + grid.scale_x * load(&points.x[k]), grid.width);
    const Ints y = clamped(grid.offset_y - grid.scale_y * load(&points.y[k]), grid.height);
    store(&out.texel_x[k], x);
    store(&out.texel_y[k], y);
    store_tile(out, k, x, y, grid.width);
    store(&out.depth[k], load(&points.z[k]) - load(&points.constant[k]));
  }
}

}  // namespace shadowkit::shadowmap
