#include "volume_culling.h"

#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace shadowkit::volume {
namespace {

double max_abs(Vec3 v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// Hazard: a relative margin, far above the rounding of planes and distances among the points
// of the reach, the box and the light (about 1e-16 of their magnitude), far below any
// scene's features.
double tolerance(const Bounds3& box, const Light& light, const Reach& reach) {
  double scale = std::max({max_abs(box.lo), max_abs(box.hi), box.diagonal()});
  if (!reach.box.empty()) scale = std::max({scale, max_abs(reach.box.lo), max_abs(reach.box.hi)});
  if (light.type == Light::Type::point) scale = std::max(scale, max_abs(light.position));
  return 1e-9 * scale + 1e-300;
}

Bounds3 widened(const Bounds3& box, double margin) {
  return {box.lo - Vec3{1, 1, 1} * margin, box.hi + Vec3{1, 1, 1} * margin};
}

// Whether the box's face on \p side of \p axis (0: lo, 1: hi) faces the light.
bool face_lit(const Bounds3& box, int axis, int side, const Light& light) {
  if (light.type == Light::Type::directional) {
    return side ? light.direction[axis] < 0 : light.direction[axis] > 0;
  }
  return side ? light.position[axis] > box.hi[axis] : light.position[axis] < box.lo[axis];
}

}  // namespace

ShadowFrustum::ShadowFrustum(const Bounds3& tight, const Light& light, const Reach& reach,
                             const ViewFrustum* view)
    : light_(light), tolerance_(tolerance(tight, light, reach)) {
  const Bounds3 box = widened(tight, tolerance_);
  const bool point = light.type == Light::Type::point;
  // Within the reach the region lies in the hull of the box's corners and the corners pushed
  // away from the light until they leave it: a point light at distance g from the box
  // needs them pushed to reach / g times their distance.
  double push = 0;
  if (point) {
    const double gap = box.distance(light.position);
    if (gap == 0) {  // the light inside the box: the volume surrounds it
      everywhere_ = true;
      return;
    }
    push = std::max(reach.limit / gap, 1.0);
  }
  std::array<Vec3, 16> hull;
  for (int c = 0; c < 8; ++c) {
    const Vec3 p = box.corner(c);
    hull[c] = p;
    hull[8 + c] = point
                      ? light.position + (p - light.position) * push
                      : p + light.direction * std::max(0.0, reach.limit - dot(p, light.direction));
  }
  for (const Vec3& p : hull) hull_box_.add(p);
  hull_box_ = widened(hull_box_, tolerance_);
  reaches_view_ = !view || !view->excludes(hull);

  const Vec3 centre = box.center();
  for (int a = 0; a < 3; ++a) {
    // Behind a light-facing face.
    for (int side = 0; side < 2; ++side) {
      if (!face_lit(box, a, side, light)) continue;
      Vec3 n{};
      n[a] = side ? -1 : 1;
      set_plane(plane_count_++, {n, side ? box.hi[a] : -box.lo[a]});
    }
    // Inside the plane through the light and each contour edge along axis a, between the
    // faces on sides (sb, sc) of the other two axes.
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (int sb = 0; sb < 2; ++sb) {
      for (int sc = 0; sc < 2; ++sc) {
        if (face_lit(box, b, sb, light) == face_lit(box, c, sc, light)) continue;
        Vec3 p0 = box.lo, p1;
        p0[b] = sb ? box.hi[b] : box.lo[b];
        p0[c] = sc ? box.hi[c] : box.lo[c];
        p1 = p0;
        p1[a] = box.hi[a];
        const Vec3 n = normalize(cross(p1 - p0, point ? light.position - p0 : light.direction));
        if (!is_finite(n)) continue;  // the light on the edge's line: no plane, no cull
        const Plane plane{n, -dot(n, p0)};
        set_plane(plane_count_++,
                  plane.distance(centre) >= 0 ? plane : Plane{-plane.normal, -plane.d});
      }
    }
  }
}

void ShadowFrustum::cut(std::span<const Vec3> corners, const Plane& plane) {
  if (everywhere_ || plane.normal == Vec3{}) return;  // the plane at infinity bounds nothing
  if (cuts_ == kMaxPlanes || !is_finite(plane.normal)) {
    lost_ = true;
    return;
  }
  double lo = INFINITY, hi = -INFINITY;
  for (const Vec3& p : corners) {
    const double d = plane.distance(p);
    lo = std::min(lo, d), hi = std::max(hi, d);
  }
  const bool positive = lo >= -tolerance_, negative = hi <= tolerance_;
  if (!positive && !negative) {  // corners on both sides
    lost_ = true;
    return;
  }
  // The corners' side; the one away from the light when they all lie on the plane.
  Plane inward = plane;
  if (!positive || (negative && light_side(plane, light_) > 0)) inward = {-plane.normal, -plane.d};
  const double light_at = light_side(inward, light_);
  if (light_at > (light_.type == Light::Type::point ? tolerance_ : 1e-12)) return;
  volume_planes_[cuts_] = inward;
  // Moved out past the corners' tolerance and the rounding of later tests.
  inward.d += 2 * tolerance_;
  // Cuts go first: they are the tighter. Without room, the box plane in the way goes.
  if (plane_count_ < kMaxPlanes) set_plane(plane_count_++, this->plane(cuts_));
  set_plane(cuts_++, inward);
}

bool ShadowFrustum::misses(const Bounds3& r) const {
  if (everywhere_) return false;
  const Bounds3& h = hull_box_;
  if (r.hi.x < h.lo.x || r.hi.y < h.lo.y || r.hi.z < h.lo.z || r.lo.x > h.hi.x || r.lo.y > h.hi.y ||
      r.lo.z > h.hi.z) {
    return true;
  }
#if defined(__SSE2__)
  // Two planes at a time: the box corner farthest along each normal, per component the
  // larger of n lo and n hi.
  const __m128d lx = _mm_set1_pd(r.lo.x), ly = _mm_set1_pd(r.lo.y), lz = _mm_set1_pd(r.lo.z);
  const __m128d hx = _mm_set1_pd(r.hi.x), hy = _mm_set1_pd(r.hi.y), hz = _mm_set1_pd(r.hi.z);
  for (int k = 0; k < plane_count_; k += 2) {
    const __m128d x = _mm_load_pd(&nx_[std::size_t(k)]), y = _mm_load_pd(&ny_[std::size_t(k)]);
    const __m128d z = _mm_load_pd(&nz_[std::size_t(k)]);
    const __m128d far =
        _mm_add_pd(_mm_add_pd(_mm_add_pd(_mm_max_pd(_mm_mul_pd(x, lx), _mm_mul_pd(x, hx)),
                                         _mm_max_pd(_mm_mul_pd(y, ly), _mm_mul_pd(y, hy))),
                              _mm_max_pd(_mm_mul_pd(z, lz), _mm_mul_pd(z, hz))),
                   _mm_load_pd(&nd_[std::size_t(k)]));
    if (_mm_movemask_pd(_mm_cmplt_pd(far, _mm_setzero_pd()))) return true;
  }
  return false;
#else
  for (int k = 0; k < plane_count_; ++k) {
    const Plane p = plane(k);
    const Vec3 n = p.normal;
    const Vec3 farthest{n.x > 0 ? r.hi.x : r.lo.x, n.y > 0 ? r.hi.y : r.lo.y,
                        n.z > 0 ? r.hi.z : r.lo.z};
    if (p.distance(farthest) < 0) return true;
  }
  return false;
#endif
}

}  // namespace shadowkit::volume
