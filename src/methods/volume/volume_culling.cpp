#include "volume_culling.h"

#include <algorithm>
#include <cmath>

namespace shadowkit {
namespace {

Vec3 corner(const Bounds3& b, int c) {
  return {c & 1 ? b.hi.x : b.lo.x, c & 2 ? b.hi.y : b.lo.y, c & 4 ? b.hi.z : b.lo.z};
}

double box_distance(const Bounds3& b, Vec3 p) {
  return length(p - max(b.lo, min(p, b.hi)));
}

}  // namespace

ViewFrustum ViewFrustum::of(const Camera& camera, double near) {
  const Vec3 f = camera.forward(), r = camera.right(), u = camera.true_up();
  const double ty = camera.tan_half_fov(), tx = ty * camera.width / camera.height;
  ViewFrustum v;
  const Vec3 corners[4] = {f - r * tx + u * ty, f + r * tx + u * ty, f + r * tx - u * ty,
                           f - r * tx - u * ty};
  for (int k = 0; k < 4; ++k) {
    Vec3 n = normalize(cross(corners[k], corners[(k + 1) % 4]));
    if (dot(n, f) < 0) n = -n;
    v.planes[k] = {n, -dot(n, camera.position)};
  }
  v.planes[4] = {f, -dot(f, camera.position) - near};
  v.near_radius = near * std::sqrt(1 + tx * tx + ty * ty);
  return v;
}

bool ViewFrustum::excludes(std::span<const Vec3> points) const {
  return std::any_of(planes.begin(), planes.end(), [&](const Plane& plane) {
    return std::all_of(points.begin(), points.end(), [&](Vec3 p) { return plane.distance(p) < 0; });
  });
}

bool shadow_volume_reaches_view(const Bounds3& box, const Light& light, const Reach& reach,
                                const ViewFrustum& view) {
  // The volume within the reach lies in the hull of the box's corners and the corners pushed
  // away from the light until they leave the reach: a point light at distance g from the box
  // needs them pushed to reach / g times their distance.
  std::array<Vec3, 16> hull;
  double push = 0;
  if (light.type == Light::Type::point) {
    const double gap = box_distance(box, light.position);
    if (gap == 0) return true;  // the light inside the box: the volume surrounds it
    push = reach.limit / gap;
  }
  for (int c = 0; c < 8; ++c) {
    const Vec3 p = corner(box, c);
    hull[c] = p;
    hull[8 + c] = light.type == Light::Type::point
                      ? light.position + (p - light.position) * std::max(push, 1.0)
                      : p + light.direction * std::max(0.0, reach.limit - dot(p, light.direction));
  }
  return !view.excludes(hull);
}

}  // namespace shadowkit
