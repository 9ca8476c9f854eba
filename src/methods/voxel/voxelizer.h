#pragma once
// Lai & Cheng §3: voxelization by recursive midpoint subdivision of each patch's parameter
// space, until the voxels of a subpatch's four corners are N-adjacent.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "patch_set.h"
#include "voxel_grid.h"

namespace shadowkit::voxel {

using Corners = std::array<GridPoint, 4>;

/// \brief A leaf of the recursion: its four corners (grid units, in the patch's corner
/// order) and its patch. Its corners' voxels are the voxelization; its two triangles
/// (0, 1, 2) and (0, 2, 3) are what the topology test (§4.2) and the renderer (§5) draw.
struct Subpatch {
  Corners corner;
  std::uint32_t patch = 0;
};

/// Whether the recursion stops at a subpatch with corners \p corner (grid units): their
/// voxels are pairwise \p adjacency-adjacent, or the subpatch is far below a voxel in size
/// (corners around a voxel vertex can sit in diagonal voxels at any scale).
bool small_enough(const Corners& corners, int adjacency);

/// \brief A leaf's rectangle [u0, u1] x [v0, v1] in its patch's parameter space (dyadic).
struct Domain {
  double u0, u1, v0, v1;
};

/// Runs the recursion over \p patch, calling \p leaf with every leaf that reaches \p grid,
/// always in the same order: §5 renders by running it again.
void voxelize_patch(const PatchSet& patches, std::uint32_t patch, const VoxelGrid& grid,
                    int adjacency, const std::function<void(const Subpatch&, const Domain&)>& leaf);

/// The voxel of grid point \p g, unclamped (coordinates may lie outside the grid).
VoxelIndex voxel_floor(Vec3 g);

/// Runs the recursion over every patch (or the \p count from \p first on), patches in
/// parallel (oneTBB): per patch, \p value (Subpatch, Domain) -> T of each of its leaves, in
/// the recursion's order.
template <class T, class Value>
std::vector<std::vector<T>> map_leaves(const PatchSet& patches, const VoxelGrid& grid,
                                       int adjacency, const Value& value, std::size_t first = 0,
                                       std::size_t count = std::size_t(-1)) {
  std::vector<std::vector<T>> per_patch(std::min(count, patches.size() - first));
  tbb::parallel_for(std::size_t(0), per_patch.size(), [&](std::size_t p) {
    voxelize_patch(
        patches, std::uint32_t(first + p), grid, adjacency,
        [&](const Subpatch& leaf, const Domain& d) { per_patch[p].push_back(value(leaf, d)); });
  });
  return per_patch;
}

/// The parts one after the other, each freed once copied.
template <class T>
std::vector<T> concatenate(std::vector<std::vector<T>> parts) {
  std::size_t total = 0;
  for (const auto& part : parts) total += part.size();
  std::vector<T> out;
  out.reserve(total);
  for (auto& part : parts) {
    out.insert(out.end(), part.begin(), part.end());
    std::vector<T>().swap(part);
  }
  return out;
}

/// How many leaves of all patches reach \p grid; nothing once they add up to more than
/// \p most. The recursion then stops, so an input that asks too much is turned away in the
/// time of \p most leaves, with nothing stored.
std::optional<std::size_t> count_leaves(const PatchSet& patches, const VoxelGrid& grid,
                                        int adjacency, std::size_t most);

/// Leaves voxelize() keeps while it counts by default (about 220 MB): what an input refused
/// for too many leaves may take.
inline constexpr std::size_t kKeptWhileCounting = std::size_t(1) << 22;

/// The leaf subpatches of every patch that reach \p grid, in patch order, in one array;
/// nothing when there are more than \p most. The leaves are counted first (as by
/// count_leaves()), each patch keeping its leaves while the count stays within \p keep: a
/// scene within it is voxelized once, a larger one again for the patches not kept.
std::optional<std::vector<Subpatch>> voxelize(const PatchSet& patches, const VoxelGrid& grid,
                                              int adjacency, std::size_t most,
                                              std::size_t keep = kKeptWhileCounting);

}  // namespace shadowkit::voxel
