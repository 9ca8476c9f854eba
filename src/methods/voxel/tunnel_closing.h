#pragma once
// Lai & Cheng §3 with N = 6: the voxels of subpatch corners that are 6-adjacent must stop
// 26-paths (Cohen-Or & Kaufman's separability). A curved subpatch can pass within a sliver of
// a voxel vertex or edge with no corner in the voxels it grazes, and leave two empty voxels
// that touch across the surface: a tunnel a 26-path slips through.
#include <cstdint>
#include <vector>

#include "cubic_frame_buffer.h"
#include "voxel_grid.h"

namespace shadowkit::voxel {

/// For a 2 x 2 x 2 block whose non-empty voxels are the bits of \p occupied (bit x + 2y + 4z),
/// the empty voxels to fill so that the block's empty voxels are one 6-connected set: then
/// any two of them that touch are joined by a 6-path within the block. The smallest
/// 6-connected set of empty voxels is filled first (the one with the lowest voxel on a tie).
std::uint8_t tunnel_fill(std::uint8_t occupied);

/// \brief A voxel added to close a tunnel, and the voxel of the voxelization nearest it in
/// its block, whose samples stand for it.
struct TunnelFill {
  std::uint64_t key, source;
};

/// The voxels to add to the non-empty voxels \p sorted_keys (ascending) so that no 2 x 2 x 2
/// block inside \p grid needs a tunnel_fill(): every 26-path through empty voxels then has a
/// 6-path through empty voxels beside it, and a voxelization that stops 6-paths stops
/// 26-paths. In the order they were added; each source is a voxel of \p sorted_keys.
std::vector<TunnelFill> close_tunnels(const std::vector<std::uint64_t>& sorted_keys,
                                      const VoxelGrid& grid, const VoxelKeys& keys);

}  // namespace shadowkit::voxel
