// ShadowGenerator::process_in_cells: §6's balanced cells filled in parallel.
#include <tbb/parallel_for.h>

#include <algorithm>

#include "shadow_generator.h"
#include "shadowkit/core/error.h"

namespace shadowkit::svbsp {
namespace {

// A piece's part in a cell, and the node's pieces it came with.
struct CellEntry {
  ConvexPolygon part;
  std::uint32_t group;
};

// A cell's fragments, and each entry's range of them.
struct CellFragments {
  std::vector<Fragment> fragments;
  std::vector<std::pair<std::size_t, std::size_t>> of_entry;
};

// Fig. 3 for one cell's entries in order, down \p tree: as process_coplanar(), a node's
// pieces classified together when \p together says so, then their lit fragments' volumes
// added; else each piece filtered and added at once.
CellFragments fill_cell(SvbspTree& tree, std::span<const CellEntry> entries,
                        const std::vector<char>& together) {
  CellFragments out;
  out.of_entry.reserve(entries.size());
  for (std::size_t i = 0; i < entries.size();) {
    const std::uint32_t group = entries[i].group;
    const std::size_t group_first = out.fragments.size();
    for (; i < entries.size() && entries[i].group == group; ++i) {
      const std::size_t first = out.fragments.size();
      if (together[group])
        tree.classify(entries[i].part, out.fragments);
      else
        tree.determine_shadow(entries[i].part, out.fragments);
      out.of_entry.emplace_back(first, out.fragments.size());
    }
    if (!together[group]) continue;
    for (std::size_t f = group_first; f < out.fragments.size(); ++f) {
      if (out.fragments[f].lit) tree.enlarge(out.fragments[f].polygon);
    }
  }
  return out;
}

// Groups (BSP nodes) a thread routes at a time.
constexpr std::size_t kGroupsPerChunk = 1024;

// A scene piece as process_coplanar() takes it: shadowed whole and alone, or filtered, its
// way down the cells' planes steps [first_step, end_step) of its chunk.
struct Piece {
  const ConvexPolygon* piece;
  std::uint32_t chunk;
  std::size_t first_step, end_step;
  bool filtered;
};

// The steps of a chunk of groups, and its leaf steps by cell.
struct RouteChunk {
  std::vector<SvbspTree::RouteStep> steps;
  std::vector<std::uint32_t> group_of_step;
  std::vector<std::uint32_t> entry_of_step;  ///< a leaf step: its entry in its cell
  std::vector<std::uint32_t> leaves;         ///< leaf steps, by cell, in order
  std::vector<std::uint32_t> cell_start;     ///< per cell: its first in leaves
  std::size_t light_facing = 0;

  // A counting sort of the leaf steps by cell, each cell's in step order.
  void sort_leaves(std::size_t cells) {
    cell_start.assign(cells + 1, 0);
    for (const SvbspTree::RouteStep& step : steps) {
      if (step.cell >= 0) ++cell_start[std::size_t(step.cell) + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) cell_start[c + 1] += cell_start[c];
    leaves.resize(cell_start[cells]);
    std::vector<std::uint32_t> next(cell_start.begin(), cell_start.end() - 1);
    for (std::uint32_t s = 0; s < steps.size(); ++s) {
      if (steps[s].cell >= 0) leaves[next[std::size_t(steps[s].cell)]++] = s;
    }
    entry_of_step.resize(steps.size());
  }
};

}  // namespace

void ShadowGenerator::process_in_cells(const SceneBsp& bsp, std::vector<Fragment>& out) {
  SHADOWKIT_CHECK(solids_ == nullptr && tree_.cell_count() > 1);
  // The nodes in front-to-back order; each node's pieces are a group (process_coplanar).
  std::vector<std::span<const ConvexPolygon>> groups;
  bsp.front_to_back(light_, [&](NodePieces node) {
    SHADOWKIT_CHECK(node.solid < 0);
    groups.push_back(node.pieces);
  });
  std::vector<char> together(groups.size());
  std::vector<Piece> pieces;
  std::vector<std::size_t> first_piece(groups.size() + 1, 0);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    first_piece[g + 1] = first_piece[g] + groups[g].size();
  }
  pieces.resize(first_piece.back());

