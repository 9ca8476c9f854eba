#pragma once
/// \brief Maps world space onto a raster: the camera's perspective view, a shadow-map cube
/// face, or an orthographic view along a light direction.
#include "shadowkit/core/vec.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// \brief A view frame (eye, right, up, forward) and the map from view space to continuous
/// pixel coordinates: pixel (c, w) covers [c, c+1) x [w, w+1) and is sampled at its centre.
///
/// Perspective: sx = offset_x + scale_x * xv / zv, sy = offset_y - scale_y * yv / zv.
/// Orthographic: sx = offset_x + scale_x * xv,      sy = offset_y - scale_y * yv.
/// (xv, yv, zv) are the coordinates along right, up and forward from the eye.
struct RasterProjection {
  Vec3 eye, right, up, forward;
  double scale_x = 1, scale_y = 1, offset_x = 0, offset_y = 0;
  double near = 1e-3;  ///< view-space depth below which geometry is clipped
  bool orthographic = false;
  int width = 1, height = 1;

  /// The camera's own view; \p near is a view-space depth.
  static RasterProjection from_camera(const Camera& camera, double near);
  /// A square perspective view of \p fov_y_deg looking along \p forward.
  static RasterProjection perspective(Vec3 eye, Vec3 forward, Vec3 up, double fov_y_deg, int width,
                                      int height, double near);
  /// An orthographic view along \p forward covering [-half_w, half_w] x [-half_h, half_h]
  /// around \p center; geometry behind eye = center - forward * depth_back is clipped.
  static RasterProjection orthographic_view(Vec3 center, Vec3 forward, Vec3 up, double half_w,
                                            double half_h, double depth_back, int width,
                                            int height);

  Vec3 to_view(Vec3 p) const {
    return {dot(p - eye, right), dot(p - eye, up), dot(p - eye, forward)};
  }
  /// Continuous pixel coordinates of a view-space point (zv > 0 for perspective).
  double pixel_x(Vec3 v) const { return offset_x + scale_x * (orthographic ? v.x : v.x / v.z); }
  double pixel_y(Vec3 v) const { return offset_y - scale_y * (orthographic ? v.y : v.y / v.z); }
  /// The scan converter's depth key: larger is nearer, linear in screen space on a plane
  /// (1/zv for perspective, -zv for orthographic).
  double depth_key(double zv) const { return orthographic ? -zv : 1.0 / zv; }
};

/// A near-plane depth for a perspective view from \p eye: small against the distance to the
/// farthest corner of \p bounds (the 1/z depth key keeps its precision even so), so that in
/// practice nothing a ray could hit is clipped.
double near_plane_for(const Bounds3& bounds, Vec3 eye);

}  // namespace shadowkit
