#pragma once
// What the projection plane holds per entry (Lai & Cheng §4): the distance of the voxel
// nearest the light (§4.1) and the list of subpatches that may block a voxel, sorted by
// distance (§4.2). Both are flat arrays over the entries that anything reaches, numbered
// densely per face (EntryRectangles), filled by counting, not by sorting records.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "light_projection.h"
#include "surface_voxels.h"

namespace shadowkit::voxel {

/// \brief Dense numbers for entries: per projection face, the rectangle of entries that
/// include() was given, row by row.
class EntryRectangles {
 public:
  void include(std::uint64_t entry);
  void include(const EntryRectangles& other);
  /// Numbers the rectangles; include() must not be called after.
  void finish();
  /// The dense number of \p entry, or nothing outside every rectangle.
  std::optional<std::size_t> index(std::uint64_t entry) const;
  std::size_t size() const { return size_; }

 private:
  struct Rectangle {
    std::uint64_t x0 = ~std::uint64_t(0), x1 = 0, y0 = ~std::uint64_t(0), y1 = 0;
    std::size_t first = 0;
    bool empty() const { return x0 > x1; }
  };
  static constexpr int kFaces = 6;
  std::array<Rectangle, kFaces> faces_;
  std::size_t size_ = 0;
};

/// \brief Per entry, the smallest distance from the light of a voxel projected there.
///
/// A voxel covers the entries within \p footprint voxels of its centre's projection:
/// with 0.5, not only the centre's entry, so that entries smaller than a voxel (near a point
/// light) leave no holes between the projections of a caster's voxels, the "illegal holes"
/// of §4; with 0, the paper's projection of voxels as points.
class NearestVoxels {
 public:
  /// Calls its argument with the centre (grid units) of every voxel of part \p part; a
  /// voxel may come more than once. Parts run in parallel and are each visited twice.
  using VoxelCentres =
      std::function<void(std::size_t part, const std::function<void(Vec3 centre)>& centre)>;
  NearestVoxels(const LightProjection& projection, std::size_t parts, const VoxelCentres& centres,
                double footprint);
  std::optional<float> nearest(std::uint64_t entry) const;
  std::size_t entry_count() const { return entry_count_; }
  std::size_t memory_bytes() const { return nearest_.capacity() * sizeof(float); }

 private:
  EntryRectangles rectangles_;
  std::vector<float> nearest_;  ///< per dense entry; infinity where no voxel projects
  std::size_t entry_count_ = 0;
};

/// \brief §4.2's per-entry lists of blocking subpatches. A leaf is listed in every entry
/// its projected corners' box overlaps (so the list of the entry where a ray to the light
/// projects holds every leaf that ray can cross), at the distance of its nearest corner.
class BlockingSubpatches {
 public:
  struct Record {
    float distance;
    std::uint32_t leaf;
    auto operator<=>(const Record&) const = default;
  };
  BlockingSubpatches(const LightProjection& projection, const std::vector<Subpatch>& leaves);
  /// The list of \p entry, nearest first.
  std::span<const Record> list(std::uint64_t entry) const;
  std::size_t record_count() const { return records_.size(); }
  std::size_t memory_bytes() const {
    return records_.capacity() * sizeof(Record) + first_.capacity() * sizeof(std::uint32_t);
  }

 private:
  EntryRectangles rectangles_;
  std::vector<std::uint32_t> first_;  ///< dense entry e: records_[first_[e] .. first_[e + 1])
  std::vector<Record> records_;
};

}  // namespace shadowkit::voxel
