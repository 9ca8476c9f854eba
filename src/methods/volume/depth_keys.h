#pragma once
// Depth keys along the camera's pixel rays: Crow's scan-line coherence (1977, Sec. VII) as
// range tests that settle whole spans, bands and tiles of pixels at once.
#include <algorithm>
#include <cmath>
#include <limits>

#include "shadowkit/scene/scene.h"

namespace shadowkit::volume {

/// Relative slack of the depth-key bounds. Rounding in the keys and in the exact plane test
/// is about 1e-15 relative; keys closer than this fall back to the exact test.
inline constexpr double kKeySlack = 1e-7;

/// \brief The depth key of a plane along the pixel rays: key = 1 / s where the ray
/// eye + s dir meets it (dir = forward + x right + y up, so s is the view depth). Linear in
/// the pixel column and row; a point is nearer than another on the same ray when its key is
/// larger, and a plane the ray meets behind the eye (or never) has key <= 0. "The visible
/// point lies beyond the polygon's plane" is exactly key(polygon) > key(visible point).
struct KeyPlane {
  double a = 0, b = 0, c = 0;  ///< key = a column + b row + c
  double slack = 0;            ///< bound on its rounding, with kKeySlack to spare
  double at(double column, double row) const { return a * column + b * row + c; }
};

/// \brief The camera's pixel-ray grid, computed once.
struct RayGrid {
  Vec3 eye, forward, right, up;
  Camera::PixelGrid grid;
  double x_extent, y_extent;  ///< bounds of |x| and |y| over the raster

  explicit RayGrid(const Camera& cam);
  /// The key plane of the plane n.p + d = 0, which must not pass through the eye.
  KeyPlane key_plane(Vec3 normal, double d) const;
};

/// \brief A range of depth keys; empty (lo = +inf, hi = -inf) when it holds none.
struct KeyRange {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double key) { lo = std::min(lo, key), hi = std::max(hi, key); }
  void add(const KeyRange& r) { lo = std::min(lo, r.lo), hi = std::max(hi, r.hi); }
  /// Widens the range by the slack, so that it bounds the exact keys.
  void widen() { lo -= kKeySlack * std::abs(lo), hi += kKeySlack * std::abs(hi); }
  bool empty() const { return lo > hi; }
};

/// Where the crossings of a polygon over some pixels lie, from its key range there.
enum class Crossing { all_before, all_behind, mixed };

/// Places a polygon whose keys over some pixels lie in [key_lo, key_hi] (each within
/// \p slack) against the visible keys of those pixels.
inline Crossing classify(double key_lo, double key_hi, double slack, const KeyRange& visible) {
  if (key_lo - slack > visible.hi) return Crossing::all_before;
  if (key_hi + slack < visible.lo) return Crossing::all_behind;
  return Crossing::mixed;
}

/// Places \p key over the pixels of columns [xa, xb] and rows [ya, yb] against their
/// \p visible keys: a plane's key is linear, so its corners bound it.
inline Crossing classify_rectangle(const KeyPlane& key, int xa, int xb, int ya, int yb,
                                   const KeyRange& visible) {
  const double k00 = key.at(xa, ya), k10 = key.at(xb, ya), k01 = key.at(xa, yb),
               k11 = key.at(xb, yb);
  return classify(std::min({k00, k10, k01, k11}), std::max({k00, k10, k01, k11}), key.slack,
                  visible);
}

/// The world-space box holding every point that pixel centres [x0, x1] x [y0, y1] see at
/// keys in \p keys (widened, not empty, positive): the corners of that piece of the view.
Bounds3 view_piece(const RayGrid& rays, int x0, int y0, int x1, int y1, const KeyRange& keys);

}  // namespace shadowkit::volume
