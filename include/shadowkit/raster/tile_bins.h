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

/// \brief One tile's nearest depth keys (and faces), drawn into batch after batch, with one
/// level of hierarchical depth (Greene, Kass & Miller 1993) over its blocks of 8 x 8 pixels:
/// each block's farthest key so far. Large triangles go first, nearest first, so that most of
/// those hidden behind nearer ones meet full blocks and are dropped whole: a cube field seen
/// at a low angle stacks dozens of triangles on a pixel. Small ones follow as they came.
///
/// \p Key: double for the camera's keys, exact to the rounding of each face's plane; float
/// for a light's depth map, which stores float depth: each key summed in double and rounded,
/// in half the tile's memory.
template <typename Key>
class TileDepth {
 public:
  static constexpr int kBlock = 8, kBlocks = TileBins::kTile / kBlock;
  /// Triangles with at most this many pixels in their rectangle are drawn pixel by pixel.
  static constexpr int kSmallTriangle = 32;
  static_assert(kBlocks * kBlocks <= 64, "a bit per block");

  /// Starts the tile of pixels [x0, x0 + w) x [y0, y0 + h) with nothing drawn: \p keys (rows of
  /// w) all -inf and, unless \p faces is null, \p faces all kNoFace.
  void reset(int x0, int y0, int w, int h, Key* keys, std::uint32_t* faces);
  /// Draws the triangles \p bin (ids into \p tris) over the tile: every key and face is the one
  /// drawing all batches in triangle order gives. Between equally near triangles the lower
  /// face id wins.
  void draw(const ScreenTriangles& tris, std::span<const std::uint32_t> bin);
  /// Takes the farthest key of every block drawn into since, for hidden().
  void settle();
  /// Whether nothing with keys at most \p nearest can show in pixels [xa, xb] x [ya, yb]
  /// (inside the tile): every block there has its farthest key beyond it. Reads the blocks
  /// as the last settle() left them, so threads may ask while no one draws.
  bool hidden(int xa, int xb, int ya, int yb, double nearest) const;

 private:
  struct BlockRange {
    int bx0, bx1, by0, by1;
  };
  /// Pixels [xa, xb] x [ya, yb] of the tile.
  struct PixelRange {
    int xa, xb, ya, yb;
    int area() const { return (xb - xa + 1) * (yb - ya + 1); }
  };
  /// The pixels of the tile within \p t's bounds.
  PixelRange pixels_of(const ScreenTriangle& t) const;
  BlockRange blocks(int xa, int xb, int ya, int yb) const;
  bool hidden(const BlockRange& r, double nearest) const;
  std::uint64_t showing(const ScreenTriangle& t, const BlockRange& r);
  void refresh(int block);
  template <bool kFaces>
  void draw_triangles(const ScreenTriangles& tris, std::span<const std::uint32_t> bin);
  template <bool kFaces>
  void draw_triangle(const ScreenTriangle& t);

  int x0_ = 0, y0_ = 0, w_ = 0, h_ = 0;
  Key* key_ = nullptr;
  std::uint32_t* face_ = nullptr;
  Key far_[kBlocks * kBlocks];
  std::uint64_t stale_ = 0;  ///< blocks drawn into since their farthest key was taken
};

extern template class TileDepth<double>;
extern template class TileDepth<float>;

}  // namespace shadowkit::raster
