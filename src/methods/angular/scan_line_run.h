#pragma once
// Runs along a scan line (discretized-shadow-volume paper, Secs. 6-7): where the answer of
// one lookup stops holding.
#include <vector>

#include "angular_table.h"
#include "light_frame.h"

namespace shadowkit::angular {

/// \brief The visible points of one receiver face along one scan line. The point seen at
/// column c is W(c) / D(c) in light-frame coordinates, with W and D linear in c, so every
/// plane condition is solved for c in closed form.
class ScanLineRun {
 public:
  ScanLineRun(const LightFrame& frame, const Camera& camera, const Plane& receiver, int row);

  /// Light-frame coordinates of the visible point at column \p c.
  Vec3 local(double c) const { return (m_ + n_ * c) / (dm_ + dn_ * c); }
  /// The column after \p c0 where the affine function \p f changes sign; +inf if none.
  double crossing(const FrameAffine& f, double c0) const;
  /// The column after \p c0 where phi takes the value \p phi (xEquivalentOf, Sec. 7); +inf.
  /// \p phi as AngularPoint keeps it (tan(phi) for a point light).
  double phi_crossing(double phi, double c0) const;
  /// phi grows with the column at column \p c (the sign of its derivative, no trigonometry).
  bool phi_increasing(double c) const;

 private:
  bool point_light_;
  Vec3 m_, n_;
  double dm_ = 0, dn_ = 0;
};

/// \brief The constant-theta planes between table entries, computed once per table so that
/// queries take no trigonometry.
class ThetaBoundaries {
 public:
  ThetaBoundaries() = default;
  ThetaBoundaries(const LightFrame& frame, const ThetaQuantization& q);

  /// The plane at the lower end of unwrapped entry \p k (k in [-1, R + 1], any k for a full
  /// turn); its value is >= 0 on the side of larger theta.
  const FrameAffine& lower(int k) const {
    if (q_.full_turn) k = ((k % q_.resolution) + q_.resolution) % q_.resolution;
    return planes_[std::size_t(k + 1)];
  }
  /// The unwrapped entry of the light-frame point \p v: found from \p guess, the entry of a
  /// nearby point, by the sides of the boundary planes; by eq. 2 when \p guess is -2 or far.
  int locate(Vec3 v, int guess) const;

 private:
  ThetaQuantization q_;
  bool point_light_ = true;
  std::vector<FrameAffine> planes_;  ///< k = -1 .. R + 1
};

/// Eq. 7, the maximum run length, solved exactly on the receiver's scan line instead of to
/// first order: the column after \p c0 where the visible point leaves theta entry \p k
/// (crosses the constant-theta plane at either end of the entry).
double max_run_end(const ScanLineRun& run, const ThetaBoundaries& bounds, int k, double c0);

}  // namespace shadowkit::angular