  // Chunks of groups in parallel: which pieces are filtered, and their ways down the cells'
  // planes, each chunk's steps in order and its leaf steps sorted by cell.
  const std::size_t cells = tree_.cell_count();
  std::vector<RouteChunk> chunks((groups.size() + kGroupsPerChunk - 1) / kGroupsPerChunk);
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t c) {
    RouteChunk& chunk = chunks[c];
    const std::size_t end = std::min(groups.size(), (c + 1) * kGroupsPerChunk);
    for (std::size_t g = c * kGroupsPerChunk; g < end; ++g) {
      const std::span<const ConvexPolygon> coplanar = groups[g];
      const Coplanar group = coplanar_pieces(coplanar);
      together[g] = group.together;
      for (std::size_t k = 0; k < coplanar.size(); ++k) {
        const ConvexPolygon& piece = coplanar[k];
        Piece& plan = pieces[first_piece[g] + k];
        plan = {&piece, std::uint32_t(c), chunk.steps.size(), chunk.steps.size(), false};
        if (!filtered(piece, group)) continue;
        ++chunk.light_facing;
        plan.filtered = true;
        tree_.route(piece, chunk.steps);
        plan.end_step = chunk.steps.size();
        chunk.group_of_step.resize(plan.end_step, std::uint32_t(g));
      }
    }
    chunk.sort_leaves(cells);
  });
  for (const RouteChunk& chunk : chunks) light_facing_ += chunk.light_facing;

  // Each cell's parts in piece order, filtered down the cell's own tree.
  cell_trees_.assign(cells, tree_.empty_like());
  std::vector<CellFragments> filled(cells);
  tbb::parallel_for(std::size_t(0), cells, [&](std::size_t cell) {
    std::vector<CellEntry> entries;
    for (RouteChunk& chunk : chunks) {
      for (std::uint32_t k = chunk.cell_start[cell]; k < chunk.cell_start[cell + 1]; ++k) {
        const std::uint32_t s = chunk.leaves[k];
        chunk.entry_of_step[s] = std::uint32_t(entries.size());
        entries.push_back({std::move(chunk.steps[s].polygon), chunk.group_of_step[s]});
      }
    }
    filled[cell] = fill_cell(cell_trees_[cell], entries, together);
  });

  // As descend() gives them: a split's two sides, each one fragment in the same state, give
  // way to the polygon it cut.
  const auto assemble = [&](auto& self, RouteChunk& chunk, std::size_t& s) -> void {
    SvbspTree::RouteStep& step = chunk.steps[s++];
    if (step.cell >= 0) {
      CellFragments& cell = filled[std::size_t(step.cell)];
      const auto [first, end] = cell.of_entry[chunk.entry_of_step[s - 1]];
      std::move(cell.fragments.begin() + std::ptrdiff_t(first),
                cell.fragments.begin() + std::ptrdiff_t(end), std::back_inserter(out));
      return;
    }
    const std::size_t first = out.size();
    self(self, chunk, s);
    self(self, chunk, s);
    if (settings_.merge_siblings && out.size() == first + 2 &&
        out[first].lit == out[first + 1].lit) {
      out[first].polygon = std::move(step.polygon);
      out.pop_back();
    }
  };
  for (const Piece& plan : pieces) {
    if (!plan.filtered) {
      out.push_back({*plan.piece, false});  // Fig. 3: not facing the light, or shadowed whole
      continue;
    }
    const std::size_t first = out.size();
    std::size_t s = plan.first_step;
    assemble(assemble, chunks[plan.chunk], s);
    SHADOWKIT_CHECK(s == plan.end_step);
    keep_whole_if_uniform(*plan.piece, first, out);
  }
}

std::size_t ShadowGenerator::svbsp_nodes() const {
  std::size_t n = tree_.node_count();
  for (const SvbspTree& t : cell_trees_) n += t.node_count();
  return n;
}

std::size_t ShadowGenerator::svbsp_bytes() const {
  std::size_t n = tree_.memory_bytes();
  for (const SvbspTree& t : cell_trees_) n += t.memory_bytes();
  return n;
}

}  // namespace shadowkit::svbsp
