#pragma once
// What the cubic frame buffer covers: only what the cameras can see and what can cast a
// shadow on it, so that a huge ground does not eat the resolution M.
#include <span>

#include "shadowkit/scene/scene.h"
#include "voxel_grid.h"

namespace shadowkit::voxel {

/// The bound rule (docs/methods/voxel.md) for one view: S = the scene's triangles clipped to
/// \p camera's view frustum; for each light, the triangles clipped to the box of S and the
/// light (a point light) or of S swept toward the light across the scene (a directional
/// light) are the casters that can shadow S. The box of S and every light's casters; empty
/// when the camera sees nothing.
Bounds3 view_bound(const Scene& scene, const Camera& camera);

/// The box that serves every view of \p views (§5.2: one frame buffer, any number of views):
/// the union of their view_bound(). With \p whole_scene, or when no view sees anything,
/// simply the scene's bounding box.
Bounds3 frame_bound(const Scene& scene, std::span<const Camera> views, bool whole_scene);

/// Cubic voxels with \p resolution along the longest side of \p bound, plus one voxel of
/// margin on every side so that surface points on the bound fall inside the grid.
VoxelGrid make_grid(const Bounds3& bound, int resolution);

/// Whether \p grid holds view_bound(\p scene, \p camera): whether a frame buffer on it has
/// every voxel the view of \p camera needs, so that a render from there drops no geometry.
bool grid_serves(const VoxelGrid& grid, const Scene& scene, const Camera& camera);

}  // namespace shadowkit::voxel
