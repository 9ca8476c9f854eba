#pragma once
// Lai & Cheng §5.1: shadows without the cubic frame buffer. The voxels are projected onto
// the light's projection plane during the voxelization and never stored, so M is bounded by
// the plane's memory, not the voxels'; every visible point is then decided on the fly with
// the offset-based test (§4.1) against that plane.
#include <cstddef>

#include "light_projection.h"
#include "patch_set.h"
#include "projection_entries.h"
#include "shadow_determination.h"
#include "voxel_grid.h"

namespace shadowkit::voxel {

class StreamedShadows {
 public:
  /// Voxelizes \p patches into \p grid (twice: once to size the plane, once to fill it) and
  /// projects every surface voxel for \p light, by \p rules (the offset test).
  StreamedShadows(const PatchSet& patches, const VoxelGrid& grid, int adjacency, const Light& light,
                  ShadowRules rules);
  /// Whether the voxel of grid point \p g, on a surface of normal \p normal, is shadowed.
  bool shadowed(Vec3 g, Vec3 normal) const;
  /// Whether voxel \p v, on a surface of normal \p normal, is shadowed: nearest the light in
  /// its entry is lit, the rest is decided by the offset test (§4.1) with A its centre.
  bool voxel_shadowed(const VoxelIndex& v, Vec3 normal) const;
  std::size_t entry_count() const { return nearest_.entry_count(); }
  std::size_t memory_bytes() const { return nearest_.memory_bytes(); }

 private:
  VoxelGrid grid_;
  LightProjection projection_;
  NearestVoxels nearest_;
};

}  // namespace shadowkit::voxel
