#include "light_frame.h"

#include <cmath>

#include "shadowkit/core/error.h"

namespace shadowkit {

LightFrame::LightFrame(const Light& light, const Camera& camera, Vec3 scene_center,
                       std::size_t index)
    : point_(light.type == Light::Type::point) {
  const Vec3 right = camera.right();
  if (point_) {
    origin_ = light.position;
    axis_[0] = right;
    axis_[1] = camera.true_up();
    axis_[2] = camera.forward();
    return;
  }
  // Parallel projection: theta-planes hold the right axis and the direction of travel.
  const Vec3 normal = cross(right, light.direction);
  if (length(normal) < 1e-9) {
    throw InputError("light " + std::to_string(index),
                     "angular: a directional light travelling along the camera's right axis "
                     "has no constant-theta planes along the scan lines (not supported)");
  }
  origin_ = scene_center;
  axis_[1] = normalize(normal);
  axis_[2] = light.direction;
  axis_[0] = cross(axis_[1], axis_[2]);
  if (dot(axis_[0], right) < 0) axis_[0] = -axis_[0];
}

AngularPoint LightFrame::angular_local(Vec3 v) const {
  if (!point_) return {v.z, v.y, v.x};
  return {length(v), std::atan2(v.y, v.z), phi_local(v)};
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

}  // namespace shadowkit
