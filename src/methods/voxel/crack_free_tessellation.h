#pragma once
// Lai & Cheng §5.3: the subpatches of the voxelization as polygons without cracks. Each
// side of a subpatch is replaced by the polyline of every point evaluated on it (by the
// subpatch or by finer neighbours, in its patch or across a shared patch side), and the
// polygon is triangulated by a zigzag between its two chains from corner 0 to corner 2.
#include <cstdint>
#include <functional>
#include <vector>

#include "patch_set.h"
#include "shadowkit/scene/mesh.h"
#include "voxelizer.h"

namespace shadowkit::voxel {

/// \brief Triangles in world space and, per triangle, its subpatch: the index in
/// voxelize()'s order (the recursion is run again and visits the same leaves).
struct SubpatchTessellation {
  PolygonSoup triangles;
  std::vector<std::uint32_t> leaf;
  std::vector<std::uint32_t> leaf_patch;  ///< per subpatch from first_leaf on: its patch
  std::uint32_t first_leaf = 0;           ///< of a batch, its first subpatch
  std::uint32_t patch_of(std::uint32_t subpatch) const { return leaf_patch[subpatch - first_leaf]; }
};

/// §5.1: the tessellation sent on as it is made, in batches of subpatches in order, each of
/// \p batch_triangles triangles or a subpatch's few more, the last of fewer. Only the points
/// on the patch sides (a first pass over every patch) are kept for the whole scene, and the
/// subpatches of a few patches at a time, so the memory follows the batch, not the scene's
/// tessellation.
void tessellate_in_batches(const PatchSet& patches, const VoxelGrid& grid, int adjacency,
                           std::size_t batch_triangles,
                           const std::function<void(SubpatchTessellation)>& batch);

/// The whole tessellation as one batch.
SubpatchTessellation tessellate_subpatches(const PatchSet& patches, const VoxelGrid& grid,
                                           int adjacency);

/// The zigzag of §5.3 between chains \p a and \p b that both run from corner 0 to corner 2
/// (a along sides 0 and 1, b along sides 3 and 2), as index triples into a then b
/// (b's points numbered after a's), counter-clockwise in (u, v).
std::vector<std::array<std::uint32_t, 3>> zigzag(std::size_t a, std::size_t b);

}  // namespace shadowkit::voxel
