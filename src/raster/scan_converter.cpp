#include "shadowkit/raster/scan_converter.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <type_traits>

#include "shadowkit/core/error.h"
#include "shadowkit/raster/cluster_view.h"
#include "shadowkit/raster/tile_bins.h"
#include "shadowkit/raster/triangle_setup.h"

namespace shadowkit {
namespace {

using raster::ClusterInView;
using raster::TileBins;
using TileOutput = ScanConverter::TileOutput;
constexpr int kTile = ScanConverter::kTileSize;
constexpr int kTilePixels = kTile * kTile;

// Every tile's keys and faces, kept for the next frame: a fresh 25 MB at 1920x1080 costs its
// page faults. A pool per kind of key (double for the camera, float for a depth map), not one
// per thread: a thread that waits in a parallel loop may take up another frame meanwhile.
template <typename Key>
struct FrameBuffers {
  std::vector<Key> keys;
  std::vector<std::uint32_t> faces;
};

template <typename Key>
class FrameBufferPool {
 public:
  std::unique_ptr<FrameBuffers<Key>> take() {
    std::lock_guard lock(mutex_);
    if (free_.empty()) return std::make_unique<FrameBuffers<Key>>();
    std::unique_ptr<FrameBuffers<Key>> b = std::move(free_.back());
    free_.pop_back();
    return b;
  }
  void give(std::unique_ptr<FrameBuffers<Key>> b) {
    std::lock_guard lock(mutex_);
    free_.push_back(std::move(b));
  }

 private:
  std::mutex mutex_;
  std::vector<std::unique_ptr<FrameBuffers<Key>>> free_;
};

template <typename Key>
FrameBufferPool<Key>& pool() {
  static FrameBufferPool<Key> frames;
  return frames;
}

// Whether cluster \p c can draw into a tile that \p wanted (rows of \p tiles_x) marks.
bool reaches(const ClusterInView& c, ScanConverter::TileMask wanted, int tiles_x) {
  for (int ty = c.y0 / kTile; ty <= c.y1 / kTile; ++ty) {
    for (int tx = c.x0 / kTile; tx <= c.x1 / kTile; ++tx) {
      if (wanted[std::size_t(ty) * tiles_x + tx]) return true;
    }
  }
  return false;
}

// Every tile of the raster, drawn into batch after batch: with several batches each in its
// own kTile x kTile slot of the pool's buffers. A RasterTile has double keys and faces, a
// DepthTile float keys alone.
template <typename Tile>
class TileFrame {
  using Key = std::remove_cv_t<std::remove_pointer_t<decltype(Tile::depth_key)>>;
  static constexpr bool kFaces = std::is_same_v<Tile, RasterTile>;

 public:
  // \p batches: how many batches will draw. One needs no tile kept between them: each
  // tile is drawn and handed on in one thread's own buffers, which stay in its cache.
  TileFrame(int width, int height, std::size_t batches, TileOutput output)
      : width_(width),
        height_(height),
        tiles_x_((width + kTile - 1) / kTile),
        tiles_y_((height + kTile - 1) / kTile),
        output_(output) {
    if (batches < 2) return;
    const std::size_t tiles = std::size_t(tiles_x_) * tiles_y_;
    buffers_ = pool<Key>().take();
    buffers_->keys.resize(tiles * kTilePixels);
    if (kFaces) buffers_->faces.resize(tiles * kTilePixels);
    key_ = buffers_->keys.data(), face_ = kFaces ? buffers_->faces.data() : nullptr;
    depth_.resize(tiles);
    reached_.assign(tiles, 0);
    kept_at_.assign(tiles, nullptr);
  }
  ~TileFrame() {
    if (buffers_) pool<Key>().give(std::move(buffers_));
  }
  TileFrame(const TileFrame&) = delete;
  TileFrame& operator=(const TileFrame&) = delete;

  int tile_count() const { return tiles_x_ * tiles_y_; }

  bool wanted(std::size_t tile) const { return output_.wanted.empty() || output_.wanted[tile]; }

  // Whether what is drawn already hides every pixel \p c can draw in wanted tiles.
  bool hides(const ClusterInView& c) const {
    if (key_ == nullptr) return false;  // one batch: drawn after every test
    for (int ty = c.y0 / kTile; ty <= c.y1 / kTile; ++ty) {
      for (int tx = c.x0 / kTile; tx <= c.x1 / kTile; ++tx) {
        const int x0 = tx * kTile, y0 = ty * kTile;
        const std::size_t t = std::size_t(ty) * tiles_x_ + tx;
        if (!wanted(t)) continue;
        if (!reached_[t]) return false;  // nothing drawn there yet
        if (!depth_[t].hidden(std::max(x0, c.x0), std::min(x0 + kTile - 1, c.x1),
                              std::max(y0, c.y0), std::min(y0 + kTile - 1, c.y1), c.nearest)) {
          return false;
        }
      }
    }
    return true;
  }

