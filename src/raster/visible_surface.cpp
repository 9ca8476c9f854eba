#include "shadowkit/raster/visible_surface.h"

#include <algorithm>
#include <cmath>

namespace shadowkit {

std::size_t VisibleSurfaceBuffer::covered_count() const {
  return std::size_t(std::count_if(face.begin(), face.end(), [](auto f) { return f != kNoFace; }));
}

std::vector<std::uint32_t> VisibleSurfaceBuffer::object_ids() const {
  std::vector<std::uint32_t> ids(face.size());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = object(i);
  return ids;
}

void VisibleSurfaceBuffer::bind(const Scene& scene) {
  const Camera& cam = scene.camera;
  scene_ = &scene;
  forward_ = cam.forward();
  right_ = cam.right();
  up_ = cam.true_up();
  // Contract: x = (2 (c + 0.5) / W - 1) t W / H, y = (1 - 2 (w + 0.5) / H) t.
  const double t = cam.tan_half_fov();
  step_ = 2.0 * t / cam.height;
  x_base_ = -t * cam.width / cam.height + 0.5 * step_;
  y_base_ = t - 0.5 * step_;
}

Vec3 VisibleSurfaceBuffer::ray(std::size_t i) const {
  const double x = x_base_ + step_ * double(i % std::size_t(width));
  const double y = y_base_ - step_ * double(i / std::size_t(width));
  return forward_ + x * right_ + y * up_;
}

Vec3 VisibleSurfaceBuffer::point(std::size_t i) const {
  const Vec3 eye = scene_->camera.position, dir = ray(i);
  const Plane& plane = scene_->face_plane(face[i]);
  return eye + dir * (-plane.distance(eye) / dot(plane.normal, dir));
}

double camera_near_plane(const Scene& scene) {
  // Relative to the farthest scene point: the 1/z depth key keeps its precision even for a
  // tiny near distance, and a ray can only miss geometry closer than this.
  const Bounds3& b = scene.bounds();
  if (b.empty()) return 1e-6;
  const Vec3 far = max(b.hi - scene.camera.position, scene.camera.position - b.lo);
  return std::max(length(far) * 1e-7, 1e-300);
}

void render_visible_surfaces(const Scene& scene, const Context& ctx, VisibleSurfaceBuffer& vsb) {
  const Camera& cam = scene.camera;
  vsb.bind(scene);
  vsb.width = cam.width;
  vsb.height = cam.height;
  const std::size_t n = std::size_t(cam.width) * cam.height;
  vsb.depth.resize(n);
  vsb.face.resize(n);

  // The scan converter's key is 1 / zv from the face's exact plane; the distance along the
  // unit ray through (x, y) on the view plane at unit depth is zv * sqrt(1 + x^2 + y^2).
  const double t = cam.tan_half_fov();
  const double step = 2.0 * t / cam.height;
  const double x_base = -t * cam.width / cam.height + 0.5 * step;
  const double y_base = t - 0.5 * step;
  std::vector<float> column_x2(std::size_t(cam.width));
  for (int c = 0; c < cam.width; ++c) column_x2[c] = float(std::pow(x_base + step * c, 2));

  const ScanConverter converter(scene);
  converter.rasterize_tiles(RasterProjection::from_camera(cam, camera_near_plane(scene)), ctx,
                            [&](const RasterTile& tile) {
    for (int y = 0; y < tile.height; ++y) {
      const float y2 = float(std::pow(y_base - step * (tile.y0 + y), 2));
      const std::size_t row = std::size_t(tile.y0 + y) * cam.width + tile.x0;
      const double* key = tile.depth_key + y * tile.width;
      const float* x2 = column_x2.data() + tile.x0;
      float* depth = vsb.depth.data() + row;
      std::copy_n(tile.face + y * tile.width, tile.width, vsb.face.begin() + std::ptrdiff_t(row));
      for (int x = 0; x < tile.width; ++x) {
        // Background keys are -inf and give +inf, as documented.
        depth[x] = std::sqrt(1.0f + x2[x] + y2) / std::max(float(key[x]), 0.0f);
      }
    }
  });
}

VisibleSurfaceBuffer render_visible_surfaces(const Scene& scene, const Context& ctx) {
  VisibleSurfaceBuffer vsb;
  render_visible_surfaces(scene, ctx, vsb);
  return vsb;
}

}  // namespace shadowkit
