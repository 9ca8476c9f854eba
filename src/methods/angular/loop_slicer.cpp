#include "loop_slicer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace shadowkit::angular {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Hazard: an edge through the light's X axis (kHalfTurnTolerance) crosses every slice on the
// axis. The light frame's rotation and the crossing's interpolation each round by a few ulps
// of the ends' coordinates, so the crossing lands a rounding to either side of the axis,
// differently in each slice. Within this many ulps it lies on the axis.
constexpr double kAxisUlps = 64;

// Mesh edge e's ends in the light frame and their sides of one slice, each computed once per
// edge and slice.
struct EdgeSides {
  Vec3 a, b;
  double ga = 0, gb = 0;

  EdgeSides(Vec3 v0, Vec3 v1, const ThetaSlice& s) : a(v0), b(v1), ga(s.side(a)), gb(s.side(b)) {}
  EdgeSides(const SlicedMesh& m, const ThetaSlice& s, const MeshEdge& edge)
      : EdgeSides(m.local[edge.v0], m.local[edge.v1], s) {}
  bool crossed() const { return (ga >= 0) != (gb >= 0); }
  // Computed from the edge's lower vertex id, so that both faces of an edge get the same
  // bits and neighbouring pairs meet without a crack.
  Crossing crossing(const ThetaSlice& s, std::uint32_t e) const {
    Crossing c;
    c.p = a + (b - a) * (ga / (ga - gb));
    c.rho = s.rho(c.p);
    // On the light's X axis (kAxisUlps): the half-plane's edge, whose phi is +-inf by the
    // sign of X (tan(phi) = X / rho with rho >= 0), never a rounded -0's opposite.
    const double axis = kAxisUlps * std::numeric_limits<double>::epsilon() *
                        std::max(max_abs_component(a), max_abs_component(b));
    if (std::abs(c.rho) <= axis) c.rho = +0.0;
    c.phi = s.phi(c.p, c.rho);
    c.edge = e;
    return c;
  }
};

// Where ridge edge \p re, whose ends \p sides holds, goes up through slice \p s into the
// half-plane at its theta: a walk's start. False when it does not (the half-plane at
// theta + pi is another entry's). On the light's X axis it goes up into this half-plane and
// down out of the other: the walk starts at phi = +-inf.
bool walk_start(const RidgeEdge& re, const MeshEdge& edge, const EdgeSides& sides,
                const ThetaSlice& s, Crossing& at) {
  const bool from_below = (re.from == edge.v0 ? sides.ga : sides.gb) < 0;
  if (!(from_below && sides.crossed())) return false;
  at = sides.crossing(s, re.edge);
  return at.rho >= 0;
}

// The crossings of face f's edges by the slice, ordered along the cut line.
void face_cuts(const SlicedMesh& m, const ThetaSlice& s, std::uint32_t f,
               std::vector<Crossing>& cuts) {
  cuts.clear();
  const std::uint32_t n = m.mesh.face_size(f);
  for (std::uint32_t k = 0; k < n; ++k) {
    const std::uint32_t e = m.mesh.corner_edge[m.mesh.face_start[f] + k];
    const EdgeSides edge(m, s, m.mesh.edges[e]);
    if (edge.crossed()) cuts.push_back(edge.crossing(s, e));
  }
  if (cuts.size() <= 2) return;
  // A non-convex face: the cut is several segments along one line.
  Vec3 lo = cuts[0].p, hi = lo;
  for (const Crossing& c : cuts) lo = min(lo, c.p), hi = max(hi, c.p);
  const Vec3 spread = hi - lo;
  const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : spread.y >= spread.z ? 1 : 2;
  std::sort(cuts.begin(), cuts.end(),
            [axis](const Crossing& a, const Crossing& b) { return a.p[axis] < b.p[axis]; });
}

