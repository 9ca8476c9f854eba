#pragma once
// The non-empty voxels of the voxelization as a list, each with the surface point that
// stands for it in shadow determination (§4).
#include <cstdint>
#include <vector>

#include "cubic_frame_buffer.h"
#include "voxelizer.h"

namespace shadowkit::voxel {

/// \brief Non-empty voxels in ascending key order, each with its samples: the leaf corners
/// (numbered leaf * 4 + corner) that fall in it, ascending (deterministic whatever the
/// thread count). A sample's position and its leaf's normal stand for the voxel in §4.
struct SurfaceVoxels {
  std::vector<std::uint64_t> keys;
  std::vector<std::uint32_t> first_sample{0};  ///< voxel i: samples[first[i] .. first[i+1])
  std::vector<std::uint32_t> samples;

  /// The voxels of \p leaves' corners (and bridges, see for_each_leaf_voxel) inside \p grid;
  /// with \p adjacency 6 also those that close tunnels (close_tunnels()), unless the paper's
  /// corners alone are asked for (\p corners_only).
  static SurfaceVoxels collect(const std::vector<Subpatch>& leaves, const VoxelGrid& grid,
                               const VoxelKeys& keys, int adjacency, bool corners_only = false);
  std::size_t size() const { return keys.size(); }
  std::size_t memory_bytes() const;
};

/// Calls \p emit(voxel, corner) with the voxels inside \p grid that stand for \p leaf: its
/// corners' voxels; where the recursion stopped on a leaf far below a voxel whose corners
/// are still not N-adjacent (it straddles a voxel edge or vertex), also the voxels of an
/// axis-by-axis path from corner 0 to the others, so that the surface stays N-connected
/// there. Bridging voxels take corner 0 (it lies within a tiny fraction of a voxel of them).
template <typename Emit>
void for_each_leaf_voxel(const Subpatch& leaf, const VoxelGrid& grid, int adjacency, Emit&& emit) {
  const auto add = [&](const VoxelIndex& v, std::uint32_t corner) {
    if (grid.contains(v)) emit(v, corner);
  };
  const VoxelIndex first = voxel_floor(leaf.corner[0].vec());
  for (std::uint32_t k = 0; k < 4; ++k) {
    const VoxelIndex v = voxel_floor(leaf.corner[k].vec());
    add(v, k);
    if (adjacent(first, v, adjacency)) continue;
    VoxelIndex step = first;
    for (int a = 0; a < 2; ++a) {
      step[a] = v[a];
      add(step, 0);
    }
  }
}

/// Position of sample \p sample (leaf * 4 + corner), grid units.
inline Vec3 sample_point(const std::vector<Subpatch>& leaves, std::uint32_t sample) {
  return leaves[sample / 4].corner[sample % 4].vec();
}

/// The leaf's normal from its diagonals (defined for the collapsed corner of a triangle
/// patch too); zero for a leaf shrunk to a point or a segment.
Vec3 leaf_normal(const Subpatch& leaf);

}  // namespace shadowkit::voxel
