#include "shadowkit/raster/visible_surface.h"

#include <algorithm>
#include <cmath>

namespace shadowkit {

std::size_t VisibleSurfaceBuffer::covered_count() const {
  return std::size_t(std::count_if(face.begin(), face.end(), [](auto f) { return f != kNoFace; }));
}

double camera_near_plane(const Scene& scene) {
  // Relative to the farthest scene point: the 1/z depth key keeps its precision even for a
  // tiny near distance, and a ray can only miss geometry closer than this.
  const Bounds3& b = scene.bounds();
  if (b.empty()) return 1e-6;
  const Vec3 far = max(b.hi - scene.camera.position, scene.camera.position - b.lo);
  return std::max(length(far) * 1e-7, 1e-300);
}

VisibleSurfaceBuffer render_visible_surfaces(const Scene& scene, const Context& ctx) {
  const Camera& cam = scene.camera;
  VisibleSurfaceBuffer vsb;
  vsb.width = cam.width;
  vsb.height = cam.height;
  const std::size_t n = std::size_t(cam.width) * cam.height;
  vsb.depth.resize(n);
  vsb.point.resize(n);
  vsb.face.resize(n);
  vsb.object.resize(n);

  const Vec3 eye = cam.position, f = cam.forward(), r = cam.right(), u = cam.true_up();
  const double t = cam.tan_half_fov();
  const double sx = 2.0 * t / cam.height, sy = 2.0 * t / cam.height;
  const double x_base = -t * cam.width / cam.height;

  const ScanConverter converter(scene);
  converter.rasterize_tiles(RasterProjection::from_camera(cam, camera_near_plane(scene)), ctx,
                            [&](const RasterTile& tile) {
    for (int y = 0; y < tile.height; ++y) {
      const int row = tile.y0 + y;
      const double ry = t - sy * (row + 0.5);
      for (int x = 0; x < tile.width; ++x) {
        const int col = tile.x0 + x;
        const std::size_t i = std::size_t(row) * cam.width + col;
        const std::uint32_t face = tile.face[y * tile.width + x];
        vsb.face[i] = face;
        if (face == kNoFace) {
          vsb.depth[i] = INFINITY;
          vsb.point[i] = {};
          vsb.object[i] = kNoFace;
          continue;
        }
        // The exact visible point: the pixel's ray against the face plane, in double.
        const Vec3 dir = f + (x_base + sx * (col + 0.5)) * r + ry * u;
        const Plane& plane = scene.face_plane(face);
        const double dist = -plane.distance(eye) / dot(plane.normal, dir);
        vsb.point[i] = Vec3f(eye + dir * dist);
        vsb.depth[i] = float(dist * length(dir));
        vsb.object[i] = scene.object_of_face(face);
      }
    }
  });
  return vsb;
}

}  // namespace shadowkit