// The other end of the segment of face f's cut that starts at \p at: the next crossing
// along the cut line (segments alternate inside and outside a non-convex face). From the
// light's X axis: the nearest crossing in the half-plane at theta. False if none.
bool partner(const SlicedMesh& m, const ThetaSlice& s, std::uint32_t f, const Crossing& at,
             std::vector<Crossing>& cuts, Crossing& out) {
  if (at.edge >= 0) {
    // The common case, a cut with two ends: the other crossing edge, without sorting.
    const std::uint32_t first = m.mesh.face_start[f], n = m.mesh.face_size(f);
    std::int64_t other = -1;
    int crossings = 0;
    bool above = s.side(m.local[m.mesh.face_vertices[first]]) >= 0;
    for (std::uint32_t k = 0; k < n; ++k) {  // corner k's edge ends at corner k + 1
      const bool next_above = s.side(m.local[m.mesh.face_vertices[first + (k + 1) % n]]) >= 0;
      if (next_above != above) {
        ++crossings;
        const std::uint32_t e = m.mesh.corner_edge[first + k];
        if (e != at.edge) other = e;
      }
      above = next_above;
    }
    if (crossings == 2 && other >= 0) {
      out = edge_crossing(m, s, std::uint32_t(other));
      return true;
    }
  }
  face_cuts(m, s, f, cuts);
  if (at.edge < 0) {
    double best = kInf;
    for (const Crossing& c : cuts) {
      const double d = length(c.p - at.p);
      if (c.rho > 0 && d < best) best = d, out = c;
    }
    return best < kInf;
  }
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    if (cuts[i].edge != at.edge) continue;
    const std::size_t j = i ^ 1;
    if (j >= cuts.size()) return false;
    out = cuts[j];
    return true;
  }
  return false;
}

// Hazard: a point light's slice is a half-plane. When the segment from \p at leaves it
// through the light's X axis, it is clipped there: phi runs to +-inf (tan(phi) of a point
// on the axis). True when clipped.
bool clip_at_axis(const Crossing& at, Crossing& next) {
  const double ra = at.rho, rb = next.rho;
  if (rb >= 0) return false;
  const double x = at.p.x + (next.p.x - at.p.x) * (ra / (ra - rb));
  next.phi = x > 0 ? kInf : -kInf;
  return true;
}

void emit(const SlicedMesh& m, const ThetaSlice& s, std::uint32_t f, double a, double b,
          std::vector<EntryPair>& out) {
  out.push_back({s.entry, m.hidden_id[f], std::min(a, b), std::max(a, b)});
}

// The walk's step-th face f is convex and was left by an edge that still crosses the slice:
// \p next is that crossing.
bool along_path(const SlicedMesh& m, const ThetaSlice& s, std::uint32_t f,
                const std::vector<WalkStep>& path, std::size_t step, Crossing& next) {
  if (step >= path.size() || path[step].face != f || !m.mesh.convex[f]) return false;
  const std::uint32_t exit = path[step].exit;
  const EdgeSides edge(m, s, m.mesh.edges[exit]);
  if (!edge.crossed()) return false;
  next = edge.crossing(s, exit);
  return true;
}

}  // namespace

// While the walk crosses the convex faces of the previous entry's walk from the same start,
// their exit edges still cross the slice and are the only other crossings: they are taken
// from \p scratch's path.
void walk(const SlicedMesh& m, const ThetaSlice& s, std::uint32_t f, const Crossing& start,
          SliceScratch& scratch, std::vector<EntryPair>& out) {
  std::vector<WalkStep>& path = scratch.path;
  Crossing at = start;
  for (std::size_t step = 0; step < m.mesh.face_count(); ++step) {
    Crossing next;
    if (!along_path(m, s, f, path, step, next)) {
      path.resize(step);
      if (!partner(m, s, f, at, scratch.cuts, next)) return;
      const auto e = std::uint32_t(next.edge);
      path.push_back({f, e, sheet_neighbour(m.mesh, m.sheets, f, e)});
    }
    const bool clipped = clip_at_axis(at, next);
    emit(m, s, f, at.phi, next.phi, out);
    if (clipped || path[step].beyond < 0) return;
    f = std::uint32_t(path[step].beyond);
    at = next;
  }
}

