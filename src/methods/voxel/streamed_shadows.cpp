#include "streamed_shadows.h"

#include <algorithm>
#include <array>
#include <functional>

#include "shadow_determination.h"
#include "surface_voxels.h"
#include "voxelizer.h"

namespace shadowkit::voxel {
namespace {

// Grid units: far above the rounding of a visible point, far below a voxel.
constexpr double kFaceSlack = 1e-4;
// The most voxels one leaf stands for: four corners and two bridging voxels for each of
// three corners (for_each_leaf_voxel).
constexpr std::size_t kLeafVoxels = 10;

// Calls \p centre with the voxel centres of \p patch's leaves, as the recursion reaches
// them; the corners of a leaf often share a voxel, which is then given once.
void project_patch(const PatchSet& patches, std::size_t patch, const VoxelGrid& grid, int adjacency,
                   const std::function<void(Vec3)>& centre) {
  voxelize_patch(
      patches, std::uint32_t(patch), grid, adjacency, [&](const Subpatch& leaf, const Domain&) {
        std::array<VoxelIndex, kLeafVoxels> given;
        std::size_t count = 0;
        for_each_leaf_voxel(leaf, grid, adjacency, [&](const VoxelIndex& v, std::uint32_t) {
          const auto end = given.begin() + count;
          if (std::find(given.begin(), end, v) != end) return;
          given[count++] = v;
          centre(VoxelGrid::center(v));
        });
      });
}

}  // namespace

StreamedShadows::StreamedShadows(const PatchSet& patches, const VoxelGrid& grid, int adjacency,
                                 const Light& light, ShadowRules rules)
    : grid_(grid),
      projection_(projection_for(light, grid, rules)),
      nearest_(nearest_voxels(
          projection_, patches.size(),
          [&](std::size_t patch, const std::function<void(Vec3)>& centre) {
            project_patch(patches, patch, grid, adjacency, centre);
          },
          rules)) {}

bool StreamedShadows::shadowed(Vec3 g, Vec3 normal) const {
  // The voxel's centre stands for the point, as a voxel of the frame buffer does (§5). A
  // point on a voxel face (a plane on a grid plane) takes the voxel on the light's side:
  // the one behind would put A' within a voxel of the surface's own voxels.
  const Vec3 side = dot(normal, projection_.toward_light(g)) < 0 ? -normal : normal;
  return voxel_shadowed(grid_.voxel_of(g + side * kFaceSlack), normal);
}

bool StreamedShadows::voxel_shadowed(const VoxelIndex& v, Vec3 normal) const {
  const Vec3 a = VoxelGrid::center(v);
  return !nearest_the_light(projection_, nearest_, a) &&
         offset_test_shadowed(projection_, nearest_, normal, a);
}

}  // namespace shadowkit::voxel
