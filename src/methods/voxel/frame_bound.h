#pragma once
// What the cubic frame buffer covers: only what the camera can see and what can cast a
// shadow on it, so that a huge ground does not eat the resolution M.
#include "shadowkit/scene/scene.h"
#include "voxel_grid.h"

namespace shadowkit::voxel {

/// The bound rule (docs/methods/voxel.md): S = the scene's triangles clipped to the camera's view
/// frustum; for each light, the triangles clipped to the box of S and the light (a point
/// light) or of S swept toward the light across the scene (a directional light) are the
/// casters that can shadow S. The bound is the box of S and every light's casters.
/// With \p whole_scene, simply the scene's bounding box.
Bounds3 frame_bound(const Scene& scene, bool whole_scene);

/// Cubic voxels with \p resolution along the longest side of \p bound, plus one voxel of
/// margin on every side so that surface points on the bound fall inside the grid.
VoxelGrid make_grid(const Bounds3& bound, int resolution);

}  // namespace shadowkit::voxel
