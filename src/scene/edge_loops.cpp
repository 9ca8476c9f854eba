#include "shadowkit/scene/edge_loops.h"

#include <unordered_map>

namespace shadowkit {

std::vector<EdgeLoop> chain_edge_loops(std::span<const std::uint32_t> from,
                                       std::span<const std::uint32_t> to) {
  std::unordered_multimap<std::uint32_t, std::uint32_t> starting_at;
  for (std::uint32_t i = 0; i < from.size(); ++i) starting_at.emplace(from[i], i);
  std::vector<char> used(from.size(), 0);
  // An unused edge leaving vertex v, or -1.
  const auto next_from = [&](std::uint32_t v) -> std::int64_t {
    auto [lo, hi] = starting_at.equal_range(v);
    for (auto it = lo; it != hi; ++it) {
      if (!used[it->second]) return it->second;
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
