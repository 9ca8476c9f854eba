#pragma once
#include <algorithm>

#include "shadowkit/core/vec.h"

namespace shadowkit::volume {

/// Distance from \p p to the segment [a, b].
inline double segment_distance(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return length(p - (a + ab * t));
}

}  // namespace shadowkit::volume
