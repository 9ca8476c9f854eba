#pragma once
// Crow's bounding-box tests (Sec. VI, Fig. 3), applied to whole shadow volumes.
#include <array>
#include <span>

#include "shadow_polygon.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// \brief The camera's viewing volume: four side planes through the eye and the near plane,
/// normals pointing inward.
struct ViewFrustum {
  std::array<Plane, 5> planes;
  /// The radius around the eye of the part of the view in front of the near plane.
  double near_radius = 0;

  static ViewFrustum of(const Camera& camera, double near);
  /// All of \p points lie outside one of the planes.
  bool excludes(std::span<const Vec3> points) const;
};

/// Whether the shadow volume of anything inside \p box (the box and the space behind it,
/// seen from the light, up to \p reach) can meet the view. When it cannot, no visible point
/// lies in it and its caster is skipped.
bool shadow_volume_reaches_view(const Bounds3& box, const Light& light, const Reach& reach,
                                const ViewFrustum& view);

}  // namespace shadowkit
