#include "surface_voxels.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <utility>

#include "bucket_sort.h"
#include "tunnel_closing.h"

namespace shadowkit::voxel {

namespace {

using Sample = std::pair<std::uint64_t, std::uint32_t>;

template <typename Emit>
void add_samples(const Subpatch& leaf, std::uint32_t id, const VoxelGrid& grid,
                 const VoxelKeys& keys, int adjacency, Emit&& emit) {
  for_each_leaf_voxel(leaf, grid, adjacency, [&](const VoxelIndex& v, std::uint32_t corner) {
    emit(Sample{keys.key(v), id * 4 + corner});
  });
}

// \p voxels with the voxels \p fills adds (tunnel_closing.h), each with its source's samples.
SurfaceVoxels with_fills(const SurfaceVoxels& voxels, std::vector<TunnelFill> fills) {
  std::sort(fills.begin(), fills.end(),
            [](const TunnelFill& a, const TunnelFill& b) { return a.key < b.key; });
  SurfaceVoxels out;
  const auto add = [&](std::uint64_t key, std::uint64_t of) {
    const auto at = std::size_t(std::lower_bound(voxels.keys.begin(), voxels.keys.end(), of) -
                                voxels.keys.begin());
    out.keys.push_back(key);
    out.samples.insert(out.samples.end(), voxels.samples.begin() + voxels.first_sample[at],
                       voxels.samples.begin() + voxels.first_sample[at + 1]);
    out.first_sample.push_back(std::uint32_t(out.samples.size()));
  };
  std::size_t next_fill = 0;
  for (const std::uint64_t key : voxels.keys) {
    for (; next_fill < fills.size() && fills[next_fill].key < key; ++next_fill) {
      add(fills[next_fill].key, fills[next_fill].source);
    }
    add(key, key);
  }
  for (; next_fill < fills.size(); ++next_fill) add(fills[next_fill].key, fills[next_fill].source);
  return out;
}

}  // namespace

SurfaceVoxels SurfaceVoxels::collect(const std::vector<Subpatch>& leaves, const VoxelGrid& grid,
                                     const VoxelKeys& keys, int adjacency, bool corners_only) {
  // In key order: grouped by brick, each brick's few samples sorted.
  std::vector<std::uint32_t> first;
  std::vector<Sample> samples;
  bucket_sort<Sample>(
      keys.brick_count(), leaves.size(),
      [&](std::size_t l, auto&& emit) {
        add_samples(leaves[l], std::uint32_t(l), grid, keys, adjacency,
                    [&](const Sample& s) { emit(keys.brick_of(s.first), s); });
      },
      first, samples);
  std::vector<std::uint32_t>().swap(first);
  SurfaceVoxels out;
  out.samples.reserve(samples.size());
  for (const auto& [key, sample] : samples) {
    if (out.keys.empty() || out.keys.back() != key) {
      if (!out.keys.empty()) out.first_sample.push_back(std::uint32_t(out.samples.size()));
      out.keys.push_back(key);
    }
    out.samples.push_back(sample);
  }
  if (!out.keys.empty()) out.first_sample.push_back(std::uint32_t(out.samples.size()));
  // §3: N = 6 promises to stop 26-paths, which corners alone do not on curved surfaces.
  if (adjacency == 6 && !corners_only) {
    std::vector<TunnelFill> fills = close_tunnels(out.keys, grid, keys);
    if (!fills.empty()) return with_fills(out, std::move(fills));
  }
  return out;
}

std::size_t SurfaceVoxels::memory_bytes() const {
  return keys.capacity() * sizeof(std::uint64_t) +
         (first_sample.capacity() + samples.capacity()) * sizeof(std::uint32_t);
}

Vec3 leaf_normal(const Subpatch& leaf) {
  const Vec3 n = cross(leaf.corner[2].vec() - leaf.corner[0].vec(),
                       leaf.corner[3].vec() - leaf.corner[1].vec());
  const double len = length(n);
  return len > 0 ? n / len : Vec3{};
}

}  // namespace shadowkit::voxel
