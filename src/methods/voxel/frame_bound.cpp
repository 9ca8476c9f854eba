#include "frame_bound.h"

#include <cmath>
#include <span>
#include <vector>

#include "shadowkit/raster/view_frustum.h"

namespace shadowkit::voxel {
namespace {

// The box of every scene triangle clipped to the intersection of \p planes.
Bounds3 clipped_bounds(const Scene& scene, std::span<const Plane> planes) {
  const TriangleList& list = scene.triangles();
  Bounds3 box;
  for (const auto& tri : list.triangles) {
    std::vector<Vec3> poly{list.positions[tri[0]], list.positions[tri[1]], list.positions[tri[2]]};
    for (const Plane& plane : planes) {
      poly = clip_polygon(poly, plane);
      if (poly.empty()) break;
    }
    for (const Vec3& p : poly) box.add(p);
  }
  return box;
}

// The box that holds every segment from a point of \p seen toward \p light, within the scene.
Bounds3 reach_toward(const Bounds3& seen, const Light& light, const Bounds3& scene_box) {
  Bounds3 reach = seen;
  if (light.type == Light::Type::point) {
    reach.add(light.position);
  } else {
    const double span = scene_box.diagonal() + seen.diagonal();
    reach.add(seen.lo - light.direction * span);
    reach.add(seen.hi - light.direction * span);
  }
  return reach;
}

}  // namespace

Bounds3 view_bound(const Scene& scene, const Camera& camera) {
  const Bounds3 seen = clipped_bounds(scene, ViewFrustum::of(camera, 0).planes);
  if (seen.empty()) return seen;
  Bounds3 bound = seen;
  for (const Light& light : scene.lights) {
    bound.add(clipped_bounds(scene, box_planes(reach_toward(seen, light, scene.bounds()))));
  }
  return bound;
}

Bounds3 frame_bound(const Scene& scene, std::span<const Camera> views, bool whole_scene) {
  if (whole_scene) return scene.bounds();
  Bounds3 bound;
  for (const Camera& camera : views) bound.add(view_bound(scene, camera));
  return bound.empty() ? scene.bounds() : bound;  // nothing visible: any grid will do
}

VoxelGrid make_grid(const Bounds3& bound, int resolution) {
  VoxelGrid grid;
  const Vec3 extent = bound.empty() ? Vec3{} : bound.extent();
  const double longest = max_abs_component(extent);
  grid.size = longest > 0 ? longest / (resolution - 2) : 1.0;
  grid.origin = (bound.empty() ? Vec3{} : bound.lo) - Vec3{grid.size, grid.size, grid.size};
  for (int a = 0; a < 3; ++a) {
    grid.dims[a] = std::min(resolution, int(std::ceil(extent[a] / grid.size)) + 2);
  }
  return grid;
}

bool grid_serves(const VoxelGrid& grid, const Scene& scene, const Camera& camera) {
  const Bounds3 needed = view_bound(scene, camera);
  if (needed.empty()) return true;
  const Vec3 hi =
      grid.origin +
      Vec3{double(grid.dims[0]), double(grid.dims[1]), double(grid.dims[2])} * grid.size;
  for (int a = 0; a < 3; ++a) {
    if (needed.lo[a] < grid.origin[a] || needed.hi[a] > hi[a]) return false;
  }
  return true;
}

}  // namespace shadowkit::voxel
