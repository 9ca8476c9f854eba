#include "shadowkit/scene/edge_loops.h"

#include <algorithm>
#include <numeric>

namespace shadowkit {

namespace {

// The edges by the vertex they leave, each vertex's in index order. Indexed by vertex where
// the edges' vertex ids span a range not much longer than their count (a mesh's, an
// object's); sorted and searched where they do not (a sub-object's few edges in a large
// mesh), so that the cost never grows with the mesh.
class EdgesByStart {
 public:
  explicit EdgesByStart(std::span<const std::uint32_t> from) : from_(from), order_(from.size()) {
    if (from.empty()) return;
    lo_ = *std::min_element(from.begin(), from.end());
    const std::uint64_t span = std::uint64_t(*std::max_element(from.begin(), from.end())) - lo_ + 1;
    if (span <= 8 * std::uint64_t(from.size()) + 64) {
      start_.assign(span + 1, 0);
      for (const std::uint32_t v : from) ++start_[v - lo_ + 1];
      for (std::size_t v = 0; v + 1 < start_.size(); ++v) start_[v + 1] += start_[v];
      std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
      for (std::uint32_t i = 0; i < from.size(); ++i) order_[fill[from[i] - lo_]++] = i;
    } else {
      std::iota(order_.begin(), order_.end(), 0u);
      std::stable_sort(order_.begin(), order_.end(),
                       [&](std::uint32_t a, std::uint32_t b) { return from[a] < from[b]; });
    }
  }

  /// The edges leaving vertex \p v.
  std::span<const std::uint32_t> leaving(std::uint32_t v) const {
    if (!start_.empty()) {
      if (v < lo_ || v - lo_ + 1 >= start_.size()) return {};
      return {order_.data() + start_[v - lo_], order_.data() + start_[v - lo_ + 1]};
    }
    const auto first = std::partition_point(order_.begin(), order_.end(),
                                            [&](std::uint32_t e) { return from_[e] < v; });
    const auto last =
        std::partition_point(first, order_.end(), [&](std::uint32_t e) { return from_[e] == v; });
    return {order_.data() + (first - order_.begin()), std::size_t(last - first)};
  }

 private:
  std::span<const std::uint32_t> from_;
  std::vector<std::uint32_t> order_;
  std::uint32_t lo_ = 0;
  std::vector<std::uint32_t> start_;  ///< per vertex from lo_, where its edges begin
};

}  // namespace

std::vector<EdgeLoop> chain_edge_loops(std::span<const std::uint32_t> from,
                                       std::span<const std::uint32_t> to) {
  const EdgesByStart by_start(from);
  std::vector<char> used(from.size(), 0);
  // An unused edge leaving vertex v, or -1.
  const auto next_from = [&](std::uint32_t v) -> std::int64_t {
    for (const std::uint32_t e : by_start.leaving(v)) {
      if (!used[e]) return e;
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
