#include "streamed_shadows.h"

#include "shadow_determination.h"
#include "surface_voxels.h"
#include "voxelizer.h"

namespace shadowkit::voxel {
namespace {

// Grid units: far above the rounding of a visible point, far below a voxel.
constexpr double kFaceSlack = 1e-4;

}  // namespace

StreamedShadows::StreamedShadows(const PatchSet& patches, const VoxelGrid& grid, int adjacency,
                                 const Light& light)
    : grid_(grid),
      projection_(projection_for(light, grid, ShadowTest::offset)),
      nearest_(
          nearest_voxels(projection_, patches.size(), [&](std::size_t patch, const auto& centre) {
            voxelize_patch(patches, std::uint32_t(patch), grid, adjacency,
                           [&](const Subpatch& leaf, const Domain&) {
                             for_each_leaf_voxel(leaf, grid, adjacency,
                                                 [&](const VoxelIndex& v, std::uint32_t) {
                                                   centre(VoxelGrid::center(v));
                                                 });
                           });
          })) {}

bool StreamedShadows::shadowed(Vec3 g, Vec3 normal) const {
  // The voxel's centre stands for the point, as a voxel of the frame buffer does (§5). A
  // point on a voxel face (a plane on a grid plane) takes the voxel on the light's side:
  // the one behind would put A' within a voxel of the surface's own voxels.
  const Vec3 side = dot(normal, projection_.toward_light(g)) < 0 ? -normal : normal;
  const Vec3 a = VoxelGrid::center(grid_.voxel_of(g + side * kFaceSlack));
  return !nearest_the_light(projection_, nearest_, a) &&
         offset_test_shadowed(projection_, nearest_, normal, a);
}

}  // namespace shadowkit::voxel
