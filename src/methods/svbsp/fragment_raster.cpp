#include "fragment_raster.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>

#include "shadowkit/raster/triangle_setup.h"

namespace shadowkit::svbsp {
namespace {

// Writes \p value at the pixels of \p face owned by one screen triangle of a fragment.
void mark(const raster::ScreenTriangle& t, std::uint32_t face, std::uint8_t value,
          const VisibleSurfaceBuffer& surfaces, ShadowMask& mask) {
  raster::SpanWalker walker(t, t.min_y);
  for (int y = t.min_y; y <= t.max_y; ++y, walker.next_row()) {
    int x0 = t.min_x, x1 = t.max_x;
    if (!walker.span(x0, x1)) continue;
    for (int x = x0; x <= x1; ++x) {
      const std::size_t i = surfaces.index(x, y);
      // Fragments of different faces may overlap on screen; only the visible face counts.
      // Several threads may store the same value here.
      if (surfaces.face[i] == face) {
        std::atomic_ref<std::uint8_t>(mask.pixels[i]).store(value, std::memory_order_relaxed);
      }
    }
  }
}

}  // namespace

void shade_fragments(const Scene& scene, const Light& light, const std::vector<Fragment>& fragments,
                     const VisibleSurfaceBuffer& surfaces, bool shadowed_only, ShadowMask& mask) {
  const Camera& cam = scene.camera;
  // The faces drawn first, whole: in shadow, or (§6, shadowed fragments only) lit wherever
  // condition 1 allows; the fragments of the other verdict are drawn over them.
  for (std::size_t i = 0; i < mask.pixels.size(); ++i) {
    if (!surfaces.covered(i)) continue;
    const bool lit =
        shadowed_only && faces_light(scene.face_plane(surfaces.face[i]), cam.position, light);
    mask.pixels[i] = lit ? kMaskLit : kMaskShadow;
  }
  const bool draw_lit = !shadowed_only;
  const RasterProjection view =
      RasterProjection::from_camera(cam, near_plane_for(scene.bounds(), cam.position));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, fragments.size(), 64), [&](const auto& r) {
    std::vector<raster::HomogeneousPoint> corners;
    std::vector<raster::ScreenTriangle> triangles;
    for (std::size_t f = r.begin(); f != r.end(); ++f) {
      const Fragment& fragment = fragments[f];
      const std::uint32_t face = fragment.polygon.face;
      if (fragment.lit != draw_lit || !faces_light(scene.face_plane(face), cam.position, light)) {
        continue;
      }
      corners.clear();
      for (const Vec3& v : fragment.polygon.vertices) corners.push_back({v, 1});
      triangles.clear();
      raster::setup_polygon(corners, face, view, triangles);
      for (const auto& t : triangles) {
        mark(t, face, draw_lit ? kMaskLit : kMaskShadow, surfaces, mask);
      }
    }
  });
}

}  // namespace shadowkit::svbsp
