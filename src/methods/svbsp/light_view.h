#pragma once
// The scene as one light sees it, in two coordinates whose lines are planes through the
// light: where the SVBSP tree may be cut into cells before any volume joins it (§6, "keep an
// SVBSP tree well-balanced, even at the expense of increased size").
#include <array>
#include <optional>

#include "shadowkit/scene/scene.h"

namespace shadowkit::svbsp {

/// \brief Two coordinates of space as seen from a light: the light's rays are the points of
/// equal coordinates, so a line of the view is a plane holding the light (a directional
/// light: holding its direction), which no shadow volume crosses differently on its sides.
class LightView {
 public:
  using Coordinates = std::array<double, 2>;

  /// The view of \p bounds from \p light: for a directional light the plane across it; for a
  /// point light the central projection onto a plane past which the whole box lies. Nothing
  /// when a point light is within the box (or too close to it): no such plane exists.
  static std::optional<LightView> of(const Light& light, const Bounds3& bounds);

  /// Where \p p lies in the view; only for points within the box.
  Coordinates coordinates(Vec3 p) const;
  /// The plane through the light holding the points whose coordinate \p axis (0 or 1) is
  /// \p value; the points of greater coordinate lie on its positive side.
  Plane plane(int axis, double value) const;

 private:
  LightView(const Light& light, Vec3 u, Vec3 v, Vec3 depth)
      : light_(light), axes_{u, v}, depth_(depth) {}

  Light light_;
  std::array<Vec3, 2> axes_;
  Vec3 depth_;  ///< a point light: the unit axis along which the box lies past the light
};

}  // namespace shadowkit::svbsp
