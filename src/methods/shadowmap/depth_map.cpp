#include "depth_map.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>

#include "shadowkit/raster/tile_bins.h"

namespace shadowkit::shadowmap {
namespace {

constexpr int kTile = DepthMap::kTile;
static_assert(kTile == raster::TileBins::kTile, "a map's tiles are the scan converter's");
constexpr float kEmpty = std::numeric_limits<float>::infinity();

}  // namespace

void DepthMap::render(const Scene& scene, const RasterProjection& view, const Context& /*ctx*/) {
  const raster::ScreenTriangles triangles = raster::setup_triangles(scene, view);
  Drawing drawing{this, view, &triangles};
  draw({&drawing, 1});
}

void DepthMap::draw(std::span<Drawing> drawings) {
  std::vector<std::optional<raster::TileBins>> bins(drawings.size());
  tbb::parallel_for(std::size_t(0), drawings.size(), [&](std::size_t d) {
    bins[d].emplace(*drawings[d].triangles, drawings[d].view.width, drawings[d].view.height);
  });
  // Only the tiles some triangle reaches are drawn, the tiles of all maps in one pass.
  struct Job {
    std::uint32_t drawing, tile;
  };
  std::vector<Job> jobs;
  for (std::size_t d = 0; d < drawings.size(); ++d) {
    drawings[d].map->allocate(drawings[d].view, bins[d]->start);
    for (int t = 0; t < bins[d]->tile_count(); ++t) {
      if (bins[d]->start[t + 1] > bins[d]->start[t])
        jobs.push_back({std::uint32_t(d), std::uint32_t(t)});
    }
  }
  std::vector<std::atomic<std::size_t>> covered(drawings.size());
  tbb::parallel_for(std::size_t(0), jobs.size(), [&](std::size_t j) {
    const Job job = jobs[j];
    const raster::TileBins& b = *bins[job.drawing];
    const std::span<const std::uint32_t> bin(b.items.data() + b.start[job.tile],
                                             b.start[job.tile + 1] - b.start[job.tile]);
    const std::size_t drawn =
        drawings[job.drawing].map->draw_tile(int(job.tile), *drawings[job.drawing].triangles, bin);
    covered[job.drawing].fetch_add(drawn, std::memory_order_relaxed);
  });
  for (std::size_t d = 0; d < drawings.size(); ++d) drawings[d].map->covered_ = covered[d].load();
}

void DepthMap::allocate(const RasterProjection& view, std::span<const std::uint32_t> bin_start) {
  view_ = view;
  texel_side_ = std::max(1.0 / view.scale_x, 1.0 / view.scale_y);
  tiles_x_ = (view.width + kTile - 1) / kTile;
  slot_.assign(bin_start.size() - 1, 0);
  std::uint32_t slots = 1;
  for (std::size_t t = 0; t + 1 < bin_start.size(); ++t) {
    if (bin_start[t + 1] > bin_start[t]) slot_[t] = slots++;
  }
  if (texels_.size() < slots * kTileTexels) texels_.resize(slots * kTileTexels);
  std::fill_n(texels_.begin(), kTileTexels, kEmpty);
}

std::size_t DepthMap::draw_tile(int tile, const raster::ScreenTriangles& triangles,
                                std::span<const std::uint32_t> bin) {
  thread_local std::array<double, kTileTexels> keys;
  const int x0 = (tile % tiles_x_) * kTile, y0 = (tile / tiles_x_) * kTile;
  const int h = std::min(kTile, view_.height - y0);
  // Williams 1978, first pass: a z-buffer rendering of the scene from the light, keeping only
  // depth; the scan converter's own, without face ids. Drawn kTile wide: texels past the
  // map's right edge stay -infinity, and count as not drawn.
  raster::draw_tile(triangles, bin, x0, y0, kTile, h, keys.data(), nullptr);
  float* out = texels_.data() + std::size_t(slot_[std::size_t(tile)]) * kTileTexels;
  // Loops without branches, which the compiler vectorizes.
  const int n = kTile * h;
  if (view_.orthographic) {
    for (int k = 0; k < n; ++k) out[k] = float(-keys[k]);
  } else {
    for (int k = 0; k < n; ++k) out[k] = float(1.0 / keys[k]);
  }
  for (int k = 0; k < n; ++k) out[k] = keys[k] == -INFINITY ? kEmpty : out[k];
  return std::size_t(
      std::count_if(keys.begin(), keys.begin() + n, [](double key) { return key != -INFINITY; }));
}

std::size_t DepthMap::memory_bytes() const {
  return texels_.capacity() * sizeof(float) + slot_.capacity() * sizeof(std::uint32_t);
}

}  // namespace shadowkit::shadowmap
