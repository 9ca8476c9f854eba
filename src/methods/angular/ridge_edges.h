#pragma once
// Ridge edges and their loops (Thakur, Cheng & Miura, RE-loops paper Sec. 2; discretized-
// shadow-volume paper Sec. 2).
#include <cstdint>
#include <span>
#include <vector>

#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/scene/edge_loops.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// \brief A ridge edge: between a face visible from the light and one hidden from it,
/// oriented as the visible face walks it (so the visible side is on its left).
///
/// Open surfaces are two-sided thin solids: every face is a front sheet and a back sheet,
/// one visible and one hidden. A boundary edge joins the two sheets of its face, so it is
/// always an RE; an interior edge between a visible and a hidden face is an RE twice (front
/// sheets and back sheets). In general an edge is an RE |w| times with w the sum over its
/// face uses of (walks it forward ? 1 : -1) * (visible ? 1 : -1), the `volume` method's
/// contour weight. A closed, consistently oriented mesh is one solid and each RE counts once.
struct RidgeEdge {
  std::uint32_t edge = 0;          ///< index into Mesh::edges
  std::uint32_t from = 0, to = 0;  ///< mesh vertex ids
  bool hidden_ridge = false;  ///< HRE: the hidden face is nearer the light than the visible one
};

/// \brief An RE loop: ridge edges chained end to start (Sec. 2 proves they close).
using RidgeEdgeLoop = EdgeLoop;

/// Visible (1) or hidden (0) per face of \p mesh for \p light.
std::vector<char> visible_faces(const Mesh& mesh, const Light& light);

/// The mesh is one solid (closed and consistently oriented); otherwise a two-sided thin solid.
bool one_solid(const Mesh& mesh);

/// The ridge edges of \p mesh for \p light, each as many times as it is an RE.
std::vector<RidgeEdge> find_ridge_edges(const Mesh& mesh, const Light& light);

/// Chains ridge edges into loops through shared vertices.
std::vector<RidgeEdgeLoop> chain_ridge_edge_loops(std::span<const RidgeEdge> edges);

/// Hidden edges (every face around them hidden; for thin solids, interior edges that are not
/// REs, whose back or front sheets are both hidden) with an end on an RE loop (Sec. 3.3).
std::vector<std::uint32_t> hidden_edges_at_loops(const Mesh& mesh, const Light& light,
                                                 std::span<const RidgeEdge> edges);

/// \brief Counts over all objects of a scene for one light.
struct RidgeEdgeStats {
  double ridge_edges = 0, loops = 0, open_loops = 0, hidden_edges = 0;
};

/// Finds every object's ridge edges, loops and hidden edges at loops (objects in parallel).
RidgeEdgeStats ridge_edge_stats(const Scene& scene, const Light& light);

}  // namespace shadowkit
