#pragma once
// Contour edges and their loops (Crow 1977, Sec. VI, Fig. 2).
#include <cstdint>
#include <span>
#include <vector>

#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/scene/edge_loops.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::volume {

/// The direction in which a shadow polygon leaves vertex \p v: away from a point light, or
/// the travel direction of a directional light (then every ray is parallel).
Vec3 away_from_light(Vec3 v, const Light& light);

/// The side (+1, -1, or 0 in its plane) of a shadow polygon through \p edge, with normal
/// \p polygon_normal, on which face use \p use lies near the edge.
int face_side(const Mesh& mesh, const MeshEdge& edge, const EdgeUse& use, Vec3 polygon_normal);

/// \brief A contour edge (Crow's "silhouette edge"): a mesh edge whose shadow polygon does not
/// cancel. Oriented so that its weight is positive: crossing its shadow polygon toward the
/// positive side of cross(to - from, away_from_light(from)) enters `weight` more of the
/// per-face shadow volumes.
///
/// Every face whose plane misses the light bounds its own shadow volume (the space behind
/// it, seen from the light); faces are two-sided, so this holds whichever way the face
/// points. An edge's shadow polygon is shared by the volumes of its faces; each face adds
/// +1 or -1 by the side of the polygon it lies on. On a closed, consistently oriented mesh
/// that sum is +-2 where a light-facing face meets a face turned away, and 0 elsewhere
/// (Crow's contour); a boundary edge of an open mesh gets +-1; a non-manifold edge the sum
/// of its faces. Faces that contain the light cast no volume and add nothing.
struct ContourEdge {
  std::uint32_t edge = 0;          ///< index into Mesh::edges
  std::uint32_t from = 0, to = 0;  ///< mesh vertex ids
  int weight = 0;
};

/// \brief Contour edges chained end to start through shared vertices (Crow's "perimeter").
using ContourLoop = EdgeLoop;

/// The contour edges of \p mesh for \p light, in mesh edge order.
std::vector<ContourEdge> find_contour_edges(const Mesh& mesh, const Light& light);

/// The contour edges of \p mesh among the edges of its faces \p faces (mesh face ids), in
/// mesh edge order, into \p out: those of a sub-object, whose edges have no other faces.
void find_contour_edges(const Mesh& mesh, std::span<const std::uint32_t> faces, const Light& light,
                        std::vector<ContourEdge>& out);

/// Chains contour edges of one mesh into loops, following each edge to an unused edge that
/// starts at its end vertex (Crow Fig. 2). On a closed manifold every loop closes.
std::vector<ContourLoop> chain_contour_loops(std::span<const ContourEdge> edges);

}  // namespace shadowkit::volume
