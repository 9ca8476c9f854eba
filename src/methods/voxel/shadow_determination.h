#pragma once
// Lai & Cheng §4: shadow determination by projecting the voxels once onto the light's
// projection plane. The voxel nearest the light in each entry is lit; the uncertain rest
// are decided by the offset-based (§4.1) or the topology-based (§4.2) test.
#include <cstddef>
#include <vector>

#include "cubic_frame_buffer.h"
#include "light_projection.h"
#include "projection_entries.h"
#include "shadowkit/scene/scene.h"
#include "surface_voxels.h"

namespace shadowkit::voxel {

enum class ShadowTest { offset, topology };

/// \brief How §4 decides: the test, and whether as the paper writes it (`voxel.paper=1`):
/// voxels projected as points, the offset test on entries one voxel wide, the topology
/// test's hits counted from the sample itself. shadowkit's default gives a voxel a footprint
/// of half a voxel around its centre (no holes between a caster's voxels), half-voxel entries
/// to the offset test, and takes the topology test's hits within a quarter voxel of the
/// sample for its own surface (the chords of the subpatches around it).
struct ShadowRules {
  ShadowTest test = ShadowTest::topology;
  bool paper = false;
};

/// \brief What one light's shadow determination did.
struct ShadowStatistics {
  std::size_t uncertain = 0;  ///< voxels not nearest the light in their entry
  std::size_t shadowed = 0;
  std::size_t entries = 0;          ///< non-empty entries of the projection plane
  std::size_t blocker_records = 0;  ///< topology test: (entry, subpatch) records
  std::size_t peak_bytes = 0;       ///< the largest transient structure
};

/// The projection plane of \p light that \p rules decide on.
LightProjection projection_for(const Light& light, const VoxelGrid& grid, ShadowRules rules);

/// The nearest-distance map of the voxels \p centres gives (see NearestVoxels), each
/// covering the entries of its footprint so that a caster leaves no holes (§4), or, by the
/// paper's \p rules, only the entry of its centre.
NearestVoxels nearest_voxels(const LightProjection& projection, std::size_t parts,
                             const NearestVoxels::VoxelCentres& centres, ShadowRules rules);

/// Whether the voxel of centre \p a (grid units) is nearest the light in its entry: lit.
bool nearest_the_light(const LightProjection& projection, const NearestVoxels& nearest, Vec3 a);

/// §4.1's offset-based test of the voxel of centre \p a on a surface of normal \p normal:
/// A' = A + sqrt(2) r n, n turned to the light, is shadowed when its entry holds a voxel
/// nearer the light than A'. The light in the surface's plane shadows it.
bool offset_test_shadowed(const LightProjection& projection, const NearestVoxels& nearest,
                          Vec3 normal, Vec3 a);

/// Sets every non-empty voxel of \p buffer lit or shadowed for \p light.
ShadowStatistics determine_shadows(const Light& light, const std::vector<Subpatch>& leaves,
                                   const SurfaceVoxels& voxels, ShadowRules rules,
                                   CubicFrameBuffer& buffer);

}  // namespace shadowkit::voxel
