#pragma once
// The RE-loops paper's own pairing (Thakur, Cheng & Miura, RE-loops paper, Secs. 3.2-3.3):
// branch pairs processed down from local peaks, equal adjacent peaks (Fig. 27), holes and
// hole-like situations by direction constraints, hidden edges inserted in duplicate; and, where
// that leaves pairs the far sheet does not join, the loops split at VREPIPs (Sec. 2.2).
#include <cstdint>
#include <span>
#include <vector>

#include "loop_slicer.h"

namespace shadowkit::angular {

/// \brief A branch (Sec. 3.2): a run of an RE loop's edges from a local peak down to a local
/// minimum, monotone in theta. Going up in the loop's order it is a left boundary, where
/// shadow begins; going down, a right boundary, where it ends (the direction constraint).
struct Branch {
  bool begins = false;
  std::vector<std::uint32_t> ridges;  ///< indices into the ridge edges, top to bottom
  std::vector<double> top;            ///< theta of each one's upper end: non-increasing
};

/// \brief A turn of an RE loop between two branches: a local peak (a group of two branches
/// starts), a hole-like peak (its branches go down and up from left to right: they are
/// inserted into the pair around them), or a local minimum (two branches end).
struct Turn {
  enum Kind { minimum, peak, hole_peak };
  Kind kind = peak;
  double theta = 0;
  std::uint32_t begins = 0, ends = 0;  ///< the branches that meet: going up and going down
  std::uint32_t vertex = 0;            ///< for a peak: the kept peak's vertex (Fig. 27)
};

/// \brief One object's closed RE loops cut into branches at their turns, turns from the
/// highest theta down (minima first at equal theta, then peaks, then hole-like peaks).
struct LoopBranches {
  std::vector<Branch> branches;
  std::vector<Turn> turns;
};

/// Splits \p loops (closed, of one solid) at their local peaks and minima. Equal adjacent
/// peaks or minima (a run of edges at constant theta) are one turn: the edges between them
/// are ignored and the kept turn takes the branches on both sides (Fig. 27).
LoopBranches split_into_branches(const SlicedMesh& mesh, std::span<const RidgeEdge> ridges,
                                 std::span<const RidgeEdgeLoop> loops, bool point_light);

/// \brief A begin of shadow and its partner in one entry, as ridge-edge crossings.
struct RePair {
  std::uint32_t entry = 0;
  double theta = 0;         ///< the entry's centre, where it is sliced
  std::uint32_t begin = 0;  ///< index into the ridge edges
  std::int64_t end = -1;    ///< index into the ridge edges; -1: no partner (a fallback)
  Crossing from, to;
};

/// Sec. 3.2, step 2: the branches processed one peak at a time going down, entry by entry
/// from the top: a peak pairs its two branches, a hole-like peak's branches are inserted into
/// the pair around them, and at a minimum the two groups that reach it merge.
std::vector<RePair> pair_branches(const SlicedMesh& mesh, std::span<const RidgeEdge> ridges,
                                  const LoopBranches& branches, const ThetaQuantization& q,
                                  std::span<const ThetaSlice> slices);

/// \brief What paper pairing did: its pairs, and the ones it could not make on its own.
struct PairingStats {
  std::size_t re_pairs = 0;
  std::size_t fallbacks = 0;  ///< begins with no partner, or an inconsistent one: walked
                              ///< instead, unless the walk is off
  std::size_t vrepips = 0;    ///< VREPIPs the loops were split at (Sec. 2.2)
};

/// Sec. 3.3: the hidden edges of one solid (both faces' far sheets meet across them). The
/// paper reaches them by a graph traversal from the loops' vertices; on a solid every far
/// sheet is bounded by RE loops, so that reaches every hidden edge, and one pass over the
/// edges finds the same set.
std::vector<std::uint32_t> hidden_edges(const Mesh& mesh, const FarSheets& sheets);

/// Sec. 3.3: each RePair (in pair_branches' order: entries from the top down) filled with the
/// crossings of \p hidden (hidden edges) that lie between its ends, by phi, each inserted in
/// duplicate: a pair per hidden face. Of the crossings between the ends, those not on the
/// current face are another layer's (a coil's) and are passed over. A begin whose crossings
/// do not lead face by face to its partner (a hole inserted into the wrong pair, a vertex on
/// the slice) is counted in \p stats and, with \p walk_fallback, walked across its far sheet
/// instead. Without it the rules' pairs stand: a begin without a partner pairs nothing, and a
/// pair whose hidden edges lead elsewhere ends on the face they lead to.
void insert_hidden_edges(const SlicedMesh& mesh, std::span<const RidgeEdge> ridges,
                         std::span<const std::uint32_t> hidden, std::span<const RePair> pairs,
                         std::span<const ThetaSlice> slices, SliceScratch& scratch,
                         std::vector<EntryPair>& out, PairingStats& stats,
                         bool walk_fallback = true);

/// The paper's pairing applies to one object: a closed, consistently oriented solid whose RE
/// loops are closed and stay on one side of the light's back (no theta wrap, no piercing of
/// the light's X axis), as the paper assumes. Elsewhere the far-sheet walk pairs.
bool paper_pairing_applies(const FarSheets& sheets, std::span<const RidgeEdgeLoop> loops,
                           bool wraps, bool axis_faces);

/// Secs. 3.2-3.3 for all of one object's RE loops: split_into_branches, pair_branches,
/// insert_hidden_edges. Where pairs fall back, the loops are also split (Sec. 2.2) at the
/// VREPIPs where their VREs go opposite ways in theta and paired again in pieces; the split
/// is kept when fewer of its pairs fall back. \p walk_fallback: see insert_hidden_edges.
void pair_re_loops(const SlicedMesh& mesh, std::span<const RidgeEdge> ridges,
                   std::span<const RidgeEdgeLoop> loops, const ThetaQuantization& q,
                   std::span<const ThetaSlice> slices, SliceScratch& scratch,
                   std::vector<EntryPair>& out, PairingStats& stats, bool walk_fallback = true);

}  // namespace shadowkit::angular
