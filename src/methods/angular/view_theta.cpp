#include "view_theta.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "shadowkit/raster/projection.h"

namespace shadowkit {
namespace {

// The view frustum as five half-spaces f(p) >= 0 in camera coordinates (x right, y up,
// z forward), half a pixel wider than the pixel centres.
struct Frustum {
  Vec3 eye, right, up, forward;
  double near = 0, tan_x = 0, tan_y = 0;

  explicit Frustum(const Scene& scene) {
    const Camera& cam = scene.camera;
    const Camera::PixelGrid grid = cam.pixel_grid();
    eye = cam.position, right = cam.right(), up = cam.true_up(), forward = cam.forward();
    near = near_plane_for(scene.bounds(), eye);  // the camera pass's own
    tan_x = std::abs(grid.x0) + grid.step / 2;
    tan_y = std::abs(grid.y0) + grid.step / 2;
  }
  Vec3 camera(Vec3 p) const {
    const Vec3 v = p - eye;
    return {dot(v, right), dot(v, up), dot(v, forward)};
  }
  // Plane \p plane's value at camera coordinates \p c.
  double side(int plane, Vec3 c) const {
    switch (plane) {
      case 0:
        return c.z - near;
      case 1:
        return tan_x * c.z - c.x;
      case 2:
        return tan_x * c.z + c.x;
      case 3:
        return tan_y * c.z - c.y;
      default:
        return tan_y * c.z + c.y;
    }
  }
  bool holds(Vec3 p) const {
    const Vec3 c = camera(p);
    for (int plane = 0; plane < 5; ++plane) {
      if (side(plane, c) < 0) return false;
    }
    return true;
  }
};

// Sutherland-Hodgman: \p polygon clipped to the frustum.
std::vector<Vec3> clip(const Frustum& frustum, std::vector<Vec3> polygon) {
  std::vector<Vec3> out;
  for (int plane = 0; plane < 5 && !polygon.empty(); ++plane) {
    out.clear();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Vec3 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
      const double fa = frustum.side(plane, frustum.camera(a));
      const double fb = frustum.side(plane, frustum.camera(b));
      if (fa >= 0) out.push_back(a);
      if ((fa >= 0) != (fb >= 0)) out.push_back(a + (b - a) * (fa / (fa - fb)));
    }
    std::swap(polygon, out);
  }
  return polygon;
}

// The bounding box's six faces.
std::array<std::vector<Vec3>, 6> box_faces(const Bounds3& box) {
  const auto corner = [&](int i) {
    return Vec3{i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y,
                i & 4 ? box.hi.z : box.lo.z};
  };
  constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  std::array<std::vector<Vec3>, 6> faces;
  for (int f = 0; f < 6; ++f) {
    for (const int i : kFaces[f]) faces[f].push_back(corner(i));
  }
  return faces;
}

}  // namespace

ViewTheta view_theta(const Scene& scene, const LightFrame& frame) {
  const Frustum frustum(scene);
  ViewTheta view;
  view.lo = std::numeric_limits<double>::infinity();
  view.hi = -view.lo;
  for (const std::vector<Vec3>& face : box_faces(scene.bounds())) {
    for (const Vec3 p : clip(frustum, face)) {
      const Vec3 v = frame.local(p);
      if (frame.point_light() && std::hypot(v.y, v.z) <= 0) return {};  // on the light's axis
      const double theta = frame.angular_local(v).theta;
      view.lo = std::min(view.lo, theta);
      view.hi = std::max(view.hi, theta);
    }
  }
  // A convex region around the light's X axis has thetas in no arc shorter than pi.
  view.bounded =
      view.lo <= view.hi && !(frame.point_light() && view.hi - view.lo >= std::numbers::pi);
  return view;
}

double scan_line_theta(const Scene& scene, const LightFrame& frame) {
  const Frustum frustum(scene);
  const double row_step = scene.camera.pixel_grid().step;  // one scan line at unit depth
  std::vector<double> steps;
  for (const SceneObject& object : scene.objects) {
    for (const Vec3 p : object.mesh.vertices) {
      if (!frustum.holds(p)) continue;
      const Vec3 v = frame.local(p);
      const double rho = frame.point_light() ? std::hypot(v.y, v.z) : 1.0;
      if (rho > 0) steps.push_back(frustum.camera(p).z * row_step / rho);
    }
  }
  if (steps.empty()) return 0;
  const auto quartile = steps.begin() + steps.size() / 4;
  std::nth_element(steps.begin(), quartile, steps.end());
  return *quartile;
}

int automatic_resolution(const Scene& scene, double scan_line, double theta_range) {
  if (scan_line == 0) return scene.camera.height;
  // Sec. 3: beyond a limit set by the screen no entry shows; eight per scan line bound the
  // table when most vertices crowd the camera.
  return int(std::clamp(theta_range / scan_line, 1.0, 8.0 * scene.camera.height));
}

}  // namespace shadowkit
