#include "view_theta.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "angular_lookup.h"
#include "shadowkit/raster/projection.h"
#include "shadowkit/raster/view_frustum.h"

namespace shadowkit::angular {
namespace {

// The camera's view, with the near plane of the camera pass.
ViewFrustum view_of(const Scene& scene) {
  return ViewFrustum::of(scene.camera, near_plane_for(scene.bounds(), scene.camera.position));
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

namespace {

// Receiver triangles larger than this share of the image are integrated in quarters (down
// to kSplitDepth levels): the theta of a pixel changes across a large face such as a ground.
// A share, not pixels, so that the integral takes the same samples at any image size.
constexpr double kSplitShare = 1.0 / 64;
constexpr int kSplitDepth = 4;

// Faces per task of the integral: fixed blocks, so that its sum is the same on every run.
constexpr std::uint32_t kFaceBlock = 1024;

// The integral of pixel_theta, over some receivers: their screen area and the area over the
// theta of a pixel.
struct PixelThetaSum {
  double area = 0, entries = 0;
  PixelThetaSum& operator+=(const PixelThetaSum& o) {
    area += o.area, entries += o.entries;
    return *this;
  }
};

// What pixel_theta integrates a face with: the camera's pixels and the light's theta.
class ReceiverIntegral {
 public:
  ReceiverIntegral(const Scene& scene, const LightFrame& frame)
      : frame_(frame),
        eye_(scene.camera.position),
        forward_(scene.camera.forward()),
        step_(scene.camera.pixel_grid().step),
        right_(scene.camera.right() * step_),
        up_(scene.camera.true_up() * step_),
        split_pixels_(kSplitShare * scene.camera.width * scene.camera.height) {}

  // A face with world plane \p plane, wholly within the view: one sample at its corners'
  // mean where it is small on screen, else its fan of triangles.
  void polygon(const Plane& plane, std::span<const Vec3> corners, PixelThetaSum& sum) const {
    double area = 0;
    Vec3 mean{};
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      area += pixel_area(corners[0], corners[k], corners[k + 1]);
    }
    if (!(area > 0)) return;
    if (area > split_pixels_) {
      for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
        triangle(plane, corners[0], corners[k], corners[k + 1], 0, sum);
      }
      return;
    }
    for (const Vec3 p : corners) mean = mean + p;
    add(plane, mean * (1.0 / double(corners.size())), area, sum);
  }

  // Triangle abc of a face with world plane \p plane, already within the view.
  void triangle(const Plane& plane, Vec3 a, Vec3 b, Vec3 c, int depth, PixelThetaSum& sum) const {
    const double area = pixel_area(a, b, c);
    if (!(area > 0)) return;
    if (area > split_pixels_ && depth < kSplitDepth) {
      const Vec3 ab = (a + b) * 0.5, bc = (b + c) * 0.5, ca = (c + a) * 0.5;
      triangle(plane, a, ab, ca, depth + 1, sum);
      triangle(plane, ab, b, bc, depth + 1, sum);
      triangle(plane, ca, bc, c, depth + 1, sum);
      triangle(plane, ab, bc, ca, depth + 1, sum);
      return;
    }
    add(plane, (a + b + c) * (1.0 / 3), area, sum);
  }

 private:
  // A sample at \p p standing for \p area pixels.
  void add(const Plane& plane, Vec3 p, double area, PixelThetaSum& sum) const {
    const double theta = pixel_theta_at(plane, p);
    if (!(theta > 0) || !std::isfinite(theta)) return;
    sum.area += area;
    sum.entries += area / theta;
  }

  // The screen area of a triangle in front of the eye, in pixels.
  double pixel_area(Vec3 a, Vec3 b, Vec3 c) const {
    const auto screen = [&](Vec3 p) {
      const Vec3 d = p - eye_;
      const double w = dot(d, forward_);
      return std::pair{dot(d, right_) / (w * step_ * step_), dot(d, up_) / (w * step_ * step_)};
    };
    const auto [ax, ay] = screen(a);
    const auto [bx, by] = screen(b);
    const auto [cx, cy] = screen(c);
    return std::abs((bx - ax) * (cy - ay) - (cx - ax) * (by - ay)) / 2;
  }

  // The theta of one pixel at point p of a receiver with world plane \p plane: the norm of
  // theta's gradient across the image there. 0 where the light grazes the receiver (the
  // exact re-check answers there, Sec. "Faces the light grazes" of the method page).
  double pixel_theta_at(const Plane& plane, Vec3 p) const {
    const Vec3 v = frame_.local(p);
    const Vec3 n = frame_.local_direction(plane.normal);  // a unit normal
    const double sine = frame_.point_light() ? std::abs(dot(n, v)) / length(v) : std::abs(n.z);
    if (!(sine >= kGrazingSine)) return 0;
    // The point where the ray through a pixel one step away meets the plane: the ray (of
    // unit depth) r moves by the step d, the point by depth (d - r (n.d) / (n.r)).
    const Vec3 d = p - eye_;
    const double depth = dot(d, forward_);
    const Vec3 r = d * (1 / depth);
    const double nr = dot(plane.normal, r);
    const auto moved = [&](Vec3 step) {
      return frame_.local_direction((step - r * (dot(plane.normal, step) / nr)) * depth);
    };
    const auto theta_change = [&](Vec3 m) {
      if (!frame_.point_light()) return m.y;
      return (v.z * m.y - v.y * m.z) / (v.y * v.y + v.z * v.z);
    };
    const double across = theta_change(moved(right_)), down = theta_change(moved(up_));
    return std::sqrt(across * across + down * down);
  }

  const LightFrame& frame_;
  Vec3 eye_, forward_;
  double step_;
  Vec3 right_, up_;  // one pixel at unit depth
  double split_pixels_;
};

}  // namespace

double entries_per_pixel(double pixels) {
  return std::max(kLeastEntriesPerPixel, kEntriesPerPixel * std::sqrt(kReferencePixels / pixels));
}

double entry_theta(const Scene& scene, const LightFrame& frame) {
  const ViewFrustum frustum = view_of(scene);
  const ReceiverIntegral integral(scene, frame);
  // Fixed blocks of the scene's faces, each with its own sum.
  const std::uint32_t faces = scene.face_count();
  std::vector<PixelThetaSum> sums((faces + kFaceBlock - 1) / kFaceBlock);
  tbb::parallel_for(std::size_t(0), sums.size(), [&](std::size_t i) {
    const std::uint32_t first = std::uint32_t(i) * kFaceBlock;
    const std::uint32_t last = std::min(first + kFaceBlock, faces);
    std::vector<Vec3> corners;
    for (std::uint32_t face = first; face < last; ++face) {
      const Mesh& mesh = scene.objects[scene.object_of_face(face)].mesh;
      const std::uint32_t f = scene.local_face(face);
      const Plane& plane = scene.face_plane(face);
      // Contract condition 1: only a face whose seen side the light faces can be lit.
      const double light = frame.point_light() ? plane.distance(frame.origin())
                                               : -frame.local_direction(plane.normal).z;
      if (!(plane.distance(scene.camera.position) * light > 0)) continue;
      const std::uint32_t n = mesh.face_size(f);
      corners.resize(n);
      bool held = true;
      for (std::uint32_t k = 0; k < n; ++k) {
        corners[k] = mesh.vertices[mesh.face_vertex(f, k)];
        held = held && frustum.holds(corners[k]);
      }
      if (held) {
        integral.polygon(plane, corners, sums[i]);
        continue;
      }
      if (frustum.excludes(corners)) continue;
      for (std::uint32_t k = 1; k + 1 < n; ++k) {  // a fan; each triangle cut to the view
        const std::vector<Vec3> cut = frustum.clip({corners[0], corners[k], corners[k + 1]});
        for (std::size_t j = 1; j + 1 < cut.size(); ++j) {
          integral.triangle(plane, cut[0], cut[j], cut[j + 1], 0, sums[i]);
        }
      }
    }
  });
  PixelThetaSum total;
  for (const PixelThetaSum& s : sums) total += s;
  // The harmonic mean over the receivers' area: an entry of that theta is one pixel wide,
  // on average over the pixels.
  if (!(total.entries > 0)) return 0;
  return total.area / total.entries / entries_per_pixel(total.area);
}

int automatic_resolution(const Scene& scene, double entry, double theta_range) {
  if (entry == 0) return scene.camera.height;
  // The bound keeps the table's size sensible where the receivers hardly change theta
  // across the image (a full turn of which the view sees a sliver).
  return int(std::clamp(theta_range / entry, 1.0, double(kMostAutomaticEntries)));
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
