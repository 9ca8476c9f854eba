#pragma once
// Lai & Cheng §4: shadow determination by projecting the voxels once onto the light's
// projection plane. The voxel nearest the light in each entry is lit; the uncertain rest
// are decided by the offset-based (§4.1) or the topology-based (§4.2) test.
#include <cstddef>
#include <vector>

#include "cubic_frame_buffer.h"
#include "shadowkit/scene/scene.h"
#include "surface_voxels.h"

namespace shadowkit::voxel {

enum class ShadowTest { offset, topology };

/// \brief What one light's shadow determination did.
struct ShadowStatistics {
  std::size_t uncertain = 0;  ///< voxels not nearest the light in their entry
  std::size_t shadowed = 0;
  std::size_t entries = 0;          ///< non-empty entries of the projection plane
  std::size_t blocker_records = 0;  ///< topology test: (entry, subpatch) records
  std::size_t peak_bytes = 0;       ///< the largest transient structure
};

/// Sets every non-empty voxel of \p buffer lit or shadowed for \p light.
ShadowStatistics determine_shadows(const Light& light, const std::vector<Subpatch>& leaves,
                                   const SurfaceVoxels& voxels, ShadowTest test,
                                   CubicFrameBuffer& buffer);

}  // namespace shadowkit::voxel
