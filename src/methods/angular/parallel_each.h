#pragma once
// A parallel loop over indices that leaves small ranges to the calling thread.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>

namespace shadowkit::angular {

/// Below this many indices a loop is not worth a task.
constexpr std::size_t kParallelGrain = 512;

/// Calls \p body(i) for every i in [0, \p n), split into blocks of at least kParallelGrain
/// indices: the per-object loops of a scene of thousands of small objects run in the task of
/// their object, without even a call into the scheduler, instead of in tasks of a few faces.
template <class Index, class Body>
void parallel_each(Index n, const Body& body) {
  constexpr Index kGrain = Index(kParallelGrain);
  if (n <= kGrain) {
    for (Index i = 0; i < n; ++i) body(i);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<Index>(Index(0), n, kGrain),
                    [&](const tbb::blocked_range<Index>& r) {
                      for (Index i = r.begin(); i != r.end(); ++i) body(i);
                    });
}

}  // namespace shadowkit::angular
