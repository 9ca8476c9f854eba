#pragma once
// Slicing RE loops at constant theta (discretized-shadow-volume paper, Sec. 7, steps
// 1.3-1.6; RE-loops paper, Secs. 3.2-3.3).
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <utility>
#include <vector>

#include "angular_table.h"
#include "ridge_edges.h"

namespace shadowkit::angular {

/// \brief The constant-theta plane at the centre of one table entry. Its tests are linear
/// forms whose coefficients hold the light's kind, so that the walks, which evaluate them
/// at every edge they cross, never branch on it.
struct ThetaSlice {
  std::uint32_t entry = 0;
  bool point_light = true;
  double side_y = 1, side_z = 0, side_0 = 0;  ///< side(v) = v.y side_y - v.z side_z + side_0
  double rho_y = 0, rho_z = 1, rho_0 = 0;     ///< rho(v) = v.y rho_y + v.z rho_z + rho_0

  /// The slice at \p theta: for a point light the half-plane through the light's X axis at
  /// angle theta (eq. 2), for a directional light the plane Y = theta.
  static ThetaSlice at(double theta, bool point_light, std::uint32_t entry = 0) {
    return at(theta, {std::sin(theta), std::cos(theta)}, point_light, entry);
  }
  /// The same, given theta's (sin, cos) (unused for a directional light).
  static ThetaSlice at(double theta, std::pair<double, double> sin_cos, bool point_light,
                       std::uint32_t entry);
  /// Signed distance-like value whose sign tells the side of the plane (shared by every
  /// edge test of the entry, so that neighbours agree on which edges the plane crosses).
  double side(Vec3 v) const { return v.y * side_y - v.z * side_z + side_0; }
  /// Distance from the light's X axis inside the half-plane at theta; negative in the
  /// half-plane at theta + pi. Always 1 for a directional light.
  double rho(Vec3 v) const { return v.y * rho_y + v.z * rho_z + rho_0; }
  /// phi as AngularPoint keeps it (tan(phi) for a point light, X for a directional one) of
  /// a point on the plane, given its rho.
  static double phi(Vec3 v, double rho_v) { return v.x / rho_v; }
};

/// \brief A point where a slice crosses the far sheet's boundary or a face's edge.
struct Crossing {
  Vec3 p;
  double phi = 0;
  double rho = 1;          ///< ThetaSlice::rho(p), kept for the clip at the light's X axis
  std::int64_t edge = -1;  ///< mesh edge; -1 on the light's X axis
};

/// \brief One face crossed by a walk along the far sheet: the edge it is left by and the
/// face beyond (-1: the edge is an RE, where the shadow ends).
struct WalkStep {
  std::uint32_t face = 0, exit = 0;
  std::int64_t beyond = -1;
};

/// \brief A walk step's exit edge, its ends in the light frame, and the hidden face it leaves.
struct PathEdge {
  Vec3 a, b;
  std::uint32_t edge = 0, hidden = 0;
};

/// \brief Reused buffers of one thread's slicing: a face's cut, and the last walk from the RE
/// being sliced (consecutive entries mostly cross the same faces by the same edges).
struct SliceScratch {
  std::vector<Crossing> cuts;
  std::vector<WalkStep> path;
  std::vector<PathEdge> path_edges;  ///< the path's exits, loaded once to repeat it
  std::vector<double> phi;           ///< a repeated walk's crossings
};

/// \brief One mesh, seen from the light, while its RE loops are sliced.
struct SlicedMesh {
  const Mesh& mesh;
  const FarSheets& sheets;
  std::span<const Vec3> local;               ///< light-frame vertices
  std::span<const double> theta;             ///< per vertex on an RE: its theta (eq. 2)
  std::span<const std::uint32_t> hidden_id;  ///< per face: its AngularTable::hidden() index
};

/// Hazard: an edge in a plane through a point light that holds the light's X axis (an edge of
/// a face edge-on to the light, such as a bottom face whose plane holds the light) runs half a
/// turn in theta, one way round or the other as rounding decides. Within this of half a turn
/// an edge may run either way.
inline constexpr double kHalfTurnTolerance = 1e-9;

/// An edge whose ends' theta about a point light are \p lo <= \p hi runs within
/// kHalfTurnTolerance of half a turn.
inline bool half_a_turn(double lo, double hi) {
  return std::abs(hi - lo - std::numbers::pi) <= kHalfTurnTolerance;
}

/// \brief Sec. 7, steps 1.5-1.6 for one RE loop. At every entry an edge of the loop crosses
/// where shadow begins (the loop's far sheet lies towards larger phi: the direction
/// constraint of Sec. 3.2 of the RE-loops paper), walks the far sheet across the slice:
/// each hidden face crossed gives one pair, each hidden edge crossed is inserted in duplicate
/// (the end of one pair and the start of the next, Sec. 5), and the walk ends on the RE
/// crossing where the shadow ends, the begin's partner.
void slice_loop(const SlicedMesh& mesh, std::span<const RidgeEdge> ridges,
                const RidgeEdgeLoop& loop, const ThetaQuantization& q,
                std::span<const ThetaSlice> slices, SliceScratch& scratch,
                std::vector<EntryPair>& out);

/// Where slice \p s crosses mesh edge \p e (bit-identical for both faces of the edge).
Crossing edge_crossing(const SlicedMesh& mesh, const ThetaSlice& s, std::uint32_t e);

/// Whether slice \p s crosses mesh edge \p e (its ends on either side; an end on the slice
/// counts as above it).
bool crosses(const SlicedMesh& mesh, const ThetaSlice& s, std::uint32_t e);

/// Where ridge edge \p re goes up through slice \p s into the half-plane at its theta: a
/// begin of shadow (the direction constraint); false when it does not.
bool ridge_start(const SlicedMesh& mesh, const RidgeEdge& re, const ThetaSlice& s, Crossing& at);

/// Walks the far sheet from \p start (on face \p f's edge, or on the light's X axis) across
/// slice \p s: one pair per face, each hidden edge crossed shared by two pairs (inserted in
/// duplicate, Sec. 5), until the RE crossing where the shadow ends. \p scratch's path is the
/// previous entry's walk from the same start, or empty.
void walk(const SlicedMesh& mesh, const ThetaSlice& s, std::uint32_t f, const Crossing& start,
          SliceScratch& scratch, std::vector<EntryPair>& out);

/// \brief A point light's X axis pierces occluding face \p f at X < 0 (light inside the
/// scene, Sec. 11.2): in every entry a far-sheet walk starts on the axis (phi = -inf) in \p f.
void slice_from_axis(const SlicedMesh& mesh, std::uint32_t f, std::span<const ThetaSlice> slices,
                     SliceScratch& scratch, std::vector<EntryPair>& out);

/// Where the light's X axis pierces face \p f (its X), if it does: NaN otherwise.
double axis_piercing(const SlicedMesh& mesh, std::uint32_t f);

}  // namespace shadowkit::angular
