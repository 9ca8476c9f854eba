#include "shadow_determination.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <optional>

#include "light_projection.h"
#include "projection_entries.h"
#include "ray_triangle.h"

namespace shadowkit::voxel {
namespace {

// §4.1: the move off the surface, in voxels.
const double kOffset = std::sqrt(2.0);
// §4.2: hits nearer than this (voxels) to the sample are its own surface around it.
constexpr double kSelfHit = 1e-3;

// §4.1: move the sample A by sqrt(2) r along its normal, to the light's side (surfaces
// are two-sided: the side facing the camera away from the light is shadowed by contract
// condition 1 at the mask, which plays the part of the paper's N . (L - A) <= 0), and
// test the moved point A' against the nearest voxel of its entry. A' is projected along
// the beam through A: its sideways move picks the entry, its move along the beam only
// its distance.
bool offset_test_shadowed(const LightProjection& projection, const NearestVoxels& nearest,
                          const Subpatch& leaf, Vec3 a) {
  const Vec3 to_light = projection.toward_light(a);
  Vec3 n = leaf_normal(leaf);
  const double facing = dot(n, to_light);
  if (facing == 0) return true;  // the light in the subpatch's plane
  if (facing < 0) n = -n;
  const Vec3 move = n * kOffset;
  const double along = dot(move, to_light);
  const Vec3 sideways = a + move - to_light * along;
  const auto blocker = nearest.nearest(projection.entry(sideways));
  return blocker && *blocker < projection.distance(a) - along;
}

// §4.2: the ray from the sample to the light against the two triangles of every subpatch
// listed, nearer than the sample, in the entry where that ray projects.
bool topology_test_shadowed(const LightProjection& projection, const BlockingSubpatches& lists,
                            const std::vector<Subpatch>& leaves, Vec3 a) {
  const Vec3 direction = projection.to_light(a);
  const double reach = length(direction);
  if (reach == 0) return false;
  const RaySegment ray{a, direction, kSelfHit / reach, 1};
  const double distance = projection.distance(a);
  for (const auto& record : lists.list(projection.entry(a))) {
    if (record.distance >= distance) break;
    const auto& c = leaves[record.leaf].corner;
    if (ray_hits_triangle(ray, c[0].vec(), c[1].vec(), c[2].vec()) ||
        ray_hits_triangle(ray, c[0].vec(), c[2].vec(), c[3].vec())) {
      return true;
    }
  }
  return false;
}

}  // namespace

ShadowStatistics determine_shadows(const Light& light, const std::vector<Subpatch>& leaves,
                                   const SurfaceVoxels& voxels, ShadowTest test,
                                   CubicFrameBuffer& buffer) {
  const LightProjection projection(light, buffer.grid());
  const VoxelKeys& keys = buffer.keys();
  // Project the voxel centres once.
  std::vector<Vec3> centres(voxels.size());
  std::vector<std::uint64_t> entries(voxels.size());
  std::vector<float> distances(voxels.size());
  tbb::parallel_for(std::size_t(0), voxels.size(), [&](std::size_t i) {
    centres[i] = VoxelGrid::center(keys.voxel(voxels.keys[i]));
    entries[i] = projection.entry(centres[i]);
    distances[i] = float(projection.distance(centres[i]));
  });
  const NearestVoxels nearest(projection, centres, distances);
  std::vector<Vec3>().swap(centres);
  std::optional<BlockingSubpatches> lists;
  if (test == ShadowTest::topology) lists.emplace(projection, leaves);

  std::vector<VoxelState> states(voxels.size(), VoxelState::lit);
  std::vector<std::uint8_t> uncertain(voxels.size(), 0);
  tbb::parallel_for(std::size_t(0), voxels.size(), [&](std::size_t i) {
    if (distances[i] <= *nearest.nearest(entries[i])) return;  // nearest: lit
    uncertain[i] = 1;
    const std::uint32_t sample = voxels.samples[i];
    const Vec3 a = sample_point(leaves, sample);
    const bool shadowed = test == ShadowTest::offset
                              ? offset_test_shadowed(projection, nearest, leaves[sample / 4], a)
                              : topology_test_shadowed(projection, *lists, leaves, a);
    states[i] = shadowed ? VoxelState::shadowed : VoxelState::lit;
  });

  ShadowStatistics stats;
  stats.entries = nearest.entry_count();
  stats.blocker_records = lists ? lists->record_count() : 0;
  stats.peak_bytes = voxels.size() * (sizeof(std::uint64_t) + sizeof(float) + sizeof(VoxelState)) +
                     (lists ? lists->memory_bytes() : 0);
  for (std::size_t i = 0; i < voxels.size(); ++i) {
    stats.uncertain += uncertain[i];
    stats.shadowed += states[i] == VoxelState::shadowed;
    buffer.set(voxels.keys[i], states[i]);
  }
  return stats;
}

}  // namespace shadowkit::voxel