namespace {

// The walks from \p re at entries \p k, k + 1, ... up to \p last that repeat the path of
// the walk before them step for step: each of its faces convex and left by the same edge,
// no step clipped at the light's axis, and the last one ending on an RE. Their pairs are
// those walk would give, from the path's edges loaded once for the run. Returns the first
// entry not done, which slice_ridge_edge takes over.
int repeat_walk(const SlicedMesh& m, const RidgeEdge& re, int k, int last,
                const ThetaQuantization& q, std::span<const ThetaSlice> slices,
                SliceScratch& scratch, std::vector<EntryPair>& out) {
  const std::vector<WalkStep>& path = scratch.path;
  if (path.empty() || path.back().beyond >= 0) return k;
  std::vector<PathEdge>& edges = scratch.path_edges;
  edges.clear();
  for (const WalkStep& step : path) {
    if (!m.mesh.convex[step.face]) return k;
    const MeshEdge& exit = m.mesh.edges[step.exit];
    edges.push_back({m.local[exit.v0], m.local[exit.v1], step.exit, m.hidden_id[step.face]});
  }
  const MeshEdge& edge = m.mesh.edges[re.edge];
  const Vec3 a = m.local[edge.v0], b = m.local[edge.v1];
  std::vector<double>& phi = scratch.phi;
  phi.resize(edges.size() + 1);
  for (; k <= last; ++k) {
    const int entry = q.entry(k);
    if (entry < 0) return k;
    const ThetaSlice& s = slices[entry];
    Crossing at;
    if (!walk_start(re, edge, EdgeSides(a, b, s), s, at)) return k;
    phi[0] = at.phi;
    for (std::size_t j = 0; j < edges.size(); ++j) {
      const EdgeSides exit(edges[j].a, edges[j].b, s);
      if (!exit.crossed()) return k;
      const Crossing next = exit.crossing(s, edges[j].edge);
      if (next.rho < 0) return k;  // clipped at the axis
      phi[j + 1] = next.phi;
    }
    for (std::size_t j = 0; j < edges.size(); ++j) {
      out.push_back(
          {s.entry, edges[j].hidden, std::min(phi[j], phi[j + 1]), std::max(phi[j], phi[j + 1])});
    }
  }
  return k;
}

// Slices ridge edge \p re over the entries whose centre its unwrapped theta interval
// [lo, hi] may hold.
void slice_ridge_edge(const SlicedMesh& m, const RidgeEdge& re, double lo, double hi,
                      const ThetaQuantization& q, std::span<const ThetaSlice> slices,
                      SliceScratch& scratch, std::vector<EntryPair>& out) {
  scratch.path.clear();
  // One more entry at each end against rounding (the side test decides), within the table
  // unless it goes all around.
  const double first = std::floor(q.position(lo) - 0.5);
  const double last = std::ceil(q.position(hi) - 0.5);
  const double end = q.full_turn ? first + q.resolution : q.resolution - 1;
  const int k0 = int(std::max(first, q.full_turn ? first : 0.0));
  const int k1 = int(std::min(last, end));
  const MeshEdge& edge = m.mesh.edges[re.edge];
  for (int k = k0; k <= k1; ++k) {
    const int entry = q.entry(k);
    if (entry < 0) continue;
    const ThetaSlice& s = slices[entry];
    Crossing at;
    if (!walk_start(re, edge, EdgeSides(m, s, edge), s, at)) continue;
    walk(m, s, re.face, at, scratch, out);
    // The entries after it that repeat its path; the loop goes on from the first that does not.
    k = repeat_walk(m, re, k + 1, k1, q, slices, scratch, out) - 1;
  }
}

// Slices ridge edge \p re over the unwrapped theta interval [lo, hi], hi < lo + 2 pi. A
// table cut to the view lies within [-pi, pi]: the part from pi on is its start, a turn lower.
void slice_arc(const SlicedMesh& m, const RidgeEdge& re, double lo, double hi,
               const ThetaQuantization& q, std::span<const ThetaSlice> slices,
               SliceScratch& scratch, std::vector<EntryPair>& out) {
  slice_ridge_edge(m, re, lo, hi, q, slices, scratch, out);
  if (!q.full_turn && hi >= std::numbers::pi) {
    slice_ridge_edge(m, re, lo - 2 * std::numbers::pi, hi - 2 * std::numbers::pi, q, slices,
                     scratch, out);
  }
}

}  // namespace

Crossing edge_crossing(const SlicedMesh& m, const ThetaSlice& s, std::uint32_t e) {
  return EdgeSides(m, s, m.mesh.edges[e]).crossing(s, e);
}

bool crosses(const SlicedMesh& m, const ThetaSlice& s, std::uint32_t e) {
  return EdgeSides(m, s, m.mesh.edges[e]).crossed();
}

