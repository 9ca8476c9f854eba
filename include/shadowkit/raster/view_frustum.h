#pragma once
/// \brief The camera's viewing volume as planes, and polygon clipping against planes: what
/// the methods use to keep to the part of the scene the camera can see.
#include <array>
#include <span>
#include <vector>

#include "shadowkit/core/vec.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// \brief The near plane and the four side planes through the eye and the outer edges of
/// the outermost pixels, normals pointing inward. There is no far plane.
struct ViewFrustum {
  std::array<Plane, 5> planes;  ///< the near plane, then the sides
  /// The near plane's rectangle, its corners in the sides' order: with the sides' edges
  /// beyond it, what bounds the view where no scene face does (an eye inside the scene).
  std::array<Vec3, 4> near_corners;
  /// The radius around the eye of the part of the view in front of the near plane.
  double near_radius = 0;

  /// \p near is a view-space depth; 0 puts the near plane through the eye.
  static ViewFrustum of(const Camera& camera, double near);
  bool holds(Vec3 p) const;
  /// All of \p points lie outside one of the planes.
  bool excludes(std::span<const Vec3> points) const;
  /// The part of the convex \p polygon inside the frustum (empty when none).
  std::vector<Vec3> clip(std::vector<Vec3> polygon) const;
};

/// Sutherland-Hodgman: the part of the convex \p polygon where plane.distance >= 0.
std::vector<Vec3> clip_polygon(std::span<const Vec3> polygon, const Plane& plane);

/// The six planes of \p box, normals inward (for clip_polygon).
std::array<Plane, 6> box_planes(const Bounds3& box);

}  // namespace shadowkit
