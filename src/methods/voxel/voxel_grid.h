#pragma once
// The voxel-to-world mapping of the cubic frame buffer (Lai & Cheng §3: the scene is
// normalized to [0, M1 - 1] x [0, M2 - 1] x [0, M3 - 1]) and the keys that name voxels.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "shadowkit/core/vec.h"

namespace shadowkit::voxel {

/// \brief Integer voxel coordinates.
using VoxelIndex = std::array<int, 3>;

/// \brief A point in grid units (one unit = one voxel edge), stored compactly as floats:
/// positions relative to the grid's origin keep their precision at any world scale.
struct GridPoint {
  float x = 0, y = 0, z = 0;
  Vec3 vec() const { return {x, y, z}; }
  static GridPoint of(Vec3 p) { return {float(p.x), float(p.y), float(p.z)}; }
};

/// \brief Cubic voxels of edge `size` covering the box [origin, origin + dims * size].
struct VoxelGrid {
  Vec3 origin;
  double size = 1;  ///< the voxel edge r, world units
  VoxelIndex dims{1, 1, 1};

  /// Voxel edges per side of the longest axis: the paper's resolution M.
  int resolution() const { return std::max({dims[0], dims[1], dims[2]}); }
  Vec3 to_grid(Vec3 world) const { return (world - origin) / size; }
  Vec3 to_world(Vec3 grid) const { return origin + grid * size; }
  /// The voxel holding grid point \p g, clamped into the grid (points on the far faces and
  /// rounding just outside belong to the border voxels).
  VoxelIndex voxel_of(Vec3 g) const {
    VoxelIndex v;
    for (int a = 0; a < 3; ++a) {
      v[a] = std::clamp(int(std::floor(std::clamp(g[a], -1.0, double(dims[a])))), 0, dims[a] - 1);
    }
    return v;
  }
  bool contains(const VoxelIndex& v) const {
    for (int a = 0; a < 3; ++a) {
      if (v[a] < 0 || v[a] >= dims[a]) return false;
    }
    return true;
  }
  /// Centre of voxel \p v in grid units.
  static Vec3 center(const VoxelIndex& v) { return {v[0] + 0.5, v[1] + 0.5, v[2] + 0.5}; }
};

/// \brief N-adjacency of Cohen-Or & Kaufman (Lai & Cheng §3): two voxels are 6-adjacent when
/// they share a face, 18- an edge, 26- a vertex. A voxel is adjacent to itself.
inline bool adjacent(const VoxelIndex& a, const VoxelIndex& b, int n) {
  int differing = 0;
  for (int k = 0; k < 3; ++k) {
    const int d = std::abs(a[k] - b[k]);
    if (d > 1) return false;
    differing += d;
  }
  return differing <= (n == 6 ? 1 : n == 18 ? 2 : 3);
}

}  // namespace shadowkit::voxel
