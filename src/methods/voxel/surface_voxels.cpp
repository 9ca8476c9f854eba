#include "surface_voxels.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <utility>

namespace shadowkit::voxel {

SurfaceVoxels SurfaceVoxels::collect(const std::vector<Subpatch>& leaves, const VoxelGrid& grid,
                                     const VoxelKeys& keys) {
  constexpr std::uint64_t kOutside = ~std::uint64_t(0);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> samples(leaves.size() * 4);
  tbb::parallel_for(std::size_t(0), leaves.size(), [&](std::size_t l) {
    for (std::uint32_t k = 0; k < 4; ++k) {
      const VoxelIndex v = voxel_floor(leaves[l].corner[k].vec());
      samples[l * 4 + k] = {grid.contains(v) ? keys.key(v) : kOutside, std::uint32_t(l * 4 + k)};
    }
  });
  tbb::parallel_sort(samples.begin(), samples.end());
  SurfaceVoxels out;
  for (const auto& [key, sample] : samples) {
    if (key == kOutside) break;  // sorted last
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
