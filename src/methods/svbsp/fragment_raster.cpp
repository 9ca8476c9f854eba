#include "fragment_raster.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <span>

#include "shadowkit/raster/triangle_setup.h"
#include "unowned_centres.h"

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

// What the pixels of each face start as. Faces the camera sees from the light's far side are
// in shadow (contract condition 1). With the shadowed fragments alone (§6) the others start
// lit; otherwise a face whose fragments share one verdict takes it, and the pixels of a face
// of both verdicts are owned by none until its fragments are drawn.
std::vector<std::uint8_t> face_starts(const Scene& scene, const Light& light,
                                      const std::vector<Fragment>& fragments, bool shadowed_only) {
  constexpr std::uint8_t kLit = 1, kShadowed = 2;
  std::vector<std::uint8_t> verdicts(scene.face_count(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, fragments.size(), 4096), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      const Fragment& f = fragments[i];
      std::atomic_ref<std::uint8_t>(verdicts[f.polygon.face])
          .fetch_or(f.lit ? kLit : kShadowed, std::memory_order_relaxed);
    }
  });
  std::vector<std::uint8_t> start(scene.face_count());
  tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, scene.face_count(), 4096),
                    [&](const auto& r) {
                      for (std::uint32_t face = r.begin(); face != r.end(); ++face) {
                        std::uint8_t value = kMaskShadow;
                        if (faces_light(scene.face_plane(face), scene.camera.position, light)) {
                          value = shadowed_only || verdicts[face] == kLit ? kMaskLit
                                  : verdicts[face] == (kLit | kShadowed)  ? kUnowned
                                                                          : kMaskShadow;
                        }
                        start[face] = value;
                      }
                    });
  return start;
}

}  // namespace

void shade_fragments(const Scene& scene, const Light& light, const std::vector<Fragment>& fragments,
                     const VisibleSurfaceBuffer& surfaces, bool shadowed_only, ShadowMask& mask) {
  const std::vector<std::uint8_t> start = face_starts(scene, light, fragments, shadowed_only);
  // Only the faces seen somewhere are drawn: most others hide behind their own objects.
  std::vector<std::uint8_t> seen(scene.face_count(), 0);
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, mask.pixels.size(), 1 << 14), [&](const auto& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          if (!surfaces.covered(i)) continue;
          const std::uint32_t face = surfaces.face[i];
          mask.pixels[i] = start[face];
          std::atomic_ref<std::uint8_t>(seen[face]).store(1, std::memory_order_relaxed);
        }
      });
  // The fragments to draw, in order.
  std::vector<std::uint32_t> drawn;
  for (std::uint32_t i = 0; i < fragments.size(); ++i) {
    const std::uint32_t face = fragments[i].polygon.face;
    const bool over =
        shadowed_only ? !fragments[i].lit && start[face] == kMaskLit : start[face] == kUnowned;
    if (over && seen[face]) drawn.push_back(i);
  }
  const RasterProjection view = RasterProjection::from_camera(
      scene.camera, near_plane_for(scene.bounds(), scene.camera.position));
  // The lit fragments last: a centre the raster gives to fragments of both verdicts (their
  // cut points a rounding apart) is lit.
  for (const bool lit : {false, true}) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, drawn.size(), 64), [&](const auto& r) {
      std::vector<raster::HomogeneousPoint> corners;
      std::vector<raster::ScreenTriangle> triangles;
      for (std::size_t k = r.begin(); k != r.end(); ++k) {
        const Fragment& fragment = fragments[drawn[k]];
        if (fragment.lit != lit) continue;
        corners.clear();
        for (const Vec3& v : fragment.polygon.vertices) corners.push_back({v, 1});
        triangles.clear();
        raster::setup_polygon(corners, fragment.polygon.face, view, triangles);
        for (const auto& t : triangles) {
          mark(t, fragment.polygon.face, lit ? kMaskLit : kMaskShadow, surfaces, mask);
        }
      }
    });
  }
  // Every unowned centre is on a face drawn.
  if (!shadowed_only) resolve_unowned(scene, fragments, drawn, surfaces, mask);
}

}  // namespace shadowkit::svbsp
