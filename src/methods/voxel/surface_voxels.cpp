#include "surface_voxels.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <utility>

#include "bucket_sort.h"

namespace shadowkit::voxel {

namespace {

using Sample = std::pair<std::uint64_t, std::uint32_t>;

// The corner voxels of \p leaf; where the recursion stopped on a leaf far below a voxel
// whose corners are still not N-adjacent (it straddles a voxel edge or vertex), also the
// voxels of an axis-by-axis path from corner 0 to the others, so that the surface stays
// N-connected there. Bridging voxels take corner 0's sample (it lies within a tiny
// fraction of a voxel from them).
template <typename Emit>
void add_samples(const Subpatch& leaf, std::uint32_t id, const VoxelGrid& grid,
                 const VoxelKeys& keys, int adjacency, Emit&& emit) {
  const auto add = [&](const VoxelIndex& v, std::uint32_t sample) {
    if (grid.contains(v)) emit(Sample{keys.key(v), sample});
  };
  const VoxelIndex first = voxel_floor(leaf.corner[0].vec());
  for (std::uint32_t k = 0; k < 4; ++k) {
    const VoxelIndex v = voxel_floor(leaf.corner[k].vec());
    add(v, id * 4 + k);
    if (adjacent(first, v, adjacency)) continue;
    VoxelIndex step = first;
    for (int a = 0; a < 2; ++a) {
      step[a] = v[a];
      add(step, id * 4);
    }
  }
}

}  // namespace

SurfaceVoxels SurfaceVoxels::collect(const std::vector<Subpatch>& leaves, const VoxelGrid& grid,
                                     const VoxelKeys& keys, int adjacency) {
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
