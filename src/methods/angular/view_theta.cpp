#include "view_theta.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "shadowkit/raster/projection.h"
#include "shadowkit/raster/view_frustum.h"

namespace shadowkit::angular {
namespace {

// The camera's view, with the near plane of the camera pass.
ViewFrustum view_of(const Scene& scene) {
  return ViewFrustum::of(scene.camera, near_plane_for(scene.bounds(), scene.camera.position));
}

// The distance from the light's X axis, with hypot's care only where the squares leave the
// normal doubles (hypot costs as much as the rest of eq. 4's work on a vertex).
double axis_distance(Vec3 v) {
  const double squares = v.y * v.y + v.z * v.z;
  constexpr double kLeast = std::numeric_limits<double>::min();
  constexpr double kMost = std::numeric_limits<double>::max();
  return squares >= kLeast && squares <= kMost ? std::sqrt(squares) : std::hypot(v.y, v.z);
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
  const ViewFrustum frustum = view_of(scene);
  const Bounds3 box = scene.bounds();
  // The corners of the part of the box in view: its faces within the frustum, and, when the
  // eye is inside the box, the near plane's rectangle within the box. Theta takes its
  // extremes over a convex region at its corners (a constant-theta set is a half-space, or
  // a wedge about the light's axis).
  std::vector<std::vector<Vec3>> boundary;
  for (const std::vector<Vec3>& face : box_faces(box)) boundary.push_back(frustum.clip(face));
  std::vector<Vec3> near(frustum.near_corners.begin(), frustum.near_corners.end());
  for (const Plane& plane : box_planes(box)) near = clip_polygon(near, plane);
  boundary.push_back(std::move(near));
  ViewTheta view;
  view.lo = std::numeric_limits<double>::infinity();
  view.hi = -view.lo;
  for (const std::vector<Vec3>& polygon : boundary) {
    for (const Vec3 p : polygon) {
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
  const ViewFrustum frustum = view_of(scene);
  const Camera& camera = scene.camera;
  const double row_step = camera.pixel_grid().step;  // one scan line at unit depth
  // Per thread, in parallel over objects: the quartile does not depend on their order.
  tbb::enumerable_thread_specific<std::vector<double>> thread_steps;
  tbb::parallel_for(std::size_t(0), scene.objects.size(), [&](std::size_t o) {
    std::vector<double>& steps = thread_steps.local();
    for (const Vec3 p : scene.objects[o].mesh.vertices) {
      if (!frustum.holds(p)) continue;
      const Vec3 v = frame.local(p);
      const double rho = frame.point_light() ? axis_distance(v) : 1.0;
      if (rho > 0) steps.push_back(dot(p - camera.position, camera.forward()) * row_step / rho);
    }
  });
  std::vector<double> steps;
  for (const std::vector<double>& some : thread_steps) {
    steps.insert(steps.end(), some.begin(), some.end());
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

double farthest_depth(const Scene& scene, const LightFrame& frame) {
  const ViewFrustum frustum = view_of(scene);
  const Camera& camera = scene.camera;
  double farthest = -1, z_f = 0;
  for (const SceneObject& object : scene.objects) {
    for (const Vec3 p : object.mesh.vertices) {
      if (!frustum.holds(p)) continue;
      const Vec3 v = frame.local(p);
      const double r = length(v);
      if (r <= farthest) continue;
      farthest = r;
      // One scan line at the vertex spans its camera depth times the row step.
      z_f = std::abs(v.z) / (dot(p - camera.position, camera.forward()) * camera.pixel_grid().step);
    }
  }
  return z_f;
}

int eq4_resolution(const Scene& scene, double z_f, double theta_lo, double theta_hi,
                   bool point_light) {
  const double cap = 8.0 * scene.camera.height;
  if (!point_light || z_f == 0) return scene.camera.height;
  if (theta_lo <= -std::numbers::pi / 2 || theta_hi >= std::numbers::pi / 2) return int(cap);
  return int(std::clamp(z_f * (std::tan(theta_hi) - std::tan(theta_lo)), 1.0, cap));
}

}  // namespace shadowkit::angular
