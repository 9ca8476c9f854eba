#include "depth_keys.h"

namespace shadowkit::volume {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

RayGrid::RayGrid(const Camera& cam)
    : eye(cam.position),
      forward(cam.forward()),
      right(cam.right()),
      up(cam.true_up()),
      grid(cam.pixel_grid()),
      x_extent(std::abs(grid.x0) + grid.step * cam.width),
      y_extent(std::abs(grid.y0) + grid.step * cam.height) {}

KeyPlane RayGrid::key_plane(Vec3 normal, double d) const {
  const double nf = dot(normal, forward), nr = dot(normal, right), nu = dot(normal, up);
  const double e = dot(normal, eye) + d;  // nonzero: the eye is off every plane it sees
  KeyPlane k;
  k.a = -grid.step * nr / e;
  k.b = grid.step * nu / e;
  k.c = -(nf + grid.x0 * nr + grid.y0 * nu) / e;
  k.slack =
      kKeySlack * (std::abs(nf) + x_extent * std::abs(nr) + y_extent * std::abs(nu)) / std::abs(e);
  return k;
}

Bounds3 view_piece(const RayGrid& rays, int x0, int y0, int x1, int y1, const KeyRange& keys) {
  Bounds3 box;
  if (!(keys.lo > 0)) return {Vec3{1, 1, 1} * -kInf, Vec3{1, 1, 1} * kInf};
  for (int c = 0; c < 8; ++c) {
    const double x = rays.grid.x0 + rays.grid.step * (c & 1 ? x1 : x0);
    const double y = rays.grid.y0 - rays.grid.step * (c & 2 ? y1 : y0);
    const double s = 1 / (c & 4 ? keys.lo : keys.hi);
    box.add(rays.eye + (rays.forward + rays.right * x + rays.up * y) * s);
  }
  // Hazard: rounding of the corners, about 1e-16 of their magnitude.
  const double scale = std::max({std::abs(box.lo.x), std::abs(box.lo.y), std::abs(box.lo.z),
                                 std::abs(box.hi.x), std::abs(box.hi.y), std::abs(box.hi.z)});
  const Vec3 margin = Vec3{1, 1, 1} * (1e-12 * scale + 1e-300);
  return {box.lo - margin, box.hi + margin};
}

}  // namespace shadowkit::volume