bool ridge_start(const SlicedMesh& m, const RidgeEdge& re, const ThetaSlice& s, Crossing& at) {
  const MeshEdge& edge = m.mesh.edges[re.edge];
  return walk_start(re, edge, EdgeSides(m, s, edge), s, at);
}

ThetaSlice ThetaSlice::at(double theta, std::pair<double, double> sin_cos, bool point_light,
                          std::uint32_t entry) {
  ThetaSlice s;
  s.entry = entry;
  s.point_light = point_light;
  if (point_light) {
    s.side_z = s.rho_y = sin_cos.first;
    s.side_y = s.rho_z = sin_cos.second;
  } else {
    s.side_0 = -theta;
    s.rho_0 = 1;
    s.rho_z = 0;
  }
  return s;
}

void slice_loop(const SlicedMesh& m, std::span<const RidgeEdge> ridges, const RidgeEdgeLoop& loop,
                const ThetaQuantization& q, std::span<const ThetaSlice> slices,
                SliceScratch& scratch, std::vector<EntryPair>& out) {
  if (slices.empty()) return;
  const bool point = slices[0].point_light;
  for (const std::uint32_t i : loop.edges) {
    const RidgeEdge& re = ridges[i];
    const double from = m.theta[re.from], to = m.theta[re.to];
    const double lo = std::min(from, to), hi = std::max(from, to);
    // Through the light's X axis (kHalfTurnTolerance): up through one half, either one.
    if (point && half_a_turn(lo, hi)) {
      slice_arc(m, re, lo, hi, q, slices, scratch, out);
      slice_arc(m, re, hi, lo + 2 * std::numbers::pi, q, slices, scratch, out);
      continue;
    }
    const bool wraps = point && hi - lo > std::numbers::pi;  // behind the light
    // Direction constraint (RE-loops paper, Sec. 3.2): seen from the light, every far sheet
    // lies to the right of its REs (larger phi), so shadow begins where an RE goes up
    // through a slice and ends where one comes down, the begin's partner. An RE clearly
    // going down begins nothing; near-constant theta is left to the side test.
    if ((to - from) * (wraps ? -1 : 1) < -1e-9) continue;
    // Unwrapped, a wrapping RE runs from hi up past pi to lo + 2 pi.
    if (wraps) {
      slice_arc(m, re, hi, lo + 2 * std::numbers::pi, q, slices, scratch, out);
    } else {
      slice_arc(m, re, lo, hi, q, slices, scratch, out);
    }
  }
}

void slice_from_axis(const SlicedMesh& m, std::uint32_t f, std::span<const ThetaSlice> slices,
                     SliceScratch& scratch, std::vector<EntryPair>& out) {
  Crossing at;
  at.p = {axis_piercing(m, f), 0, 0};
  at.phi = -kInf;
  for (const ThetaSlice& s : slices) {
    at.rho = s.rho(at.p);
    scratch.path.clear();  // from the axis, the exit is not the only other crossing
    walk(m, s, f, at, scratch, out);
  }
}

double axis_piercing(const SlicedMesh& m, std::uint32_t f) {
  const std::uint32_t n = m.mesh.face_size(f);
  // The origin inside the face's projection on the (Y, F) plane (crossing number), and the
  // face's Newell normal.
  bool inside = false;
  for (std::uint32_t k = 0; k < n; ++k) {
    const Vec3 a = m.local[m.mesh.face_vertex(f, k)];
    const Vec3 b = m.local[m.mesh.face_vertex(f, (k + 1) % n)];
    if ((a.y > 0) != (b.y > 0) && 0 < a.z + (b.z - a.z) * (0 - a.y) / (b.y - a.y)) {
      inside = !inside;
    }
  }
  if (!inside) return std::numeric_limits<double>::quiet_NaN();
  Vec3 normal{0, 0, 0};
  for (std::uint32_t k = 0; k < n; ++k) {
    normal = normal +
             cross(m.local[m.mesh.face_vertex(f, k)], m.local[m.mesh.face_vertex(f, (k + 1) % n)]);
  }
  if (normal.x == 0) return std::numeric_limits<double>::quiet_NaN();
  return dot(normal, m.local[m.mesh.face_vertex(f, 0)]) / normal.x;
}

}  // namespace shadowkit::angular
