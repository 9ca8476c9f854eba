#include "frame_bound.h"

#include <cmath>
#include <vector>

namespace shadowkit::voxel {
namespace {

using Polygon = std::vector<Vec3>;

// Sutherland-Hodgman: the part of \p poly with plane.distance >= 0.
Polygon clip(const Polygon& poly, const Plane& plane) {
  Polygon out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec3 a = poly[i], b = poly[(i + 1) % poly.size()];
    const double da = plane.distance(a), db = plane.distance(b);
    if (da >= 0) out.push_back(a);
    if ((da >= 0) != (db >= 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

// The box of every scene triangle clipped to the intersection of \p planes.
Bounds3 clipped_bounds(const Scene& scene, const std::vector<Plane>& planes) {
  const TriangleList& list = scene.triangles();
  Bounds3 box;
  for (const auto& tri : list.triangles) {
    Polygon poly{list.positions[tri[0]], list.positions[tri[1]], list.positions[tri[2]]};
    for (const Plane& plane : planes) {
      poly = clip(poly, plane);
      if (poly.empty()) break;
    }
    for (const Vec3& p : poly) box.add(p);
  }
  return box;
}

Plane plane_through(Vec3 point, Vec3 normal) {
  const Vec3 n = normalize(normal);
  return {n, -dot(n, point)};
}

// The camera's view frustum (no far plane): the near side and the four sides through the
// outer edges of the outermost pixels.
std::vector<Plane> view_frustum(const Camera& camera) {
  const Camera::PixelGrid g = camera.pixel_grid();
  const Vec3 f = camera.forward(), r = camera.right(), u = camera.true_up(), eye = camera.position;
  const double x_lo = g.x0 - 0.5 * g.step, x_hi = g.x0 + (camera.width - 0.5) * g.step;
  const double y_hi = g.y0 + 0.5 * g.step, y_lo = g.y0 - (camera.height - 0.5) * g.step;
  return {plane_through(eye, f), plane_through(eye, r - f * x_lo), plane_through(eye, f * x_hi - r),
          plane_through(eye, f * y_hi - u), plane_through(eye, u - f * y_lo)};
}

std::vector<Plane> box_planes(const Bounds3& box) {
  std::vector<Plane> planes;
  for (int a = 0; a < 3; ++a) {
    Vec3 n;
    n[a] = 1;
    planes.push_back({n, -box.lo[a]});
    planes.push_back({-n, box.hi[a]});
  }
  return planes;
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

Bounds3 frame_bound(const Scene& scene, bool whole_scene) {
  if (whole_scene) return scene.bounds();
  Bounds3 seen = clipped_bounds(scene, view_frustum(scene.camera));
  if (seen.empty()) return scene.bounds();  // nothing visible: any grid will do
  Bounds3 bound = seen;
  for (const Light& light : scene.lights) {
    bound.add(clipped_bounds(scene, box_planes(reach_toward(seen, light, scene.bounds()))));
  }
  return bound;
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

}  // namespace shadowkit::voxel
