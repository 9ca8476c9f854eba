#include "shadowkit/raster/tile_bins.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>

#include "shadowkit/core/error.h"

namespace shadowkit::raster {

TileBins::TileBins(const ScreenTriangles& tris, int width, int height)
    : tiles_x((width + kTile - 1) / kTile), tiles_y((height + kTile - 1) / kTile) {
  const std::size_t tiles = std::size_t(tiles_x) * tiles_y;
  const auto for_each_tile = [&](std::uint32_t chunk, auto&& fn) {
    tris.for_each_in_chunk(chunk, [&](std::uint32_t t, const ScreenTriangle& s) {
      const int tx0 = int(s.min_x) / kTile, tx1 = int(s.max_x) / kTile;
      const int ty0 = int(s.min_y) / kTile, ty1 = int(s.max_y) / kTile;
      const bool one_tile = tx0 == tx1 && ty0 == ty1;
      for (int ty = ty0; ty <= ty1; ++ty) {
        for (int tx = tx0; tx <= tx1; ++tx) {
          if (one_tile || may_own_pixel_in(s, std::max(int(s.min_x), tx * kTile),
                                           std::min(int(s.max_x), tx * kTile + kTile - 1),
                                           std::max(int(s.min_y), ty * kTile),
                                           std::min(int(s.max_y), ty * kTile + kTile - 1))) {
            fn(std::size_t(ty) * tiles_x + tx, t);
          }
        }
      }
    });
  };
  // Per chunk and tile, how many; then where each chunk's go, chunk after chunk in each bin.
  const std::uint32_t chunks = tris.chunk_count();
  std::vector<std::uint32_t> count(std::size_t(chunks) * tiles, 0);
  tbb::parallel_for(std::uint32_t(0), chunks, [&](std::uint32_t c) {
    for_each_tile(c, [&](std::size_t tile, std::uint32_t) { ++count[c * tiles + tile]; });
  });
  start.assign(tiles + 1, 0);
  std::uint64_t total = 0;
  for (std::size_t tile = 0; tile < tiles; ++tile) {
    start[tile] = std::uint32_t(total);
    for (std::uint32_t c = 0; c < chunks; ++c) {
      const std::uint32_t n = count[c * tiles + tile];
      count[c * tiles + tile] = std::uint32_t(total);
      total += n;
    }
    SHADOWKIT_CHECK(total < std::numeric_limits<std::uint32_t>::max());
  }
  start[tiles] = std::uint32_t(total);
  items.resize(total);
  tbb::parallel_for(std::uint32_t(0), chunks, [&](std::uint32_t c) {
    for_each_tile(c,
                  [&](std::size_t tile, std::uint32_t t) { items[count[c * tiles + tile]++] = t; });
  });
}

}  // namespace shadowkit::raster
