#include "shadowkit/raster/scan_converter.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "shadowkit/core/error.h"
#include "shadowkit/raster/tile_bins.h"
#include "shadowkit/raster/triangle_setup.h"

namespace shadowkit {
namespace {

using raster::TileBins;
constexpr int kTile = ScanConverter::kTileSize;

struct TileBuffers {
  double key[kTile * kTile];
  std::uint32_t face[kTile * kTile];
};

}  // namespace

void ScanConverter::rasterize_tiles(const RasterProjection& view, const Context& /*ctx*/,
                                    const std::function<void(const RasterTile&)>& fn) const {
  const raster::ScreenTriangles tris = raster::setup_triangles(scene_, view);
  const TileBins bins(tris, view.width, view.height);
  const int tile_count = bins.tiles_x * bins.tiles_y;
  tbb::parallel_for(0, tile_count, [&](int tile) {
    thread_local TileBuffers buf;
    const int x0 = (tile % bins.tiles_x) * kTile, y0 = (tile / bins.tiles_x) * kTile;
    const int w = std::min(kTile, view.width - x0), h = std::min(kTile, view.height - y0);
    raster::draw_tile(
        tris, {bins.items.data() + bins.start[tile], bins.items.data() + bins.start[tile + 1]}, x0,
        y0, w, h, buf.key, buf.face);
    fn(RasterTile{x0, y0, w, h, buf.key, buf.face});
  });
}

DepthFaceBuffer ScanConverter::rasterize(const RasterProjection& view, const Context& ctx) const {
  DepthFaceBuffer out;
  out.width = view.width;
  out.height = view.height;
  out.depth_key.resize(std::size_t(view.width) * view.height);
  out.face.resize(out.depth_key.size());
  rasterize_tiles(view, ctx, [&](const RasterTile& tile) {
    for (int y = 0; y < tile.height; ++y) {
      const std::size_t dst = std::size_t(tile.y0 + y) * view.width + tile.x0;
      std::transform(tile.depth_key + y * tile.width, tile.depth_key + (y + 1) * tile.width,
                     out.depth_key.begin() + std::ptrdiff_t(dst),
                     [](double k) { return float(k); });
      std::copy_n(tile.face + y * tile.width, tile.width, out.face.begin() + dst);
    }
  });
  return out;
}

}  // namespace shadowkit
