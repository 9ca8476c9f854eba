#include "stencil_count.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "../../raster/tile_bins.h"

namespace shadowkit {
namespace {

using raster::ScreenTriangle;
using raster::TileBins;
constexpr int kTile = TileBins::kTile;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Shadow polygons as screen triangles, face = polygon index. Order does not matter: counts
// add up.
std::vector<ScreenTriangle> setup_shadow_polygons(const std::vector<ShadowPolygon>& polygons,
                                                  const RasterProjection& view) {
  constexpr std::size_t kChunk = 1024;
  std::vector<std::vector<ScreenTriangle>> chunks((polygons.size() + kChunk - 1) / kChunk);
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t c) {
    for (std::size_t i = c * kChunk; i < std::min(polygons.size(), (c + 1) * kChunk); ++i) {
      const ShadowPolygon& p = polygons[i];
      raster::setup_polygon({p.corners.data(), std::size_t(p.corner_count)}, std::uint32_t(i), view,
                            chunks[c]);
    }
  });
  std::vector<ScreenTriangle> all;
  for (const auto& c : chunks) all.insert(all.end(), c.begin(), c.end());
  return all;
}

// Whether triangle \p s may own a pixel centre of the tile [x0, x1] x [y0, y1]: no edge has
// all four corner centres outside. Long thin shadow polygons cross few of the tiles their
// bounds overlap; this keeps the span walk off the rest.
bool overlaps_tile(const ScreenTriangle& s, int x0, int y0, int x1, int y1) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const std::int64_t dx = s.x[j] - s.x[i], dy = s.y[j] - s.y[i];
    // As EdgeWalker: E = dx (256 py + 128 - y_i) - dy (256 px + 128 - x_i), >= 0 inside.
    const auto e = [&](int px, int py) {
      return dx * (py * raster::kSubpixel + raster::kSubpixel / 2 - s.y[i]) -
             dy * (px * raster::kSubpixel + raster::kSubpixel / 2 - s.x[i]);
    };
    if (std::max({e(x0, y0), e(x1, y0), e(x0, y1), e(x1, y1)}) < 0) return false;
  }
  return true;
}

// One tile's visible points (NaN for background, so that no plane test passes) and counts.
struct TileCounts {
  double x[kTile * kTile], y[kTile * kTile], z[kTile * kTile];
  std::uint32_t face[kTile * kTile];
  int count[kTile * kTile];
};

// Adds one polygon's crossings on one span of a row. The plane test is exact in double on
// the visible point itself, so only coverage depends on the raster.
void count_span(const ShadowPolygon& p, const TileCounts& t, int* count, int first, int last) {
  const double nx = p.normal.x, ny = p.normal.y, nz = p.normal.z, d = p.d;
  const int jump = p.jump;
  if (!p.depth_fail) {
    // Crow's depth-pass: the crossing lies between the eye and the visible point.
    for (int i = first; i <= last; ++i) {
      count[i] += (nx * t.x[i] + ny * t.y[i] + nz * t.z[i] + d > 0) ? jump : 0;
    }
  } else if (p.face == kNoFace) {
    // Depth-fail: the crossing lies behind the visible point.
    for (int i = first; i <= last; ++i) {
      count[i] -= (nx * t.x[i] + ny * t.y[i] + nz * t.z[i] + d <= 0) ? jump : 0;
    }
  } else {
    // A light cap through its own visible point: the volume begins right behind it.
    for (int i = first; i <= last; ++i) {
      const bool behind = nx * t.x[i] + ny * t.y[i] + nz * t.z[i] + d <= 0 || t.face[i] == p.face;
      count[i] -= behind ? jump : 0;
    }
  }
}

}  // namespace

StencilStats count_shadow_polygons(const std::vector<ShadowPolygon>& polygons, int eye_count,
                                   const Scene& scene, const Light& light,
                                   const VisibleSurfaceBuffer& surfaces, ShadowMask& mask) {
  const Camera& cam = scene.camera;
  const RasterProjection view =
      RasterProjection::from_camera(cam, near_plane_for(scene.bounds(), cam.position));
  const std::vector<ScreenTriangle> tris = setup_shadow_polygons(polygons, view);
  const TileBins bins(tris, view.width, view.height);
  std::atomic<std::size_t> fill = 0, negative = 0;

  tbb::parallel_for(0, bins.tile_count(), [&](int tile) {
    thread_local TileCounts t;
    const int x0 = (tile % bins.tiles_x) * kTile, y0 = (tile / bins.tiles_x) * kTile;
    const int w = std::min(kTile, view.width - x0), h = std::min(kTile, view.height - y0);
    bool any = false;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t i = surfaces.index(x0 + x, y0 + y);
        const int k = y * w + x;
        const Vec3 p = surfaces.covered(i) ? surfaces.point(i) : Vec3{kNaN, kNaN, kNaN};
        t.x[k] = p.x, t.y[k] = p.y, t.z[k] = p.z;
        t.face[k] = surfaces.face[i];
        t.count[k] = eye_count;
        any = any || surfaces.covered(i);
      }
    }
    if (!any) return;

    std::size_t tile_fill = 0;
    for (std::uint32_t b = bins.start[tile]; b < bins.start[tile + 1]; ++b) {
      const ScreenTriangle& s = tris[bins.items[b]];
      const ShadowPolygon& poly = polygons[s.face];
      const int ya = std::max(y0, s.min_y), yb = std::min(y0 + h - 1, s.max_y);
      const int xa0 = std::max(x0, s.min_x), xb0 = std::min(x0 + w - 1, s.max_x);
      if (!overlaps_tile(s, xa0, ya, xb0, yb)) continue;
      raster::SpanWalker walker(s, ya);
      for (int py = ya; py <= yb; ++py, walker.next_row()) {
        int xa = std::max(x0, s.min_x), xb = std::min(x0 + w - 1, s.max_x);
        if (!walker.span(xa, xb)) continue;
        tile_fill += std::size_t(xb - xa + 1);
        const int row = (py - y0) * w - x0;
        count_span(poly, t, t.count, row + xa, row + xb);
      }
    }

    // Shadow where the count is positive, or where the camera sees the face's unlit side
    // (contract condition 1).
    std::size_t tile_negative = 0;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t i = surfaces.index(x0 + x, y0 + y);
        if (!surfaces.covered(i)) continue;
        const int c = t.count[y * w + x];
        tile_negative += c < 0;
        const bool lit =
            c <= 0 && faces_light(scene.face_plane(surfaces.face[i]), cam.position, light);
        mask.pixels[i] = lit ? kMaskLit : kMaskShadow;
      }
    }
    fill += tile_fill;
    negative += tile_negative;
  });
  return {fill.load(), negative.load()};
}

}  // namespace shadowkit
