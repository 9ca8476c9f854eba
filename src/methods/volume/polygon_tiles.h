#pragma once
// Shadow polygons against the tiles of the counting pass: which tiles and rows they reach.
#include <cstdint>
#include <span>
#include <vector>

#include "counting_tile.h"
#include "shadowkit/raster/screen_polygon.h"

namespace shadowkit::volume {

/// Whether polygon \p s may own a pixel centre of the pixels [x0, x1] x [y0, y1]: no edge
/// has all four corner centres outside. Long thin shadow polygons cross few of the tiles
/// their bounds overlap; this keeps the span walk off the rest.
bool overlaps_rectangle(const raster::ScreenPolygon& s, int x0, int y0, int x1, int y1);

/// Narrows [va, vb], pixels along one axis, to those where polygon \p s can own pixel
/// centres within pixels [ua, ub] along the other (u = x for rows, u = y for columns): the
/// extent of the polygon within that strip, widened by a pixel. A thin slanted shadow polygon
/// spans many more rows of a tile than it crosses within its columns, and the other way
/// round.
void narrow_to_strip(const raster::ScreenPolygon& s, bool u_is_x, int ua, int ub, int& va, int& vb);

/// \brief Polygon indices per tile, in polygon order. Per row of tiles, a polygon goes only
/// into the tiles its columns there reach, not into every tile of its bounding box: long
/// slanted shadow polygons cross far fewer tiles than their boxes hold.
struct PolygonBins {
  int tiles_x, tiles_y;
  std::vector<std::uint32_t> start, items;  ///< tile t holds items[start[t] .. start[t + 1])

  PolygonBins(std::span<const raster::ScreenPolygon* const> polygons, int width, int height);
  int tile_count() const { return tiles_x * tiles_y; }
};

}  // namespace shadowkit::volume
