#include "shadowkit/scene/edge_loops.h"

#include <algorithm>

namespace shadowkit {

std::vector<EdgeLoop> chain_edge_loops(std::span<const std::uint32_t> from,
                                       std::span<const std::uint32_t> to) {
  // The edges leaving each vertex, in index order (compressed rows).
  std::uint32_t vertices = 0;
  for (const std::uint32_t v : from) vertices = std::max(vertices, v + 1);
  std::vector<std::uint32_t> start(vertices + 1, 0), leaving(from.size());
  for (const std::uint32_t v : from) ++start[v + 1];
  for (std::uint32_t v = 0; v < vertices; ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t i = 0; i < from.size(); ++i) leaving[fill[from[i]]++] = i;
  std::vector<char> used(from.size(), 0);
  // An unused edge leaving vertex v, or -1.
  const auto next_from = [&](std::uint32_t v) -> std::int64_t {
    if (v >= vertices) return -1;
    for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) {
      if (!used[leaving[k]]) return leaving[k];
    }
    return -1;
  };
  std::vector<EdgeLoop> loops;
  for (std::uint32_t first = 0; first < from.size(); ++first) {
    if (used[first]) continue;
    EdgeLoop loop;
    for (std::int64_t e = first; e >= 0; e = next_from(to[e])) {
      used[e] = 1;
      loop.edges.push_back(std::uint32_t(e));
      if (to[e] == from[first]) break;
    }
    loop.closed = to[loop.edges.back()] == from[first];
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace shadowkit
