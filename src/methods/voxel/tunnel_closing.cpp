#include "tunnel_closing.h"

#include <array>
#include <bit>
#include <unordered_map>
#include <unordered_set>

namespace shadowkit::voxel {
namespace {

// The 6-connected set of the voxels of \p voxels (block bits) that holds voxel \p seed:
// two voxels of a block are 6-adjacent when their bits differ in one place.
std::uint8_t component(std::uint8_t voxels, int seed) {
  std::uint8_t reached = std::uint8_t(1u << seed), grown = 0;
  while (grown != reached) {
    grown = reached;
    for (int v = 0; v < 8; ++v) {
      if (!(reached >> v & 1)) continue;
      for (const int axis : {1, 2, 4}) reached |= std::uint8_t(1u << (v ^ axis)) & voxels;
    }
  }
  return reached;
}

// The block offset of bit \p v.
VoxelIndex offset(int v) {
  return {v & 1, v >> 1 & 1, v >> 2 & 1};
}

VoxelIndex plus(const VoxelIndex& a, const VoxelIndex& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}

// The non-empty voxel of the block nearest voxel \p v: fewest differing axes, lowest bit.
int nearest_occupied(std::uint8_t occupied, int v) {
  int best = -1;
  for (int w = 0; w < 8; ++w) {
    if (!(occupied >> w & 1)) continue;
    if (best < 0 || std::popcount(unsigned(v ^ w)) < std::popcount(unsigned(v ^ best))) best = w;
  }
  return best;
}

}  // namespace

std::uint8_t tunnel_fill(std::uint8_t occupied) {
  std::uint8_t fill = 0;
  for (;;) {
    const auto empty = std::uint8_t(~(occupied | fill));
    std::uint8_t smallest = 0;
    int components = 0;
    for (std::uint8_t left = empty; left != 0;) {
      const std::uint8_t c = component(empty, std::countr_zero(left));
      left &= std::uint8_t(~c);
      ++components;
      if (smallest == 0 || std::popcount(c) < std::popcount(smallest)) smallest = c;
    }
    if (components <= 1) return fill;
    fill |= smallest;
  }
}

std::vector<TunnelFill> close_tunnels(const std::vector<std::uint64_t>& sorted_keys,
                                      const VoxelGrid& grid, const VoxelKeys& keys) {
  std::unordered_set<std::uint64_t> filled(sorted_keys.begin(), sorted_keys.end());
  std::unordered_map<std::uint64_t, std::uint64_t> source;  // of a fill: a voxel of sorted_keys
  std::vector<TunnelFill> added;
  // Blocks inside the grid that hold a non-empty voxel; those around a fill once more.
  std::vector<VoxelIndex> blocks;
  const auto blocks_around = [&](const VoxelIndex& v) {
    for (int d = 0; d < 8; ++d) {
      const VoxelIndex o{v[0] - (d & 1), v[1] - (d >> 1 & 1), v[2] - (d >> 2 & 1)};
      if (grid.contains(o) && grid.contains(plus(o, {1, 1, 1}))) blocks.push_back(o);
    }
  };
  for (const std::uint64_t key : sorted_keys) blocks_around(keys.voxel(key));
  while (!blocks.empty()) {
    const VoxelIndex o = blocks.back();
    blocks.pop_back();
    std::uint8_t occupied = 0;
    for (int v = 0; v < 8; ++v)
      occupied |= std::uint8_t(filled.count(keys.key(plus(o, offset(v)))) << v);
    const std::uint8_t fill = tunnel_fill(occupied);
    for (int v = 0; v < 8; ++v) {
      if (!(fill >> v & 1)) continue;
      const std::uint64_t key = keys.key(plus(o, offset(v)));
      const std::uint64_t near = keys.key(plus(o, offset(nearest_occupied(occupied, v))));
      const auto via = source.find(near);
      const std::uint64_t from = via == source.end() ? near : via->second;
      filled.insert(key);
      source.emplace(key, from);
      added.push_back({key, from});
      blocks_around(plus(o, offset(v)));
    }
  }
  return added;
}

}  // namespace shadowkit::voxel
