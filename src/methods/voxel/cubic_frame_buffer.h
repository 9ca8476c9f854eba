#pragma once
// Lai & Cheng §5.2: one cubic frame buffer for the whole scene, each voxel 0 (empty),
// 1 (lit) or 2 (shadowed). Stored in sparse bricks of 8^3 voxels at 2 bits a voxel: a
// surface touches O(M^2) of the M^3 voxels, so 1024^3 costs megabytes, not 256 MB.
#include <array>
#include <cstdint>
#include <vector>

#include "voxel_grid.h"

namespace shadowkit::voxel {

enum class VoxelState : std::uint8_t { empty = 0, lit = 1, shadowed = 2 };

/// \brief Names voxels by 64-bit keys in brick-major order, so that sorting keys groups
/// the voxels of a brick.
struct VoxelKeys {
  VoxelIndex bricks;  ///< bricks per axis

  explicit VoxelKeys(const VoxelIndex& dims);
  std::uint64_t key(const VoxelIndex& v) const;
  VoxelIndex voxel(std::uint64_t key) const;
  std::uint64_t brick_of(std::uint64_t key) const { return key >> 9; }
  std::uint64_t brick_count() const;
};

/// \brief The cubic frame buffer.
class CubicFrameBuffer {
 public:
  CubicFrameBuffer() : keys_({1, 1, 1}) {}
  /// Marks the voxels of \p sorted_keys (ascending) non-empty (lit).
  CubicFrameBuffer(const VoxelGrid& grid, const std::vector<std::uint64_t>& sorted_keys);

  const VoxelGrid& grid() const { return grid_; }
  const VoxelKeys& keys() const { return keys_; }
  VoxelState state(const VoxelIndex& v) const;
  /// Sets a non-empty voxel's state (lit or shadowed).
  void set(std::uint64_t key, VoxelState state);
  std::size_t memory_bytes() const;

 private:
  using Brick = std::array<std::uint64_t, 16>;  // 512 voxels x 2 bits
  static constexpr std::uint32_t kNoBrick = ~std::uint32_t(0);

  VoxelGrid grid_;
  VoxelKeys keys_;
  std::vector<std::uint32_t> directory_;  ///< brick slot per brick, or kNoBrick
  std::vector<Brick> bricks_;
};

}  // namespace shadowkit::voxel