  // Draws \p tris into every tile they reach, starting a tile when a batch first reaches it;
  // the last batch hands every tile some batch reached (or every tile) to \p fn while it is
  // in cache. A kept tile no batch reaches is never touched: most of a view of the sky.
  void draw(const raster::ScreenTriangles& tris, bool last,
            const std::function<void(const Tile&)>& fn) {
    const TileBins bins(tris, width_, height_);
    tbb::parallel_for(0, tile_count(), [&](int t) {
      if (!wanted(std::size_t(t))) return;
      struct Scratch {
        Key key[kTilePixels];
        std::uint32_t face[kFaces ? kTilePixels : 1];
        raster::TileDepth<Key> depth;
      };
      thread_local Scratch scratch;
      const bool drawing = bins.start[t + 1] > bins.start[t];
      const bool started = key_ != nullptr && reached_[t];
      const int x0 = (t % tiles_x_) * kTile, y0 = (t / tiles_x_) * kTile;
      const int w = std::min(kTile, width_ - x0), h = std::min(kTile, height_ - y0);
      if (!drawing && !started) {
        if constexpr (kFaces) {
          if (last && output_.empty_tiles) fn(Tile{x0, y0, w, h});  // empty(): not drawn
        }
        return;
      }
      // Kept while a later batch may draw into it; otherwise drawn in the thread's own.
      const bool kept = key_ != nullptr && (drawing || started);
      Key* key = kept ? kept_keys(t, w) : scratch.key;
      std::uint32_t* face = !kFaces ? nullptr
                            : kept  ? face_ + std::size_t(t) * kTilePixels
                                    : scratch.face;
      Tile r{x0, y0, w, h, key};
      if constexpr (kFaces) r.face = face;
      raster::TileDepth<Key>& depth = kept ? depth_[t] : scratch.depth;
      if (!started) depth.reset(r.x0, r.y0, r.width, r.height, key, face);
      if (drawing) {
        depth.draw(tris,
                   {bins.items.data() + bins.start[t], bins.items.data() + bins.start[t + 1]});
        if (kept) reached_[t] = 1;
        if (!last) depth.settle();  // for hides(), between batches
      }
      if (last) fn(r);
    });
  }

 private:
  // Where kept tile \p t (\p w pixels wide) is drawn: the caller's storage for a full-width
  // depth tile, if it has some, else the frame's slot.
  Key* kept_keys(int t, int w) {
    Key*& at = kept_at_[std::size_t(t)];
    if (at != nullptr) return at;
    if constexpr (!kFaces) {
      if (output_.keep_in != nullptr && w == kTile) at = (*output_.keep_in)(std::size_t(t));
    }
    if (at == nullptr) at = key_ + std::size_t(t) * kTilePixels;
    return at;
  }

  int width_, height_, tiles_x_, tiles_y_;
  std::unique_ptr<FrameBuffers<Key>> buffers_;
  Key* key_ = nullptr;  ///< tile after tile, when kept between batches
  std::uint32_t* face_ = nullptr;
  std::vector<raster::TileDepth<Key>> depth_;
  std::vector<char> reached_;  ///< per kept tile, whether a batch drew triangles into it
  std::vector<Key*> kept_at_;  ///< per kept tile, where it is drawn, once started
  TileOutput output_;
};

// Faces of outward solids turned from the eye, which their solid's near side hides: only of
// solids wholly past the near plane, since one the near plane cuts shows its inside.
class HiddenSides {
 public:
  HiddenSides(const Scene& scene, const RasterProjection& view)
      : scene_(scene), view_(view), solid_state_(scene.outward_solids().size(), kUnknown) {}

  bool hidden(std::uint32_t face) const {
    const std::int32_t s = scene_.outward_solids().solid_of(face);
    if (s < 0 || !hides_far_side(std::size_t(s))) return false;
    // OutwardSolids::far_side_from and far_side_along, with their test of the solid asked
    // once per solid (hides_far_side), not once per face.
    const Plane& plane = scene_.face_plane(face);
    return view_.orthographic ? OutwardSolids::turned_along(plane, view_.forward)
                              : OutwardSolids::turned_from(plane, view_.eye);
  }

 private:
  enum : std::uint8_t { kUnknown, kHides, kShows };
  // Whether solid \p s's near side hides its far side: the solid lies past the near plane
  // and, for a perspective view, the eye lies outside its box. Taken when a face of the
  // solid is first met: a cube map's face meets a few of a scene's solids, and most views
  // meet few of them that are not hidden whole. Threads that meet the solid at once find
  // the same answer.
  bool hides_far_side(std::size_t s) const {
    std::atomic_ref<std::uint8_t> state(solid_state_[s]);
    std::uint8_t known = state.load(std::memory_order_relaxed);
    if (known == kUnknown) {
      const OutwardSolids& solids = scene_.outward_solids();
      const Bounds3& box = solids.bounds(s);
      bool hides = view_.orthographic || solids.outside(s, view_.eye);
      for (int k = 0; k < 8 && hides; ++k) hides = view_.to_view(box.corner(k)).z > view_.near;
      known = hides ? kHides : kShows;
      state.store(known, std::memory_order_relaxed);
    }
    return known == kHides;
  }

