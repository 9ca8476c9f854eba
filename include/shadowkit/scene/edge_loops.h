#pragma once
/// \brief Chaining directed mesh edges into loops (Crow's contour loops, Thakur et al.'s
/// ridge-edge loops).
#include <cstdint>
#include <span>
#include <vector>

namespace shadowkit {

/// \brief Edges walked end to start, as indices into the list that was chained.
struct EdgeLoop {
  std::vector<std::uint32_t> edges;
  bool closed = false;  ///< the last edge ends where the first starts
};

/// Chains directed edges (edge i runs from vertex from[i] to to[i]) into loops, each edge used
/// once, in order of their first edge; at a vertex with several continuations the first
/// unused one is taken.
std::vector<EdgeLoop> chain_edge_loops(std::span<const std::uint32_t> from,
                                       std::span<const std::uint32_t> to);

/// The same for any edge type with `from` and `to` members.
template <class Edge>
std::vector<EdgeLoop> chain_edge_loops(std::span<const Edge> edges) {
  std::vector<std::uint32_t> from, to;
  from.reserve(edges.size());
  to.reserve(edges.size());
  for (const Edge& e : edges) from.push_back(e.from), to.push_back(e.to);
  return chain_edge_loops(std::span<const std::uint32_t>(from), std::span<const std::uint32_t>(to));
}

}  // namespace shadowkit
