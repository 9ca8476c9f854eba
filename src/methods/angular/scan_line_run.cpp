#include "scan_line_run.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowkit {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

// Hazard: a root within 1e-9 of c0 is c0 itself, not a change ahead.
double after(double root, double c0) {
  return std::isfinite(root) && root > c0 + 1e-9 ? root : kNever;
}

}  // namespace

ScanLineRun::ScanLineRun(const LightFrame& frame, const Camera& camera, const Plane& receiver,
                         int row)
    : point_light_(frame.point_light()) {
  const Camera::PixelGrid grid = camera.pixel_grid();
  const Vec3 a =
      camera.forward() + grid.x0 * camera.right() + (grid.y0 - grid.step * row) * camera.true_up();
  const Vec3 b = grid.step * camera.right();
  const Vec3 eye = camera.position - frame.origin();
  const double k0 = receiver.distance(camera.position);
  // Q(c) - origin = eye + t(c) ray(c), t = -k0 / D(c), D(c) = n . ray(c).
  dm_ = dot(receiver.normal, a);
  dn_ = dot(receiver.normal, b);
  m_ = frame.local_direction(eye * dm_ - a * k0);
  n_ = frame.local_direction(eye * dn_ - b * k0);
}

double ScanLineRun::crossing(const FrameAffine& f, double c0) const {
  const double at0 = f.at(m_, dm_), slope = f.at(n_, dn_);
  return slope == 0 ? kNever : after(-at0 / slope, c0);
}

double ScanLineRun::phi_crossing(double phi, double c0) const {
  if (!point_light_) return crossing({{1, 0, 0}, -phi}, c0);
  // The cone X = tan(phi) hypot(Y, F) (phi is kept as its tangent), squared: a quadratic in
  // c; a root counts when X / D there has the sign of phi.
  const double c2 = 1, s2 = phi * phi;
  const double qa = c2 * n_.x * n_.x - s2 * (n_.y * n_.y + n_.z * n_.z);
  const double qb = 2 * (c2 * m_.x * n_.x - s2 * (m_.y * n_.y + m_.z * n_.z));
  const double qc = c2 * m_.x * m_.x - s2 * (m_.y * m_.y + m_.z * m_.z);
  double roots[2] = {kNever, kNever};
  if (std::abs(qa) < 1e-300) {
    if (qb != 0) roots[0] = -qc / qb;
  } else {
    const double disc = qb * qb - 4 * qa * qc;
    if (disc < 0) return kNever;
    const double s = std::sqrt(disc);
    const double q = -0.5 * (qb + (qb >= 0 ? s : -s));  // stable roots
    roots[0] = q / qa;
    roots[1] = q != 0 ? qc / q : kNever;
  }
  double best = kNever;
  for (double c : roots) {
    if (!std::isfinite(c)) continue;
    const double x = (m_.x + n_.x * c) * (dm_ + dn_ * c);
    if (x * phi >= 0) best = std::min(best, after(c, c0));
  }
  return best;
}

double max_run_end(const ScanLineRun& run, const LightFrame& frame, const ThetaQuantization& q,
                   int k, double c0) {
  return std::min(run.crossing(frame.theta_plane(q.lower(k)), c0),
                  run.crossing(frame.theta_plane(q.lower(k + 1)), c0));
}

}  // namespace shadowkit
