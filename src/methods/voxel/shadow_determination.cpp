#include "shadow_determination.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <optional>

#include "light_projection.h"
#include "projection_entries.h"
#include "ray_triangle.h"

namespace shadowkit::voxel {
namespace {

// §4.2: hits nearer than this (voxels) to the sample are its own surface around it: the
// paper's rule, with only rounding to absorb.
constexpr double kSelfHit = 1e-3;
// §4.2 tests the ray against flat subpatches, while the sample lies on the curved surface.
// Where a coarser leaf meets finer ones, its side is a chord past their corners on the
// surface; on a concave surface it passes above them, and a ray from such a corner hits it
// a few thousandths of a voxel away: an isolated shadowed voxel, a dark speck on a lit
// surface. By default hits within this distance (voxels) along the ray are the sample's own
// surface: the sag of a side of 2 sqrt(3) voxels (corners in 26-adjacent voxels) on any
// surface curved to a radius of 6 voxels or more, met at 90 degrees to the ray. Moving the
// ray's start along the ray, not off the surface, leaves the shadows of a grazing light
// their length.
constexpr double kOwnSurface = 0.25;
// Half a voxel: the footprint of a voxel on the plane for "nearest the light is lit".
constexpr double kNoHoles = 0.5;
// §4.1 compares a point moved by sqrt(2) voxels with voxels' footprints: entries of half
// a voxel keep a lit plane's own voxels out of the moved point's entry at grazing angles.
constexpr double kOffsetEntriesPerVoxel = 2;
// §4.1: the move off the surface, in voxels.
const double kOffset = std::sqrt(2.0);

// §4.2: the ray from the sample \p a to the light against the two triangles of every
// subpatch listed, nearer than the sample, in the entry where that ray projects; hits within
// \p own_surface voxels of \p a are its own surface.
bool topology_test_shadowed(const LightProjection& projection, const BlockingSubpatches& lists,
                            const std::vector<Subpatch>& leaves, Vec3 a, double own_surface) {
  const Vec3 direction = projection.to_light(a);
  const double reach = length(direction);
  if (reach == 0) return false;
  // A point light's end of the ray likewise: a surface that close holds the light, to the
  // voxels' precision, and passes it edge on (a light at a box's corner).
  const double light_end = projection.point_light() ? own_surface / reach : 0;
  const RaySegment ray{a, direction, own_surface / reach, 1 - light_end};
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

// The sample that stands for voxel \p i: the one whose subpatch faces the light most
// (normals follow the patches' vertex order). Where a lit face and one turned away share
// a voxel (a closed mesh's edge), the voxel is then decided for the lit face; the other
// is shadowed anyway by condition 1 at the mask.
std::uint32_t facing_sample(const LightProjection& projection, const std::vector<Subpatch>& leaves,
                            const SurfaceVoxels& voxels, std::size_t i) {
  std::uint32_t best = voxels.samples[voxels.first_sample[i]];
  double best_facing = -INFINITY;
  for (std::uint32_t k = voxels.first_sample[i]; k < voxels.first_sample[i + 1]; ++k) {
    const std::uint32_t s = voxels.samples[k];
    const double facing =
        dot(leaf_normal(leaves[s / 4]), projection.toward_light(sample_point(leaves, s)));
    if (facing > best_facing) best = s, best_facing = facing;
  }
  return best;
}

}  // namespace

LightProjection projection_for(const Light& light, const VoxelGrid& grid, ShadowRules rules) {
  const bool half_voxel = rules.test == ShadowTest::offset && !rules.paper;
  return LightProjection(light, grid, half_voxel ? kOffsetEntriesPerVoxel : 1.0);
}

NearestVoxels nearest_voxels(const LightProjection& projection, std::size_t parts,
                             const NearestVoxels::VoxelCentres& centres, ShadowRules rules) {
  return NearestVoxels(projection, parts, centres, rules.paper ? 0.0 : kNoHoles);
}

bool nearest_the_light(const LightProjection& projection, const NearestVoxels& nearest, Vec3 a) {
  const auto blocker = nearest.nearest(projection.entry(a));
  return !blocker || float(projection.distance(a)) <= *blocker;
}

// Surfaces are two-sided: the side facing the camera away from the light is shadowed by
// contract condition 1 at the mask, which plays the part of the paper's N . (L - A) <= 0,
// so the normal is turned to the light's side. A' is projected along the beam through A:
// its sideways move picks the entry, its move along the beam only its distance.
bool offset_test_shadowed(const LightProjection& projection, const NearestVoxels& nearest,
                          Vec3 normal, Vec3 a) {
  const Vec3 to_light = projection.toward_light(a);
  const double facing = dot(normal, to_light);
  if (facing == 0) return true;  // the light in the surface's plane
  const Vec3 move = (facing < 0 ? -normal : normal) * kOffset;
  const double along = dot(move, to_light);
  const Vec3 sideways = a + move - to_light * along;
  const auto blocker = nearest.nearest(projection.entry(sideways));
  return blocker && *blocker < projection.distance(a) - along;
}

ShadowStatistics determine_shadows(const Light& light, const std::vector<Subpatch>& leaves,
                                   const SurfaceVoxels& voxels, ShadowRules rules,
                                   CubicFrameBuffer& buffer) {
  const LightProjection projection = projection_for(light, buffer.grid(), rules);
  const VoxelKeys& keys = buffer.keys();
  // The voxel centres (x.5 coordinates: exact as floats).
  std::vector<GridPoint> centres(voxels.size());
  tbb::parallel_for(std::size_t(0), voxels.size(), [&](std::size_t i) {
    centres[i] = GridPoint::of(VoxelGrid::center(keys.voxel(voxels.keys[i])));
  });
  const NearestVoxels nearest = nearest_voxels(
      projection, voxels.size(),
      [&](std::size_t i, const auto& centre) { centre(centres[i].vec()); }, rules);
  std::optional<BlockingSubpatches> lists;
  if (rules.test == ShadowTest::topology) lists.emplace(projection, leaves);
  const double own_surface = rules.paper ? kSelfHit : kOwnSurface;

  std::vector<VoxelState> states(voxels.size(), VoxelState::lit);
  std::vector<std::uint8_t> uncertain(voxels.size(), 0);
  tbb::parallel_for(std::size_t(0), voxels.size(), [&](std::size_t i) {
    if (nearest_the_light(projection, nearest, centres[i].vec())) return;
    uncertain[i] = 1;
    const std::uint32_t sample = facing_sample(projection, leaves, voxels, i);
    const bool shadowed =
        rules.test == ShadowTest::offset
            ? offset_test_shadowed(projection, nearest, leaf_normal(leaves[sample / 4]),
                                   centres[i].vec())
            : topology_test_shadowed(projection, *lists, leaves, sample_point(leaves, sample),
                                     own_surface);
    states[i] = shadowed ? VoxelState::shadowed : VoxelState::lit;
  });

  ShadowStatistics stats;
  stats.entries = nearest.entry_count();
  stats.blocker_records = lists ? lists->record_count() : 0;
  stats.peak_bytes = voxels.size() * (sizeof(GridPoint) + 2) + nearest.memory_bytes() +
                     (lists ? lists->memory_bytes() : 0);
  for (std::size_t i = 0; i < voxels.size(); ++i) {
    stats.uncertain += uncertain[i];
    stats.shadowed += states[i] == VoxelState::shadowed;
    buffer.set(voxels.keys[i], states[i]);
  }
  return stats;
}

}  // namespace shadowkit::voxel
