#include "shadowkit/raster/visible_surface.h"

#include <algorithm>
#include <cmath>

namespace shadowkit {

std::size_t VisibleSurfaceBuffer::covered_count() const {
  return std::size_t(std::count_if(face.begin(), face.end(), [](auto f) { return f != kNoFace; }));
}

void VisibleSurfaceBuffer::summarize_coverage() {
  block_covered.assign(std::size_t(blocks_per_row()) * height, 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (covered(index(x, y))) {
        block_covered[std::size_t(y) * blocks_per_row() + std::size_t(x / kCoverageBlock)] = 1;
      }
    }
  }
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
  grid_ = cam.pixel_grid();
}

Vec3 VisibleSurfaceBuffer::ray(std::size_t i) const {
  const double x = grid_.x0 + grid_.step * double(i % std::size_t(width));
  const double y = grid_.y0 - grid_.step * double(i / std::size_t(width));
  return forward_ + x * right_ + y * up_;
}

Vec3 VisibleSurfaceBuffer::point(std::size_t i) const {
  const Vec3 eye = scene_->camera.position, dir = ray(i);
  const Plane& plane = this->plane(i);
  return eye + dir * (-plane.distance(eye) / dot(plane.normal, dir));
}

void render_visible_surfaces(const Scene& scene, const Context& ctx, VisibleSurfaceBuffer& vsb) {
  const Camera& cam = scene.camera;
  vsb.bind(scene);
  vsb.width = cam.width;
  vsb.height = cam.height;
  const std::size_t n = std::size_t(cam.width) * cam.height;
  vsb.depth.resize(n);
  vsb.face.resize(n);
  vsb.block_covered.assign(std::size_t(vsb.blocks_per_row()) * cam.height, 0);

  // The scan converter's key is 1 / zv from the face's exact plane; the distance along the
  // unit ray through (x, y) on the view plane at unit depth is zv * sqrt(1 + x^2 + y^2).
  const Camera::PixelGrid grid = cam.pixel_grid();
  std::vector<float> column_x2(std::size_t(cam.width));
  for (int c = 0; c < cam.width; ++c) column_x2[c] = float(std::pow(grid.x0 + grid.step * c, 2));

  const ScanConverter converter(scene);
  converter.rasterize_tiles(
      RasterProjection::from_camera(cam, near_plane_for(scene.bounds(), cam.position)), ctx,
      [&](const RasterTile& tile) {
        for (int y = 0; y < tile.height; ++y) {
          const float y2 = float(std::pow(grid.y0 - grid.step * (tile.y0 + y), 2));
          const std::size_t row = std::size_t(tile.y0 + y) * cam.width + tile.x0;
          const float* x2 = column_x2.data() + tile.x0;
          float* depth = vsb.depth.data() + row;
          const std::uint32_t* face = tile.empty() ? nullptr : tile.face + y * tile.width;
          if (face) {
            std::copy_n(face, tile.width, vsb.face.begin() + std::ptrdiff_t(row));
          } else {
            std::fill_n(vsb.face.begin() + std::ptrdiff_t(row), tile.width, kNoFace);
          }
          // Tiles are coverage blocks, so each tile writes its own flags.
          const bool covered = face && std::any_of(face, face + tile.width,
                                                   [](std::uint32_t f) { return f != kNoFace; });
          vsb.block_covered[std::size_t(tile.y0 + y) * vsb.blocks_per_row() +
                            std::size_t(tile.x0 / VisibleSurfaceBuffer::kCoverageBlock)] = covered;
          if (!covered) {
            std::fill_n(depth, tile.width, INFINITY);  // what the keys of -inf give
            continue;
          }
          const double* key = tile.depth_key + y * tile.width;
          for (int x = 0; x < tile.width; ++x) {
            // Background keys are -inf and give a depth of +inf.
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
