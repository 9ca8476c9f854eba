#pragma once
/// \brief The closed solids of a scene whose far side, seen from outside, their own near side
/// hides: what lets a light skip the faces a solid shadows itself (svbsp, §6 of Chin &
/// Feiner's silhouette optimization in its simplest form) and a view skip the faces it
/// cannot see.
#include <cstdint>
#include <vector>

#include "shadowkit/core/vec.h"

namespace shadowkit {

struct Scene;

/// \brief The outward solids of a scene: the connected parts of closed, consistently oriented
/// meshes whose signed volume is positive (a part turned inside out, or a cavity's lining,
/// is none). A face of such a solid turned from a point outside it is hidden from that point
/// by the solid's faces turned toward it: a ray entering the solid there left it through one
/// of those.
class OutwardSolids {
 public:
  OutwardSolids() = default;
  explicit OutwardSolids(const Scene& scene);

  /// Whether global face \p face bounds an outward solid.
  bool bounds_solid(std::uint32_t face) const { return solid_[face] >= 0; }
  /// The solid global face \p face bounds, -1 for none.
  std::int32_t solid_of(std::uint32_t face) const { return solid_[face]; }
  /// How many solids there are.
  std::size_t size() const { return bounds_.size(); }
  /// Solid \p s's bounding box.
  const Bounds3& bounds(std::size_t s) const { return bounds_[s]; }
  /// Whether \p point lies outside solid \p s's bounding box.
  bool outside(std::size_t s, Vec3 point) const;
  /// Whether \p face is on the far side of its solid from \p point: it bounds an outward
  /// solid, its plane is turned from the point, and the point is outside the solid's box.
  bool far_side_from(const Scene& scene, std::uint32_t face, Vec3 point) const;
  /// Whether \p face is on the far side of its solid seen along \p direction from infinitely
  /// far: it bounds an outward solid and its plane is turned from the viewer.
  bool far_side_along(const Scene& scene, std::uint32_t face, Vec3 direction) const;
  /// The face tests of far_side_from and far_side_along alone, for a caller that knows the
  /// solid's part: whether a face's \p plane is turned from \p point, or from a viewer
  /// looking along \p direction.
  static bool turned_from(const Plane& plane, Vec3 point) { return plane.distance(point) < 0; }
  static bool turned_along(const Plane& plane, Vec3 direction) {
    return dot(plane.normal, direction) > 0;
  }

 private:
  std::vector<std::int32_t> solid_;  ///< per global face: its solid, -1 for none
  std::vector<Bounds3> bounds_;      ///< per solid
};

}  // namespace shadowkit
