#pragma once
// Lai & Cheng §4.2: the ray/triangle test with five dot products (after Badouel 1990).
#include "shadowkit/core/vec.h"

namespace shadowkit::voxel {

/// \brief The points origin + t direction for t in (t_min, t_max).
struct RaySegment {
  Vec3 origin, direction;
  double t_min = 0, t_max = 1;
};

/// Whether \p ray crosses triangle (v0, v1, v2): P_I, the ray's point in the triangle's
/// plane, is inside when s >= 0, t >= 0 and s + t <= 1, with s and t from the five dot
/// products of u = v1 - v0, v = v2 - v0 and w = P_I - v0. A ray in the plane and a
/// degenerate triangle never hit.
inline bool ray_hits_triangle(const RaySegment& ray, Vec3 v0, Vec3 v1, Vec3 v2) {
  const Vec3 u = v1 - v0, v = v2 - v0;
  const Vec3 n = cross(u, v);
  const double along = dot(n, ray.direction);
  if (along == 0) return false;
  const double t_plane = dot(n, v0 - ray.origin) / along;
  if (!(t_plane > ray.t_min && t_plane < ray.t_max)) return false;
  const Vec3 w = ray.origin + ray.direction * t_plane - v0;
  const double uu = dot(u, u), uv = dot(u, v), vv = dot(v, v), wu = dot(w, u), wv = dot(w, v);
  const double denominator = uv * uv - uu * vv;
  if (denominator == 0) return false;
  const double s = (uv * wv - vv * wu) / denominator;
  const double t = (uv * wu - uu * wv) / denominator;
  return s >= 0 && t >= 0 && s + t <= 1;
}

}  // namespace shadowkit::voxel
