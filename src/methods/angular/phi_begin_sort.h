#pragma once
// Step 1.7 of the discretized-shadow-volume paper (Sec. 7): each entry sorted by phi.
#include <cstdint>
#include <span>
#include <vector>

#include "angular_pair.h"

namespace shadowkit::angular {

/// \brief A stable sort of one entry's pairs by phi_begin, whose buffers serve one entry
/// after another. The pairs arrive in the order of their loops' least phi, not of their
/// begins in this entry, and an insertion sort alone mispredicts its exit about once per
/// pair. So first a counting sort, whose only branches are the loops', into four buckets
/// per pair that split the entry's finite begins evenly; then an insertion sort, which
/// moves only pairs that share a bucket. Infinite begins (from the light's axis, Sec. 11.2)
/// go to the end buckets.
class PhiBeginSort {
 public:
  /// \p entry's pairs sorted by phi_begin, equal ones in their given order; valid until the
  /// next call.
  std::span<const AngularPair> operator()(std::span<const AngularPair> entry);

 private:
  std::vector<std::uint32_t> bucket_;  // per pair
  std::vector<std::uint32_t> next_;    // per bucket, its next slot in sorted_
  std::vector<AngularPair> sorted_;
};

}  // namespace shadowkit::angular
