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

  /// The voxels of \p leaves' corners (and bridges, see add_samples) inside \p grid.
  static SurfaceVoxels collect(const std::vector<Subpatch>& leaves, const VoxelGrid& grid,
                               const VoxelKeys& keys, int adjacency);
  std::size_t size() const { return keys.size(); }
  std::size_t memory_bytes() const;
};

/// Position of sample \p sample (leaf * 4 + corner), grid units.
inline Vec3 sample_point(const std::vector<Subpatch>& leaves, std::uint32_t sample) {
  return leaves[sample / 4].corner[sample % 4].vec();
}

/// The leaf's normal from its diagonals (defined for the collapsed corner of a triangle
/// patch too); zero for a leaf shrunk to a point or a segment.
Vec3 leaf_normal(const Subpatch& leaf);

}  // namespace shadowkit::voxel
