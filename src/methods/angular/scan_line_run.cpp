#include "scan_line_run.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace shadowkit::angular {
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

bool ScanLineRun::phi_increasing(double c) const {
  const Vec3 w = m_ + n_ * c;
  const double d = dm_ + dn_ * c;
  // Point light: tan(phi) = W.x sign(D) / |W.yz|; directional: phi = W.x / D.
  const double slope = point_light_
                           ? (n_.x * (w.y * w.y + w.z * w.z) - w.x * (w.y * n_.y + w.z * n_.z)) * d
                           : n_.x * d - w.x * dn_;
  return slope >= 0;
}

ThetaBoundaries::ThetaBoundaries(const LightFrame& frame, const ThetaQuantization& q)
    : q_(q), point_light_(frame.point_light()) {
  planes_.resize(std::size_t(q.resolution) + 3);
  tbb::parallel_for(-1, q.resolution + 2,
                    [&](int k) { planes_[std::size_t(k + 1)] = frame.theta_plane(q.lower(k)); });
}

int ThetaBoundaries::locate(Vec3 v, int guess) const {
  // A plane's side tells theta's side only within half a turn of it.
  constexpr int kReach = 4;
  if (guess != -2 && (!point_light_ || q_.widest() * kReach < std::numbers::pi / 2)) {
    int k = guess;
    for (int step = 0; step < kReach; ++step) {
      if (!q_.full_turn && (k < 0 || k >= q_.resolution)) break;
      if (lower(k).at(v) < 0) {
        --k;
      } else if (lower(k + 1).at(v) >= 0) {
        ++k;
      } else {
        return k;
      }
    }
  }
  return q_.index(point_light_ ? std::atan2(v.y, v.z) : v.y);
}

double max_run_end(const ScanLineRun& run, const ThetaBoundaries& bounds, int k, double c0) {
  return std::min(run.crossing(bounds.lower(k), c0), run.crossing(bounds.lower(k + 1), c0));
}

}  // namespace shadowkit::angular
