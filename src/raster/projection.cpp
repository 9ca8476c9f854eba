#include "shadowkit/raster/projection.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace shadowkit {

RasterProjection RasterProjection::perspective(Vec3 eye, Vec3 forward, Vec3 up, double fov_y_deg,
                                               int width, int height, double near) {
  RasterProjection p;
  p.eye = eye;
  p.forward = normalize(forward);
  p.right = normalize(cross(p.forward, up));
  p.up = cross(p.right, p.forward);
  // Contract: x = (2(c + 0.5)/W - 1) tan(fov/2) W/H, y = (1 - 2(w + 0.5)/H) tan(fov/2);
  // solved for the continuous pixel coordinates c + 0.5 and w + 0.5.
  const double t = std::tan(fov_y_deg * std::numbers::pi / 360.0);
  p.scale_x = height / (2.0 * t);
  p.scale_y = height / (2.0 * t);
  p.offset_x = width / 2.0;
  p.offset_y = height / 2.0;
  p.near = near;
  p.width = width;
  p.height = height;
  return p;
}

RasterProjection RasterProjection::from_camera(const Camera& camera, double near) {
  return perspective(camera.position, camera.look_at - camera.position, camera.up, camera.fov_y_deg,
                     camera.width, camera.height, near);
}

RasterProjection RasterProjection::orthographic_view(Vec3 center, Vec3 forward, Vec3 up,
                                                     double half_w, double half_h,
                                                     double depth_back, int width, int height) {
  RasterProjection p;
  p.forward = normalize(forward);
  p.right = normalize(cross(p.forward, up));
  p.up = cross(p.right, p.forward);
  p.eye = center - p.forward * depth_back;
  p.orthographic = true;
  p.scale_x = width / (2.0 * half_w);
  p.scale_y = height / (2.0 * half_h);
  p.offset_x = width / 2.0;
  p.offset_y = height / 2.0;
  p.near = 0;
  p.width = width;
  p.height = height;
  return p;
}

double near_plane_for(const Bounds3& bounds, Vec3 eye) {
  if (bounds.empty()) return 1e-6;
  const Vec3 far = max(bounds.hi - eye, eye - bounds.lo);
  return std::max(length(far) * 1e-7, 1e-300);
}

}  // namespace shadowkit
