#pragma once
// The light's frame and the angular coordinates (r, theta, phi) of Thakur, Cheng & Miura
// (discretized-shadow-volume paper, Sec. 3, eqs. 1-3).
#include <cmath>

#include "shadowkit/scene/scene.h"

namespace shadowkit::angular {

/// \brief A point in angular coordinates: distance r, scan-line angle theta, and phi along
/// the constant-theta plane, kept as tan(phi) for a point light (eq. 3 before its arctangent:
/// monotone in phi, so pairs sort and compare alike, and no arctangent is ever taken).
struct AngularPoint {
  double r = 0, theta = 0, phi = 0;
};

/// \brief An affine function a . v + b w of homogeneous light-frame coordinates (v, w);
/// its zero set is a plane (a constant-theta plane, a constant-phi plane of a directional
/// light, or a face plane).
struct FrameAffine {
  Vec3 a;
  double b = 0;
  double at(Vec3 v, double w = 1) const { return dot(a, v) + b * w; }
};

/// Eq. 2 of a light-frame point, as LightFrame::angular_local gives it, knowing only the
/// light's kind: for code that holds light-frame points but no frame.
inline double local_theta(Vec3 v, bool point_light) {
  return point_light ? std::atan2(v.y, v.z) : v.y;
}

/// \brief The frame fixed to the light whose XY plane is parallel to the camera's
/// projection plane (Sec. 3, Fig. 18), so that lines along the camera's right axis are
/// constant-theta lines.
///
/// Point light: local coordinates (X, Y, F) with X along the camera's right axis, Y along
/// its up axis and F = -Z along its forward axis. theta = atan2(Y, F) (eq. 2 extended to the
/// whole turn: the two hemispheres of Sec. 11.2 are |theta| < pi/2 and beyond, so a light
/// inside the scene needs no split), tan(phi) = X / hypot(Y, F) (eq. 3 measured inside
/// the constant-theta half-plane; within one theta it orders points as eq. 3 does),
/// r = |p - light| (eq. 1).
/// Directional light: the parallel projection. theta-planes are the planes holding the
/// camera's right axis and the light direction d, or, when d runs along that axis (within
/// 1e-9 rad), d and the camera's forward axis; local coordinates (phi, theta, r) are
/// orthonormal, left-handed, with r along d and the origin at \p scene_center.
class LightFrame {
 public:
  LightFrame(const Light& light, const Camera& camera, Vec3 scene_center);

  bool point_light() const { return point_; }
  /// Light-frame coordinates of a world point.
  Vec3 local(Vec3 p) const { return local_direction(p - origin_); }
  /// Light-frame components of a world direction.
  Vec3 local_direction(Vec3 v) const {
    return {dot(v, axis_[0]), dot(v, axis_[1]), dot(v, axis_[2])};
  }
  Vec3 origin() const { return origin_; }

  /// Eqs. 1-3 of a light-frame point.
  AngularPoint angular_local(Vec3 v) const;
  AngularPoint angular(Vec3 p) const { return angular_local(local(p)); }
  /// phi alone (eq. 3) of a light-frame point, as AngularPoint keeps it.
  double phi_local(Vec3 v) const { return point_ ? v.x / std::sqrt(v.y * v.y + v.z * v.z) : v.x; }

  /// The constant-theta plane at \p theta (for a point light it also holds theta + pi).
  FrameAffine theta_plane(double theta) const;
  /// A world plane in light-frame coordinates.
  FrameAffine plane(const Plane& world) const;
  /// The plane swept by the light's rays through the light-frame segment \p a \p b.
  FrameAffine ray_plane(Vec3 a, Vec3 b) const;

 private:
  bool point_ = true;
  Vec3 origin_;
  Vec3 axis_[3];
};

}  // namespace shadowkit::angular
