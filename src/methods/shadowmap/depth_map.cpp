#include "depth_map.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "shadowkit/core/error.h"

namespace shadowkit::shadowmap {
namespace {

constexpr int kTile = DepthMap::kTile;
static_assert(kTile == ScanConverter::kTileSize, "a map's tiles are the scan converter's");
constexpr float kEmpty = std::numeric_limits<float>::infinity();

}  // namespace

void DepthMap::draw(const Scene& scene, const Context& ctx, ScanConverter::TileMask wanted) {
  if (!wanted.empty() && std::find(wanted.begin(), wanted.end(), 1) == wanted.end()) return;
  for (std::size_t t = 0; t < drawn_.size(); ++t) {
    if (!wanted.empty() && !wanted[t]) continue;
    SHADOWKIT_CHECK(!drawn_[t]);  // each tile has room for one slot
    drawn_[t] = 1;
  }
  std::atomic<std::uint32_t> slots{std::uint32_t(slots_)};
  std::atomic<std::size_t> covered{covered_};
  // A tile's slot, taken when it is first drawn into: tiles kept between batches are drawn
  // in it, and their keys become depth in place.
  const auto slot_of = [&](std::size_t t) {
    if (slot_[t] == 0) slot_[t] = slots.fetch_add(1, std::memory_order_relaxed);
    return slot_[t];
  };
  // Williams 1978, first pass: a z-buffer rendering of the scene from the light, keeping only
  // depth; the scan converter's own, so that what a nearer surface hides is never drawn.
  ScanConverter(scene).rasterize_depth_tiles(
      view_, ctx,
      [&](const DepthTile& tile) {
        const std::size_t t = std::size_t(tile.y0 / kTile) * tiles_x_ + tile.x0 / kTile;
        covered.fetch_add(store(tile, slot_of(t)), std::memory_order_relaxed);
      },
      wanted, [&](std::size_t t) { return texels_.get() + std::size_t(slot_of(t)) * kTileTexels; });
  slots_ = slots.load();
  covered_ = covered.load();
}

void DepthMap::start(const RasterProjection& view) {
  view_ = view;
  texel_side_ = std::max(1.0 / view.scale_x, 1.0 / view.scale_y);
  grid_ = {float(view.offset_x), float(view.offset_y), float(view.scale_x),
           float(view.scale_y),  view.width,           view.height};
  tiles_x_ = (view.width + kTile - 1) / kTile;
  const int tiles_y = (view.height + kTile - 1) / kTile;
  slot_.assign(std::size_t(tiles_x_) * tiles_y, 0);
  drawn_.assign(slot_.size(), 0);
  if (capacity_ < slot_.size() + 1) {
    capacity_ = slot_.size() + 1;
    texels_ = make_huge_page_array<float>(capacity_ * kTileTexels);
  }
  std::fill_n(texels_.get(), kTileTexels, kEmpty);
  slots_ = 1;
  covered_ = 0;
}

// Stores a drawn tile's keys as linear depth in \p slot; returns how many texels were drawn.
std::size_t DepthMap::store(const DepthTile& tile, std::uint32_t slot) {
  float* out = texels_.get() + std::size_t(slot) * kTileTexels;
  std::size_t drawn = 0;
  for (int y = 0; y < tile.height; ++y) {
    const float* key = tile.depth_key + y * tile.width;
    drawn += view_.orthographic ? store_row<true>(key, tile.width, out + y * kTile)
                                : store_row<false>(key, tile.width, out + y * kTile);
  }
  return drawn;
}

// One row of store(), in loops without branches, which the compiler vectorizes. A key of
// -inf (nothing drawn) gives +inf either way: -(-inf), and 1 / 0. In float: a division in
// double would take most of the time of drawing a map that a few large faces fill.
template <bool kOrthographic>
int DepthMap::store_row(const float* key, int n, float* depth) {
  // Counted first: a tile drawn in its slot becomes depth in place.
  const int drawn = int(std::count_if(key, key + n, [](float k) { return k != -INFINITY; }));
  for (int x = 0; x < n; ++x) depth[x] = linear_depth<kOrthographic>(key[x]);
  return drawn;
}

std::size_t DepthMap::drawn_tiles() const {
  return std::size_t(std::count(drawn_.begin(), drawn_.end(), 1));
}

std::size_t DepthMap::memory_bytes() const {
  return slots_ * kTileTexels * sizeof(float) + slot_.capacity() * sizeof(std::uint32_t) +
         drawn_.capacity();
}

}  // namespace shadowkit::shadowmap
