#include "light_view.h"

#include <cmath>

namespace shadowkit::svbsp {
namespace {

// Hazard: a box that nearly touches the light's plane across the depth axis projects to
// coordinates of unbounded size; past this share of its diagonal it is refused.
constexpr double kMinClearance = 1e-3;

Vec3 unit_axis(int axis, double sign) {
  Vec3 e;
  e[axis] = sign;
  return e;
}

}  // namespace

std::optional<LightView> LightView::of(const Light& light, const Bounds3& bounds) {
  if (bounds.empty()) return std::nullopt;
  if (light.type == Light::Type::directional) {
    const Vec3 d = light.direction;
    const Vec3 other = std::abs(d.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = normalize(cross(d, other));
    return LightView(light, u, cross(d, u), {});
  }
  // The depth axis: the signed axis along which the nearest corner of the box lies farthest
  // past the light.
  int best_axis = -1;
  double best_sign = 0, best_gap = kMinClearance * bounds.diagonal();
  for (int axis = 0; axis < 3; ++axis) {
    for (const double sign : {1.0, -1.0}) {
      const double gap = sign > 0 ? bounds.lo[axis] - light.position[axis]
                                  : light.position[axis] - bounds.hi[axis];
      if (gap > best_gap) best_axis = axis, best_sign = sign, best_gap = gap;
    }
  }
  if (best_axis < 0) return std::nullopt;
  return LightView(light, unit_axis((best_axis + 1) % 3, 1), unit_axis((best_axis + 2) % 3, 1),
                   unit_axis(best_axis, best_sign));
}

LightView::Coordinates LightView::coordinates(Vec3 p) const {
  if (light_.type == Light::Type::directional) return {dot(axes_[0], p), dot(axes_[1], p)};
  const Vec3 r = p - light_.position;
  const double depth = dot(depth_, r);
  return {dot(axes_[0], r) / depth, dot(axes_[1], r) / depth};
}

Plane LightView::plane(int axis, double value) const {
  if (light_.type == Light::Type::directional) return {axes_[std::size_t(axis)], -value};
  // axis·r - value * depth·r = 0 holds the light; scaled by depth·r > 0 it keeps the sign
  // of coordinate - value.
  const Vec3 n = axes_[std::size_t(axis)] - depth_ * value;
  const double len = length(n);
  const Vec3 unit = n / len;
  return {unit, -dot(unit, light_.position)};
}

}  // namespace shadowkit::svbsp
