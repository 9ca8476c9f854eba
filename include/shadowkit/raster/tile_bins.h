#pragma once
// Binning of screen triangles into the scan converter's tiles.
#include <cstdint>
#include <limits>
#include <vector>

#include "shadowkit/core/error.h"
#include "shadowkit/raster/scan_converter.h"
#include "shadowkit/raster/triangle_setup.h"

namespace shadowkit::raster {

/// \brief Counting sort of triangle ids into the tiles their bounds overlap; each bin keeps
/// triangle order.
struct TileBins {
  static constexpr int kTile = ScanConverter::kTileSize;
  int tiles_x = 0, tiles_y = 0;
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> items;

  TileBins(const ScreenTriangles& tris, int width, int height)
      : tiles_x((width + kTile - 1) / kTile), tiles_y((height + kTile - 1) / kTile) {
    std::vector<std::uint32_t> count(std::size_t(tiles_x) * tiles_y + 1, 0);
    for_each_tile(tris, [&](std::size_t tile, std::uint32_t) { ++count[tile + 1]; });
    std::uint64_t total = 0;
    for (std::size_t i = 1; i < count.size(); ++i) total += count[i];
    SHADOWKIT_CHECK(total < std::numeric_limits<std::uint32_t>::max());
    for (std::size_t i = 1; i < count.size(); ++i) count[i] += count[i - 1];
    start = count;
    items.resize(count.back());
    for_each_tile(tris, [&](std::size_t tile, std::uint32_t t) { items[count[tile]++] = t; });
  }

  int tile_count() const { return tiles_x * tiles_y; }

  template <class Fn>
  void for_each_tile(const ScreenTriangles& tris, Fn&& fn) const {
    tris.for_each([&](std::uint32_t t, const ScreenTriangle& s) {
      for (int ty = s.min_y / kTile; ty <= s.max_y / kTile; ++ty) {
        for (int tx = s.min_x / kTile; tx <= s.max_x / kTile; ++tx) {
          fn(std::size_t(ty) * tiles_x + tx, t);
        }
      }
    });
  }
};

}  // namespace shadowkit::raster
