#include "shadowkit/scene/edge_loops.h"

#include <gtest/gtest.h>

namespace shadowkit {
namespace {

std::vector<std::vector<std::uint32_t>> chained(const std::vector<std::uint32_t>& from,
                                                const std::vector<std::uint32_t>& to,
                                                std::vector<bool>* closed = nullptr) {
  std::vector<std::vector<std::uint32_t>> out;
  for (const EdgeLoop& loop : chain_edge_loops(from, to)) {
    out.push_back(loop.edges);
    if (closed) closed->push_back(loop.closed);
  }
  return out;
}

// A figure eight through vertex 0 (two triangles sharing it), then an open path.
const std::vector<std::uint32_t> kFrom{0, 1, 2, 0, 3, 4, 5, 6};
const std::vector<std::uint32_t> kTo{1, 2, 0, 3, 4, 0, 6, 7};

TEST(EdgeLoops, TakeTheFirstUnusedEdgeAtABranchAndLeaveOpenPathsOpen) {
  std::vector<bool> closed;
  // At vertex 0, edge 0's loop ends where it began; edge 3 starts the second triangle.
  EXPECT_EQ(chained(kFrom, kTo, &closed),
            (std::vector<std::vector<std::uint32_t>>{{0, 1, 2}, {3, 4, 5}, {6, 7}}));
  EXPECT_EQ(closed, (std::vector<bool>{true, true, false}));
}

TEST(EdgeLoops, ChainTheSameWhateverTheVertexIdsSpan) {
  // Vertex ids spread far apart (a sub-object's few edges in a large mesh) are searched, not
  // indexed; the loops are the same, and so is the choice at the branch.
  const auto spread = [](std::vector<std::uint32_t> ids) {
    for (std::uint32_t& v : ids) v = v * 1'000'003u + 17u;
    return ids;
  };
  EXPECT_EQ(chained(spread(kFrom), spread(kTo)), chained(kFrom, kTo));
  EXPECT_TRUE(chain_edge_loops(std::span<const std::uint32_t>{}, {}).empty());
}

}  // namespace
}  // namespace shadowkit
