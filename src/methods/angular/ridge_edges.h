#pragma once
// Ridge edges and their loops (Thakur, Cheng & Miura, RE-loops paper Sec. 2; discretized-
// shadow-volume paper Sec. 2).
#include <cstdint>
#include <span>
#include <vector>

#include "shadowkit/scene/edge_loops.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::angular {

/// \brief Which faces of one mesh bound the shadow volume for one light, as sheets.
///
/// Every face has a far sheet: the side turned away from the light (its front when the light
/// is behind it, its back otherwise). A closed mesh seen from its outside region is one
/// solid: only its hidden faces (light behind the plane) occlude, and their far sheets are
/// their fronts. Otherwise (open, non-manifold or inconsistently oriented meshes, or a solid
/// whose inside may hold the eye or the light) the mesh is a two-sided thin solid: every
/// face whose plane misses the light occludes with its far sheet.
struct FarSheets {
  std::vector<signed char> side;  ///< per face: +1 light in front, -1 behind, 0 in the plane
  bool solid = true;

  bool occludes(std::uint32_t f) const { return solid ? side[f] < 0 : side[f] != 0; }
};

/// The sides of \p mesh's faces for \p light; \p solid as FarSheets::solid.
FarSheets far_sheets(const Mesh& mesh, const Light& light, bool solid);

/// The face whose far sheet continues face \p f's far sheet across mesh edge \p e, or -1
/// when \p e bounds it (a manifold edge whose two faces' far sheets meet smoothly, i.e.
/// whose thin-solid weight sum (walks it forward ? 1 : -1) * side is 0; never across a
/// boundary or non-manifold edge).
std::int64_t sheet_neighbour(const Mesh& mesh, const FarSheets& sheets, std::uint32_t f,
                             std::uint32_t e);

/// \brief A ridge edge: where an occluding face's far sheet ends (Sec. 2: between a visible
/// and a hidden face of a solid; on a thin solid also every boundary edge, and a fold between
/// sheets twice). Oriented so that its far sheet lies on its left seen against the sheet's
/// normal, so that the ridge edges chain into closed loops.
struct RidgeEdge {
  std::uint32_t edge = 0;          ///< index into Mesh::edges
  std::uint32_t from = 0, to = 0;  ///< mesh vertex ids
  std::uint32_t face = 0;          ///< the occluding face whose far sheet ends here
  bool hidden_ridge = false;  ///< HRE: the hidden face is nearer the light than the visible one
};

/// \brief An RE loop: ridge edges chained end to start (Sec. 2 proves they close).
using RidgeEdgeLoop = EdgeLoop;

/// The mesh is one solid (closed and consistently oriented); otherwise a two-sided thin solid.
bool one_solid(const Mesh& mesh);

/// The ridge edges of \p mesh: one per occluding face and sheet-bounding edge of it.
std::vector<RidgeEdge> find_ridge_edges(const Mesh& mesh, const FarSheets& sheets);

/// Chains ridge edges into loops through shared vertices.
std::vector<RidgeEdgeLoop> chain_ridge_edge_loops(std::span<const RidgeEdge> edges);

/// Hidden edges (Sec. 3.3: the far sheets of both faces meet across them) with an end on a
/// ridge edge.
std::vector<std::uint32_t> hidden_edges_at_loops(const Mesh& mesh, const FarSheets& sheets,
                                                 std::span<const RidgeEdge> edges);

/// \brief Counts over all objects of a scene for one light.
struct RidgeEdgeStats {
  double ridge_edges = 0, loops = 0, open_loops = 0;
};

}  // namespace shadowkit::angular
