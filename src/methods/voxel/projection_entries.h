#pragma once
// What the projection plane holds per entry (Lai & Cheng §4): the distance of the voxel
// nearest the light (§4.1) and the list of subpatches that may block a voxel, sorted by
// distance (§4.2). Both are sparse: sorted (entry, ...) records found by binary search.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "light_projection.h"
#include "surface_voxels.h"

namespace shadowkit::voxel {

/// \brief Per entry, the smallest distance from the light of a voxel projected there.
///
/// A voxel covers the entries within \p footprint voxels of its centre's projection:
/// with 0.5, not only the centre's entry, so that entries smaller than a voxel (near a point
/// light) leave no holes between the projections of a caster's voxels, the "illegal holes"
/// of §4; with 0, the paper's projection of voxels as points.
class NearestVoxels {
 public:
  /// \p centres and \p distances: one per voxel (grid units).
  NearestVoxels(const LightProjection& projection, const std::vector<Vec3>& centres,
                const std::vector<float>& distances, double footprint);
  std::optional<float> nearest(std::uint64_t entry) const;
  std::size_t entry_count() const { return entries_.size(); }

 private:
  std::vector<std::uint64_t> entries_;
  std::vector<float> nearest_;
};

/// \brief §4.2's per-entry lists of blocking subpatches. A leaf is listed in every entry
/// its projected corners' box overlaps (so the list of the entry where a ray to the light
/// projects holds every leaf that ray can cross), at the distance of its nearest corner.
class BlockingSubpatches {
 public:
  struct Record {
    std::uint64_t entry;
    float distance;
    std::uint32_t leaf;
    auto operator<=>(const Record&) const = default;
  };
  BlockingSubpatches(const LightProjection& projection, const std::vector<Subpatch>& leaves);
  /// The list of \p entry, nearest first.
  std::span<const Record> list(std::uint64_t entry) const;
  std::size_t record_count() const { return records_.size(); }
  std::size_t memory_bytes() const { return records_.capacity() * sizeof(Record); }

 private:
  std::vector<Record> records_;
};

}  // namespace shadowkit::voxel
