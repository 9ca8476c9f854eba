#pragma once
// A parallel counting sort into buckets, for the per-entry and per-brick lists of the
// voxel method: count, prefix sums, fill, then each bucket's few records sorted. It
// replaces a sort of all records (most of §3 + §4's time at M = 512).
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <vector>

namespace shadowkit::voxel {

/// Runs \p for_each(i, emit) for items 0..n-1 twice (in parallel), where emit(bucket,
/// record) files a record under bucket < \p buckets; leaves bucket b's records in
/// records[first[b] .. first[b + 1]), ascending.
template <typename Record, typename ForEach>
void bucket_sort(std::size_t buckets, std::size_t n, const ForEach& for_each,
                 std::vector<std::uint32_t>& first, std::vector<Record>& records) {
  first.assign(buckets + 1, 0);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    for_each(i, [&](std::size_t bucket, const Record&) {
      std::atomic_ref<std::uint32_t>(first[bucket + 1]).fetch_add(1, std::memory_order_relaxed);
    });
  });
  for (std::size_t b = 1; b < first.size(); ++b) first[b] += first[b - 1];
  records.resize(first.back());
  std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    for_each(i, [&](std::size_t bucket, const Record& record) {
      records[std::atomic_ref<std::uint32_t>(next[bucket])
                  .fetch_add(1, std::memory_order_relaxed)] = record;
    });
  });
  tbb::parallel_for(std::size_t(0), buckets, [&](std::size_t b) {
    std::sort(records.begin() + first[b], records.begin() + first[b + 1]);
  });
}

}  // namespace shadowkit::voxel
