#pragma once
/// \brief The software z-buffer scan converter that every method relies on.
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include "shadowkit/core/context.h"
#include "shadowkit/raster/projection.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit {

inline constexpr std::uint32_t kNoFace = std::numeric_limits<std::uint32_t>::max();

/// \brief Nearest face per pixel and its depth key (larger is nearer; see RasterProjection).
struct DepthFaceBuffer {
  int width = 0, height = 0;
  std::vector<float> depth_key;
  std::vector<std::uint32_t> face;  ///< global face id, kNoFace where nothing was drawn
};

/// \brief One finished tile: pixels [x0, x0+width) x [y0, y0+height) of the raster, rows of
/// `width` entries.
struct RasterTile {
  int x0 = 0, y0 = 0, width = 0, height = 0;
  const double* depth_key = nullptr;  ///< exact to double rounding of the face plane
  const std::uint32_t* face = nullptr;
  /// No triangle reached the tile (keys and faces null): every pixel is background, key
  /// -inf and face kNoFace. Most of a view of the sky is handed on without being drawn.
  bool empty() const { return face == nullptr; }
};

/// \brief One finished tile of a depth map: keys alone, in float (a map stores float depth).
struct DepthTile {
  int x0 = 0, y0 = 0, width = 0, height = 0;
  const float* depth_key = nullptr;
};

/// \brief Rasterizes a scene's triangles: near-plane and guard-band clipping, top-left fill
/// rule on 1/256-pixel fixed point (a pixel centre on an edge shared by two triangles is drawn
/// exactly once), tiles in parallel with oneTBB. Back faces are culled only where a closed
/// solid's near side hides them (OutwardSolids); open meshes show both sides.
class ScanConverter {
 public:
  /// Depth is interpolated from each face's exact plane, so all triangles of a polygon agree.
  explicit ScanConverter(const Scene& scene) : scene_(scene) {}

  /// Tile edge in pixels.
  static constexpr int kTileSize = 64;
  /// Clusters in the first of the batches that grow (rasterize_tiles), at least.
  static constexpr std::size_t kFirstBatch = 64;
  /// Below this many clusters in view, one batch: keeping every tile between batches costs
  /// more than culling the few hidden clusters saves.
  static constexpr std::size_t kCulledClusters = 2048;

  /// Nearest face per pixel. Ties in depth go to the lower triangle index.
  DepthFaceBuffer rasterize(const RasterProjection& view, const Context& ctx) const;

  /// Calls \p fn once per finished tile, from several threads at once: the building block
  /// of rasterize() and of passes that post-process a tile while it is in cache. \p fn must
  /// not start parallel work itself: the tile's buffer is the worker thread's own. A tile
  /// no triangle reaches comes empty (RasterTile::empty), without buffers.
  void rasterize_tiles(const RasterProjection& view, const Context& ctx,
                       const std::function<void(const RasterTile&)>& fn) const;
  /// Per tile of a raster (row by row, kTileSize pixels a side), whether it is wanted.
  using TileMask = std::span<const std::uint8_t>;

  /// As rasterize_tiles, for a light's depth map: float keys only, and only the tiles that
  /// some triangle reaches; the others hold nothing. With \p wanted, only the tiles it marks:
  /// no triangle is set up whose cluster reaches none of them.
  /// \p keep_in, when given, is where a full-width tile kept between batches is drawn, asked
  /// once per tile when a batch first reaches it (rows of kTileSize keys; null: the pass's
  /// own storage): a depth map's own slot, which \p fn then finds its keys in.
  using TileStorage = std::function<float*(std::size_t tile)>;
  void rasterize_depth_tiles(const RasterProjection& view, const Context& ctx,
                             const std::function<void(const DepthTile&)>& fn, TileMask wanted = {},
                             const TileStorage& keep_in = {}) const;

  /// What the drawing of the clusters hands on, besides its tiles' keys (and faces, for a
  /// RasterTile).
  struct TileOutput {
    bool empty_tiles;                      ///< tiles no triangle reaches, too
    TileMask wanted;                       ///< the tiles drawn; empty: all
    const TileStorage* keep_in = nullptr;  ///< depth tiles only
  };

 private:
  template <typename Tile>
  void draw_clusters(const RasterProjection& view, TileOutput output,
                     const std::function<void(const Tile&)>& fn) const;

  const Scene& scene_;
};

}  // namespace shadowkit
