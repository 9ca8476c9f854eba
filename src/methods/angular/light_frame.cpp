#include "light_frame.h"

#include <cmath>

namespace shadowkit::angular {

LightFrame::LightFrame(const Light& light, const Camera& camera, Vec3 scene_center)
    : point_(light.type == Light::Type::point) {
  const Vec3 right = camera.right();
  if (point_) {
    origin_ = light.position;
    axis_[0] = right;
    axis_[1] = camera.true_up();
    axis_[2] = camera.forward();
    return;
  }
  // Parallel projection: theta-planes hold the direction of travel and the right axis, so
  // that lines along the right axis keep theta (Sec. 3). A light travelling along that axis
  // lies in every plane holding it; its theta-planes are the ones that also hold the forward
  // axis, parallel to the centre scan line's plane. Either way a scan line keeps theta on
  // faces parallel to the right axis (which such a light grazes) and crosses theta-planes on
  // the others, where eq. 7's run lengths end.
  Vec3 normal = cross(right, light.direction);
  if (length(normal) < 1e-9) normal = cross(camera.forward(), light.direction);
  origin_ = scene_center;
  axis_[1] = normalize(normal);
  axis_[2] = light.direction;
  axis_[0] = cross(axis_[2], axis_[1]);  // left-handed, as the point light's frame
}

AngularPoint LightFrame::angular_local(Vec3 v) const {
  if (!point_) return {v.z, v.y, v.x};
  return {length(v), local_theta(v, true), phi_local(v)};
}

FrameAffine LightFrame::theta_plane(double theta) const {
  if (!point_) return {{0, 1, 0}, -theta};
  // Y cos(theta) - F sin(theta) = 0 holds the half-planes at theta and theta + pi.
  return {{0, std::cos(theta), -std::sin(theta)}, 0};
}

FrameAffine LightFrame::plane(const Plane& world) const {
  return {local_direction(world.normal), world.distance(origin_)};
}

FrameAffine LightFrame::ray_plane(Vec3 a, Vec3 b) const {
  if (point_) return {cross(a, b), 0};
  const Vec3 n = cross(b - a, Vec3{0, 0, 1});
  return {n, -dot(n, a)};
}

}  // namespace shadowkit::angular
