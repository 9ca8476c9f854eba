#pragma once
// The scan converter's tiles: screen triangles binned into them, and one tile drawn.
#include <cstdint>
#include <span>
#include <vector>

#include "shadowkit/raster/scan_converter.h"
#include "shadowkit/raster/triangle_setup.h"

namespace shadowkit::raster {

/// \brief Counting sort of triangle ids into the tiles their bounds overlap; each bin keeps
/// triangle order. Chunks of triangles are counted and placed in parallel.
struct TileBins {
  static constexpr int kTile = ScanConverter::kTileSize;
  int tiles_x = 0, tiles_y = 0;
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> items;

  TileBins(const ScreenTriangles& tris, int width, int height);
  int tile_count() const { return tiles_x * tiles_y; }
};

/// Draws the triangles \p bin (ids into \p tris) over the pixels [x0, x0 + w) x [y0, y0 + h)
/// of one tile: the nearest depth key per pixel into \p keys (rows of w, -inf where nothing
/// is drawn) and, unless \p faces is null, its face id into \p faces (kNoFace where
/// nothing). Triangles go nearest first and those hidden behind what is drawn already are
/// dropped whole; every key and face is the one drawing them in triangle order gives.
void draw_tile(const ScreenTriangles& tris, std::span<const std::uint32_t> bin, int x0, int y0,
               int w, int h, double* keys, std::uint32_t* faces);

}  // namespace shadowkit::raster
