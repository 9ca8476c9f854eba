#pragma once
// Binning of screen triangles into the scan converter's tiles.
#include <cstdint>
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

}  // namespace shadowkit::raster
