#include "shadowkit/raster/view_frustum.h"

#include <algorithm>
#include <cmath>

namespace shadowkit {

ViewFrustum ViewFrustum::of(const Camera& camera, double near) {
  const Vec3 f = camera.forward(), r = camera.right(), u = camera.true_up();
  const double ty = camera.tan_half_fov(), tx = ty * camera.width / camera.height;
  ViewFrustum v;
  v.planes[0] = {f, -dot(f, camera.position) - near};
  const Vec3 corners[4] = {f - r * tx + u * ty, f + r * tx + u * ty, f + r * tx - u * ty,
                           f - r * tx - u * ty};
  for (int k = 0; k < 4; ++k) {
    v.near_corners[k] = camera.position + corners[k] * near;
    Vec3 n = normalize(cross(corners[k], corners[(k + 1) % 4]));
    if (dot(n, f) < 0) n = -n;
    v.planes[k + 1] = {n, -dot(n, camera.position)};
  }
  v.near_radius = near * std::sqrt(1 + tx * tx + ty * ty);
  return v;
}

bool ViewFrustum::holds(Vec3 p) const {
  return std::all_of(planes.begin(), planes.end(),
                     [&](const Plane& plane) { return plane.distance(p) >= 0; });
}

bool ViewFrustum::excludes(std::span<const Vec3> points) const {
  return std::any_of(planes.begin(), planes.end(), [&](const Plane& plane) {
    return std::all_of(points.begin(), points.end(), [&](Vec3 p) { return plane.distance(p) < 0; });
  });
}

std::vector<Vec3> ViewFrustum::clip(std::vector<Vec3> polygon) const {
  for (const Plane& plane : planes) {
    if (polygon.empty()) break;
    polygon = clip_polygon(polygon, plane);
  }
  return polygon;
}

std::vector<Vec3> clip_polygon(std::span<const Vec3> polygon, const Plane& plane) {
  std::vector<Vec3> out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec3 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    const double da = plane.distance(a), db = plane.distance(b);
    if (da >= 0) out.push_back(a);
    if ((da >= 0) != (db >= 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

std::array<Plane, 6> box_planes(const Bounds3& box) {
  std::array<Plane, 6> planes;
  for (int a = 0; a < 3; ++a) {
    Vec3 n{0, 0, 0};
    n[a] = 1;
    planes[2 * a] = {n, -box.lo[a]};
    planes[2 * a + 1] = {-n, box.hi[a]};
  }
  return planes;
}

}  // namespace shadowkit
