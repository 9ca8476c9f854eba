#include "cubic_frame_buffer.h"

#include "shadowkit/core/error.h"

namespace shadowkit::voxel {

VoxelKeys::VoxelKeys(const VoxelIndex& dims)
    : bricks{(dims[0] + 7) / 8, (dims[1] + 7) / 8, (dims[2] + 7) / 8} {}

std::uint64_t VoxelKeys::key(const VoxelIndex& v) const {
  const std::uint64_t brick = std::uint64_t(v[0] >> 3) +
                              std::uint64_t(bricks[0]) * (std::uint64_t(v[1] >> 3) +
                                                          std::uint64_t(bricks[1]) * (v[2] >> 3));
  return brick << 9 | std::uint64_t((v[0] & 7) | (v[1] & 7) << 3 | (v[2] & 7) << 6);
}

VoxelIndex VoxelKeys::voxel(std::uint64_t key) const {
  const std::uint64_t brick = key >> 9;
  const int local = int(key & 511);
  const int bx = int(brick % bricks[0]), by = int(brick / bricks[0] % bricks[1]);
  const int bz = int(brick / bricks[0] / bricks[1]);
  return {bx * 8 + (local & 7), by * 8 + (local >> 3 & 7), bz * 8 + (local >> 6)};
}

std::uint64_t VoxelKeys::brick_count() const {
  return std::uint64_t(bricks[0]) * bricks[1] * bricks[2];
}

CubicFrameBuffer::CubicFrameBuffer(const VoxelGrid& grid,
                                   const std::vector<std::uint64_t>& sorted_keys)
    : grid_(grid), keys_(grid.dims), directory_(keys_.brick_count(), kNoBrick) {
  for (const std::uint64_t key : sorted_keys) {
    std::uint32_t& slot = directory_[keys_.brick_of(key)];
    if (slot == kNoBrick) {
      slot = std::uint32_t(bricks_.size());
      bricks_.push_back({});
    }
    set(key, VoxelState::lit);
  }
}

VoxelState CubicFrameBuffer::state(const VoxelIndex& v) const {
  if (!grid_.contains(v)) return VoxelState::empty;
  const std::uint64_t key = keys_.key(v);
  const std::uint32_t slot = directory_[keys_.brick_of(key)];
  if (slot == kNoBrick) return VoxelState::empty;
  const unsigned bit = unsigned(key & 511) * 2;
  return VoxelState(bricks_[slot][bit / 64] >> (bit % 64) & 3);
}

void CubicFrameBuffer::set(std::uint64_t key, VoxelState state) {
  const std::uint32_t slot = directory_[keys_.brick_of(key)];
  SHADOWKIT_CHECK(slot != kNoBrick);
  const unsigned bit = unsigned(key & 511) * 2;
  std::uint64_t& word = bricks_[slot][bit / 64];
  word = (word & ~(std::uint64_t(3) << (bit % 64))) | std::uint64_t(state) << (bit % 64);
}

std::size_t CubicFrameBuffer::memory_bytes() const {
  return directory_.capacity() * sizeof(std::uint32_t) + bricks_.capacity() * sizeof(Brick);
}

}  // namespace shadowkit::voxel