  const Scene& scene_;
  const RasterProjection& view_;
  mutable std::vector<std::uint8_t> solid_state_;
};

// The triangles of the clusters \p batch that neither what \p frame has drawn nor their own
// solid hides, as entries of the scene's TriangleClusters.
template <typename Tile>
std::vector<std::uint32_t> unhidden_triangles(const Scene& scene, const HiddenSides& sides,
                                              const TileFrame<Tile>& frame,
                                              std::span<const ClusterInView> batch) {
  const TriangleClusters& clusters = scene.triangles().clusters;
  constexpr std::size_t kSize = TriangleClusters::kSize;
  std::vector<std::uint32_t> kept(batch.size() * kSize);
  std::vector<std::uint8_t> count(batch.size(), 0);
  tbb::parallel_for(std::size_t(0), batch.size(), [&](std::size_t i) {
    if (frame.hides(batch[i])) return;
    const auto [first, last] = clusters.entries(batch[i].cluster);
    for (std::uint32_t e = first; e < last; ++e) {
      if (!sides.hidden(clusters.faces[e])) kept[i * kSize + count[i]++] = e;
    }
  });
  std::size_t n = 0;
  for (std::size_t i = 0; i < batch.size(); ++i) {
    std::copy_n(kept.begin() + std::ptrdiff_t(i * kSize), count[i],
                kept.begin() + std::ptrdiff_t(n));
    n += count[i];
  }
  kept.resize(n);
  return kept;
}

}  // namespace

// The clusters go nearest first in batches that grow geometrically, each culled against what
// the batches before it drew: hierarchical z-buffer visibility (Greene, Kass & Miller 1993)
// with the scene's clusters as its boxes. Of a million triangles in a cube field, the near
// ones hide most of the rest before any is set up. Every pixel still gets the nearest key of
// all the triangles, whatever order they are drawn in.
void ScanConverter::rasterize_tiles(const RasterProjection& view, const Context& /*ctx*/,
                                    const std::function<void(const RasterTile&)>& fn) const {
  draw_clusters<RasterTile>(view, {.empty_tiles = true, .wanted = {}}, fn);
}

void ScanConverter::rasterize_depth_tiles(const RasterProjection& view, const Context& /*ctx*/,
                                          const std::function<void(const DepthTile&)>& fn,
                                          TileMask wanted, const TileStorage& keep_in) const {
  draw_clusters<DepthTile>(
      view, {.empty_tiles = false, .wanted = wanted, .keep_in = keep_in ? &keep_in : nullptr}, fn);
}

template <typename Tile>
void ScanConverter::draw_clusters(const RasterProjection& view, TileOutput output,
                                  const std::function<void(const Tile&)>& fn) const {
  std::vector<ClusterInView> order = raster::clusters_in_view(scene_, view);
  if (!output.wanted.empty()) {
    const int tiles_x = (view.width + kTile - 1) / kTile;
    std::erase_if(order,
                  [&](const ClusterInView& c) { return !reaches(c, output.wanted, tiles_x); });
  }
  std::vector<std::size_t> batch_start{0};
  if (order.size() < kCulledClusters) batch_start.push_back(order.size());
  for (std::size_t size = std::max(kFirstBatch, order.size() / 64);
       batch_start.back() < order.size(); size += size / 4) {
    batch_start.push_back(std::min(order.size(), batch_start.back() + size));
  }
  if (batch_start.size() == 1) batch_start.push_back(0);  // nothing in view: one empty batch

  TileFrame<Tile> frame(view.width, view.height, batch_start.size() - 1, output);
  const HiddenSides sides(scene_, view);
  for (std::size_t b = 0; b + 1 < batch_start.size(); ++b) {
    const std::span<const ClusterInView> batch(order.data() + batch_start[b],
                                               batch_start[b + 1] - batch_start[b]);
    const std::vector<std::uint32_t> entries = unhidden_triangles(scene_, sides, frame, batch);
    frame.draw(raster::setup_cluster_triangles(scene_, view, entries), b + 2 == batch_start.size(),
               fn);
  }
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
      if (tile.empty()) {
        std::fill_n(out.depth_key.begin() + std::ptrdiff_t(dst), tile.width, -INFINITY);
        std::fill_n(out.face.begin() + std::ptrdiff_t(dst), tile.width, kNoFace);
        continue;
      }
      std::transform(tile.depth_key + y * tile.width, tile.depth_key + (y + 1) * tile.width,
                     out.depth_key.begin() + std::ptrdiff_t(dst),
                     [](double k) { return float(k); });
      std::copy_n(tile.face + y * tile.width, tile.width, out.face.begin() + dst);
    }
  });
  return out;
}

}  // namespace shadowkit
