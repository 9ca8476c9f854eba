#pragma once
// A parallel loop over indices that leaves small ranges to the calling thread.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace shadowkit {

/// Calls \p body(i) for every i in [0, \p n), split into blocks of at least 512 indices:
/// the per-object loops of a scene of thousands of small objects run inline in the task of
/// their object instead of spawning tasks of a few faces each.
template <class Index, class Body>
void parallel_each(Index n, const Body& body) {
  constexpr Index kGrain = 512;
  tbb::parallel_for(tbb::blocked_range<Index>(Index(0), n, kGrain),
                    [&](const tbb::blocked_range<Index>& r) {
                      for (Index i = r.begin(); i != r.end(); ++i) body(i);
                    });
}

}  // namespace shadowkit
