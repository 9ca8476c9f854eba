#pragma once
// Visible ridge edge pseudo intersection points (VREPIPs) and the split of coiled RE loops
// into simple loops at them (Thakur, Cheng & Miura, RE-loops paper, Secs. 2.1-2.4).
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "ridge_edges.h"

namespace shadowkit::angular {

/// \brief Where the projections from the light of two light-frame segments cross: the
/// parameter along each (0 at its first point, 1 at its second).
struct ProjectedCrossing {
  double s = 0, t = 0;
};

/// Whether the projections from the light of segments \p a0 \p a1 and \p b0 \p b1 cross
/// properly, and where. Touching (an end on the other's projection) and collinear overlaps
/// are not crossings. \p point_light: the light is at the frame's origin; otherwise it shines
/// along +Z (the directional frame's r axis).
std::optional<ProjectedCrossing> projections_cross(Vec3 a0, Vec3 a1, Vec3 b0, Vec3 b1,
                                                   bool point_light);

/// \brief A VREPIP (Sec. 2.1): the point of visible ridge edge \p ridge, at \p t along it from
/// its `from` vertex, where another VRE's projection crosses its own.
struct Vrepip {
  std::uint32_t ridge = 0;
  double t = 0;
  Vec3 p;            ///< light-frame point
  double depth = 0;  ///< distance from the light along its ray
};

/// \brief The VREPIPs that project to one point, nearest the light first. Imaginary edges
/// join them along the light's ray: two VREs crossing give a near and a far VREPIP (Sec.
/// 2.2); more than two VREs through one point give one VREPIP each (Sec. 2.4, Fig. 15).
struct PseudoIntersection {
  std::vector<std::uint32_t> vrepips;  ///< indices into Vrepips::points
};

/// \brief An object's VREPIPs, grouped by the point they project to.
struct Vrepips {
  std::vector<Vrepip> points;
  std::vector<PseudoIntersection> at;
};

/// The VREPIPs of the VREs of one object's closed RE loops \p loops (vertices \p local in the
/// light frame): the paper's edge-edge intersection tests in the light's projection, between
/// pairs of VREs whose theta ranges overlap.
Vrepips find_vrepips(std::span<const Vec3> local, std::span<const RidgeEdge> ridges,
                     std::span<const RidgeEdgeLoop> loops, bool point_light);

/// \brief The part of ridge edge \p ridge from \p t0 to \p t1 along its direction.
struct LoopPiece {
  std::uint32_t ridge = 0;
  double t0 = 0, t1 = 1;
};

/// \brief A loop after the split: pieces in traversal order. Where consecutive pieces do not
/// meet at a vertex, an imaginary edge joins them (from a VREPIP to another of its point).
using SimpleLoop = std::vector<LoopPiece>;

/// Sec. 2.2's traversal: along each closed loop of \p loops in its direction, and at every
/// VREPIP across the imaginary edge onto the VRE that leaves that point next clockwise from
/// the incoming one (Sec. 2.4; for two VREs, the other one). Every ridge edge is traversed
/// once, in pieces; every imaginary edge once each way. The loops that come out do not cross
/// at any VREPIP of \p v.
std::vector<SimpleLoop> split_at_vrepips(std::span<const Vec3> local,
                                         std::span<const RidgeEdge> ridges,
                                         std::span<const RidgeEdgeLoop> loops, const Vrepips& v,
                                         bool point_light);

}  // namespace shadowkit::angular
