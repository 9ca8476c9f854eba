#pragma once
// A parallel loop whose results keep their order: fixed runs of indices, each appending to a
// list of its own, the lists joined in run order.
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace shadowkit {

/// Calls \p body(i, list) for every i in [0, \p n), in fixed runs of \p run indices, and
/// appends to \p out what the calls appended to their run's list, in index order whichever
/// thread took which run. One run is done on the calling thread; several in parallel,
/// isolated: while it waits, the calling thread takes no outside task, which could reuse
/// its thread_local buffers.
template <class T, class Body>
void append_in_runs(std::size_t n, std::size_t run, std::vector<T>& out, const Body& body) {
  if (n <= run) {
    for (std::size_t i = 0; i < n; ++i) body(i, out);
    return;
  }
  std::vector<std::vector<T>> lists((n + run - 1) / run);
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(std::size_t(0), lists.size(), [&](std::size_t r) {
      for (std::size_t i = r * run; i < std::min(n, (r + 1) * run); ++i) body(i, lists[r]);
    });
  });
  for (const std::vector<T>& list : lists) out.insert(out.end(), list.begin(), list.end());
}

}  // namespace shadowkit
