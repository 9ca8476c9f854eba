#include "re_loop_pairing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <tuple>

#include "light_frame.h"
#include "vrepips.h"

namespace shadowkit::angular {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Eq. 2 of any vertex (SlicedMesh::theta holds only the ridge edges' ones).
double vertex_theta(const SlicedMesh& m, std::uint32_t v, bool point_light) {
  return local_theta(m.local[v], point_light);
}

// The hidden edges by theta, while the slices go down: those whose theta range may hold the
// current slice's.
class HiddenEdgeSweep {
 public:
  HiddenEdgeSweep(const SlicedMesh& m, std::span<const std::uint32_t> hidden, bool point_light) {
    for (const std::uint32_t e : hidden) {
      const MeshEdge& edge = m.mesh.edges[e];
      double lo = vertex_theta(m, edge.v0, point_light), hi = vertex_theta(m, edge.v1, point_light);
      if (lo > hi) std::swap(lo, hi);
      // Hazard: an edge behind the light (theta wraps) is never inserted; a pair across it
      // does not reach its partner and is walked.
      if (point_light && hi - lo > std::numbers::pi) continue;
      edges_.push_back({lo, hi, e});
    }
    std::sort(edges_.begin(), edges_.end(),
              [](const Span& a, const Span& b) { return a.hi > b.hi; });
  }
  // The edges that may cross the slice at \p theta, lower than the previous call's.
  std::span<const std::uint32_t> at(double theta) {
    const double pad = 1e-9 * (1 + std::abs(theta));
    for (; next_ < edges_.size() && edges_[next_].hi >= theta - pad; ++next_) {
      active_.push_back(next_);
    }
    std::erase_if(active_, [&](std::size_t i) { return edges_[i].lo > theta + pad; });
    current_.clear();
    for (const std::size_t i : active_) current_.push_back(edges_[i].edge);
    return current_;
  }

 private:
  struct Span {
    double lo = 0, hi = 0;
    std::uint32_t edge = 0;
  };
  std::vector<Span> edges_;
  std::size_t next_ = 0;
  std::vector<std::size_t> active_;
  std::vector<std::uint32_t> current_;
};

// +1 when ridge edge re goes up in theta along its direction, -1 down, 0 at constant theta.
int rise(const SlicedMesh& m, const RidgeEdge& re) {
  const double d = m.theta[re.to] - m.theta[re.from];
  return d > 0 ? 1 : d < 0 ? -1 : 0;
}

// A branch under construction: ridge edges in the loop's order, at constant theta or with
// rise \p rises.
struct Run {
  int rises = 0;
  std::vector<std::uint32_t> ridges;
};

// The index of the first edge of \p loop after a turn: its rise differs from the last
// non-flat rise before it. -1 when there is none (a loop at constant theta).
int first_after_turn(std::span<const int> rises) {
  const std::size_t n = rises.size();
  int previous = 0;
  for (std::size_t j = 0; j < 2 * n && previous == 0; ++j) previous = rises[(n - 1 - j % n)];
  for (std::size_t i = 0; i < n; ++i) {
    if (rises[i] != 0 && rises[i] != previous) return int(i);
    if (rises[i] != 0) previous = rises[i];
  }
  return -1;
}

// Cuts one closed loop into runs of one rise. Edges at constant theta inside a run (a step)
// stay in it; at a turn they are dropped (Fig. 27: the edge between equal adjacent peaks is
// ignored).
std::vector<Run> runs_of(const SlicedMesh& m, std::span<const RidgeEdge> ridges,
                         const RidgeEdgeLoop& loop) {
  std::vector<int> rises;
  for (const std::uint32_t i : loop.edges) rises.push_back(rise(m, ridges[i]));
  const int start = first_after_turn(rises);
  if (start < 0) return {};
  std::vector<Run> runs;
  std::vector<std::uint32_t> flat;
  const std::size_t n = rises.size();
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t i = (std::size_t(start) + j) % n;
    if (rises[i] == 0) {
      flat.push_back(loop.edges[i]);
      continue;
    }
    if (runs.empty() || runs.back().rises != rises[i]) {
      runs.push_back({rises[i], {}});
    } else {
      runs.back().ridges.insert(runs.back().ridges.end(), flat.begin(), flat.end());
    }
    flat.clear();
    runs.back().ridges.push_back(loop.edges[i]);
  }
  return runs;
}

// A run as a branch: its ridge edges from the top down, with their upper thetas.
Branch branch_of(const SlicedMesh& m, std::span<const RidgeEdge> ridges, Run run) {
  Branch b;
  b.begins = run.rises > 0;
  if (b.begins) std::reverse(run.ridges.begin(), run.ridges.end());
  b.ridges = std::move(run.ridges);
  for (const std::uint32_t i : b.ridges) {
    b.top.push_back(std::max(m.theta[ridges[i].from], m.theta[ridges[i].to]));
  }
  return b;
}

// The highest ridge edge of branch b and its theta extent.
const RidgeEdge& top_edge(std::span<const RidgeEdge> ridges, const Branch& b) {
  return ridges[b.ridges.front()];
}

// Sec. 3.2's direction constraint at a peak: just below it, the branch going up (shadow
// begins) lies left of the one going down for an outer peak; right of it, the two bound a
// hole or a hole-like situation (Figs. 25-27). Compared half way down the shorter top edge.
Turn::Kind peak_kind(const SlicedMesh& m, std::span<const RidgeEdge> ridges, const Branch& up,
                     const Branch& down, double theta, bool point_light) {
  const RidgeEdge& a = top_edge(ridges, up);
  const RidgeEdge& b = top_edge(ridges, down);
  const double drop = std::min(theta - std::min(m.theta[a.from], m.theta[a.to]),
                               theta - std::min(m.theta[b.from], m.theta[b.to]));
  const ThetaSlice below = ThetaSlice::at(theta - drop / 2, point_light);
  return edge_crossing(m, below, a.edge).phi < edge_crossing(m, below, b.edge).phi
             ? Turn::peak
             : Turn::hole_peak;
}

// The turn between consecutive branches \p a and \p b (ids \p ia, \p ib) of one loop.
Turn turn_between(const SlicedMesh& m, std::span<const RidgeEdge> ridges,
                  std::span<const Branch> branches, std::uint32_t ia, std::uint32_t ib,
                  bool point_light) {
  const Branch& a = branches[ia];
  const Branch& b = branches[ib];
  Turn t;
  if (a.begins) {  // up, then down: a peak; the kept one is where b leaves it (Fig. 27)
    t.begins = ia, t.ends = ib;
    t.vertex = ridges[b.ridges.front()].from;
    t.theta = m.theta[t.vertex];
    t.kind = peak_kind(m, ridges, a, b, t.theta, point_light);
  } else {  // down, then up: a minimum
    t.kind = Turn::minimum;
    t.ends = ia, t.begins = ib;
    t.vertex = ridges[a.ridges.back()].to;
    t.theta = m.theta[t.vertex];
  }
  return t;
}

// The ridge edge of branch \p b that crosses slice \p s (at theta \p theta), found by the
// branch's upper thetas and confirmed by the slice's own side test, and where; -1 when none
// does.
std::int64_t branch_crossing(const SlicedMesh& m, std::span<const RidgeEdge> ridges,
                             const Branch& b, const ThetaSlice& s, double theta, Crossing& at) {
  const auto first_below = std::partition_point(b.top.begin(), b.top.end(),
                                                [theta](double top) { return top >= theta; });
  const int i = int(first_below - b.top.begin()) - 1;
  for (const int c : {i, i + 1, i - 1}) {
    if (c < 0 || c >= int(b.ridges.size())) continue;
    const std::uint32_t re = b.ridges[std::size_t(c)];
    if (!crosses(m, s, ridges[re].edge)) continue;
    at = edge_crossing(m, s, ridges[re].edge);
    return at.rho > 0 ? std::int64_t(re) : -1;
  }
  return -1;
}

// The branches while the sweep goes down: which begin pairs with which end, and which
// begins are active (their peak passed, their minimum not yet).
class BranchPairs {
 public:
  explicit BranchPairs(std::size_t n) : partner_(n, -1), slot_(n, -1) {}

  const std::vector<std::uint32_t>& active() const { return active_; }
  std::int64_t partner(std::uint32_t b) const { return partner_[b]; }
  void pair(std::int64_t a, std::int64_t b) {
    if (a >= 0) partner_[std::size_t(a)] = b;
    if (b >= 0) partner_[std::size_t(b)] = a;
  }
  void activate(std::uint32_t b) {
    slot_[b] = std::int64_t(active_.size());
    active_.push_back(b);
  }
  void deactivate(std::uint32_t b) {
    if (slot_[b] < 0) return;
    const std::uint32_t last = active_.back();
    active_[std::size_t(slot_[b])] = last;
    slot_[last] = slot_[b];
    active_.pop_back();
    slot_[b] = -1;
  }

 private:
  std::vector<std::int64_t> partner_;
  std::vector<std::int64_t> slot_;
  std::vector<std::uint32_t> active_;
};

// A hole-like peak's branches inserted into the pair around the peak (Sec. 3.2, Figs. 25-27):
// the innermost active pair whose crossings at the peak's theta hold its phi. Its begin then
// ends at the peak's branch going down; the peak's branch going up ends at its end.
void insert_hole_peak(const SlicedMesh& m, std::span<const RidgeEdge> ridges,
                      std::span<const Branch> branches, const Turn& t, bool point_light,
                      BranchPairs& pairs) {
  const ThetaSlice s = ThetaSlice::at(t.theta, point_light);
  const Vec3 v = m.local[t.vertex];
  const double phi = ThetaSlice::phi(v, s.rho(v));
  std::int64_t best = -1;
  double width = kInf;
  for (const std::uint32_t b : pairs.active()) {
    const std::int64_t e = pairs.partner(b);
    Crossing from, to;
    if (e < 0 || branch_crossing(m, ridges, branches[b], s, t.theta, from) < 0 ||
        branch_crossing(m, ridges, branches[std::size_t(e)], s, t.theta, to) < 0) {
      continue;
    }
    if (from.phi < phi && phi < to.phi && to.phi - from.phi < width) {
      best = b, width = to.phi - from.phi;
    }
  }
  pairs.activate(t.begins);
  if (best < 0) return;  // no pair around it: its begin has no partner (walked)
  const std::int64_t end = pairs.partner(std::uint32_t(best));
  pairs.pair(best, t.ends);
  pairs.pair(t.begins, end);
}

// Sec. 3.2: one turn of the sweep down.
void take_turn(const SlicedMesh& m, std::span<const RidgeEdge> ridges,
               std::span<const Branch> branches, const Turn& t, bool point_light,
               BranchPairs& pairs) {
  switch (t.kind) {
    case Turn::peak:  // a new group: its two branches pair
      pairs.pair(t.begins, t.ends);
      pairs.activate(t.begins);
      return;
    case Turn::hole_peak:
      insert_hole_peak(m, ridges, branches, t, point_light, pairs);
      return;
    case Turn::minimum: {  // two groups reach the same minimum: they merge
      const std::int64_t begin = pairs.partner(t.ends), end = pairs.partner(t.begins);
      pairs.deactivate(t.begins);
      pairs.pair(t.begins, -1);
      pairs.pair(t.ends, -1);
      if (begin != std::int64_t(t.begins)) pairs.pair(begin, end);
      return;
    }
  }
}

// The RePairs of one slice: every active begin with its partner.
void pairs_at(const SlicedMesh& m, std::span<const RidgeEdge> ridges,
              std::span<const Branch> branches, const BranchPairs& pairs, const ThetaSlice& s,
              double theta, std::vector<RePair>& out) {
  for (const std::uint32_t b : pairs.active()) {
    RePair p;
    p.entry = s.entry;
    p.theta = theta;
    const std::int64_t begin = branch_crossing(m, ridges, branches[b], s, theta, p.from);
    if (begin < 0) continue;
    p.begin = std::uint32_t(begin);
    const std::int64_t e = pairs.partner(b);
    if (e >= 0) p.end = branch_crossing(m, ridges, branches[std::size_t(e)], s, theta, p.to);
    out.push_back(p);
  }
}

// The other face of mesh edge \p e from face \p f; -1 when f is not one of its two faces.
std::int64_t face_across(const Mesh& mesh, std::uint32_t e, std::uint32_t f) {
  const MeshEdge& edge = mesh.edges[e];
  if (edge.use_count != 2) return -1;
  const std::uint32_t a = mesh.edge_uses[edge.first_use].face;
  const std::uint32_t b = mesh.edge_uses[edge.first_use + 1].face;
  if (a == f) return b;
  return b == f ? std::int64_t(a) : -1;
}

// The hidden edges' crossings of one slice, sorted by phi.
void hidden_crossings(const SlicedMesh& m, std::span<const std::uint32_t> hidden,
                      const ThetaSlice& s, std::vector<Crossing>& out) {
  out.clear();
  for (const std::uint32_t e : hidden) {
    if (!crosses(m, s, e)) continue;
    const Crossing c = edge_crossing(m, s, e);
    if (c.rho > 0) out.push_back(c);
  }
  std::sort(out.begin(), out.end(),
            [](const Crossing& a, const Crossing& b) { return a.phi < b.phi; });
}

// One RePair with the hidden edges between its ends inserted in duplicate (Sec. 3.3): a pair
// per face, from the begin's face on, each hidden crossing of the current face leading into
// the next, the last one ending at the partner's crossing. False when the faces do not lead
// to the partner's face: the last pair is then on another face.
bool fill_pair(const SlicedMesh& m, std::span<const RidgeEdge> ridges, const RePair& p,
               std::span<const Crossing> hidden, std::vector<EntryPair>& out) {
  std::uint32_t f = ridges[p.begin].face;
  double phi = p.from.phi;
  auto c = std::lower_bound(hidden.begin(), hidden.end(), phi,
                            [](const Crossing& x, double v) { return x.phi < v; });
  for (; c != hidden.end() && c->phi <= p.to.phi; ++c) {
    const std::int64_t next = face_across(m.mesh, std::uint32_t(c->edge), f);
    if (next < 0) continue;  // another layer's hidden edge
    out.push_back({p.entry, m.hidden_id[f], phi, c->phi});
    phi = c->phi;
    f = std::uint32_t(next);
  }
  out.push_back({p.entry, m.hidden_id[f], phi, p.to.phi});
  return ridges[std::size_t(p.end)].face == f;
}

// Entries whose centre may lie in [lo, hi], one more at each end against rounding.
std::pair<int, int> entry_range(const ThetaQuantization& q, double lo, double hi) {
  const int first = int(std::max(std::floor(q.position(lo) - 0.5), 0.0));
  const int last = int(std::min(std::ceil(q.position(hi) - 0.5), double(q.resolution - 1)));
  return {first, last};
}

// Sec. 2.2's split where it changes the branches: the pseudo intersections at which VREs go
// opposite ways in theta (a branch going down passes one going up as the light sees them).
// Where all go one way (the windings of a coil, Fig. 22), Sec. 3.2's peaks pair the layers as
// the far sheet joins them, and a split there would pair one layer's begin with another's
// end.
Vrepips where_branches_cross(const SlicedMesh& m, std::span<const RidgeEdge> ridges,
                             const Vrepips& all) {
  Vrepips out;
  for (const PseudoIntersection& at : all.at) {
    const int first = rise(m, ridges[all.points[at.vrepips[0]].ridge]);
    if (std::ranges::all_of(at.vrepips, [&](std::uint32_t v) {
          return rise(m, ridges[all.points[v].ridge]) == first;
        })) {
      continue;
    }
    PseudoIntersection& kept = out.at.emplace_back();
    for (const std::uint32_t v : at.vrepips) {
      kept.vrepips.push_back(std::uint32_t(out.points.size()));
      out.points.push_back(all.points[v]);
    }
  }
  return out;
}

// An object's RE loops after the split: each piece a ridge edge of its own (same mesh edge and
// face, so that its crossings are the edge's, bit for bit), its VREPIP ends vertices appended
// after the mesh's, so that Sec. 3.2's branches take the pieces as they take ridge edges.
struct SplitLoops {
  std::vector<Vec3> local;
  std::vector<double> theta;
  std::vector<RidgeEdge> ridges;
  std::vector<RidgeEdgeLoop> loops;
};

SplitLoops split_loops(const SlicedMesh& m, std::span<const RidgeEdge> ridges, const Vrepips& v,
                       std::span<const SimpleLoop> simple, bool point_light) {
  SplitLoops out{{m.local.begin(), m.local.end()}, {m.theta.begin(), m.theta.end()}, {}, {}};
  std::map<std::pair<std::uint32_t, double>, std::uint32_t> vertex_at;  // (ridge, t)
  for (const Vrepip& p : v.points) {
    vertex_at[{p.ridge, p.t}] = std::uint32_t(out.local.size());
    out.local.push_back(p.p);
    out.theta.push_back(local_theta(p.p, point_light));
  }
  for (const SimpleLoop& loop : simple) {
    RidgeEdgeLoop& split = out.loops.emplace_back(RidgeEdgeLoop{{}, true});
    for (const LoopPiece& piece : loop) {
      RidgeEdge re = ridges[piece.ridge];
      if (piece.t0 > 0) re.from = vertex_at.at({piece.ridge, piece.t0});
      if (piece.t1 < 1) re.to = vertex_at.at({piece.ridge, piece.t1});
      split.edges.push_back(std::uint32_t(out.ridges.size()));
      out.ridges.push_back(re);
    }
  }
  return out;
}

// Secs. 3.2-3.3 for loops that need no split.
void pair_loops(const SlicedMesh& m, std::span<const RidgeEdge> ridges,
                std::span<const RidgeEdgeLoop> loops, const ThetaQuantization& q,
                std::span<const ThetaSlice> slices, SliceScratch& scratch,
                std::vector<EntryPair>& out, PairingStats& stats, bool walk_fallback) {
  const LoopBranches branches = split_into_branches(m, ridges, loops, slices[0].point_light);
  const std::vector<RePair> pairs = pair_branches(m, ridges, branches, q, slices);
  const std::vector<std::uint32_t> hidden = hidden_edges(m.mesh, m.sheets);
  insert_hidden_edges(m, ridges, hidden, pairs, slices, scratch, out, stats, walk_fallback);
}

// Secs. 2.2 and 3.2-3.3: the loops split at \p v's VREPIPs, their pieces paired.
void pair_split_loops(const SlicedMesh& m, std::span<const RidgeEdge> ridges,
                      std::span<const RidgeEdgeLoop> loops, const Vrepips& v,
                      const ThetaQuantization& q, std::span<const ThetaSlice> slices,
                      SliceScratch& scratch, std::vector<EntryPair>& out, PairingStats& stats,
                      bool walk_fallback) {
  const bool point_light = slices[0].point_light;
  const SplitLoops split = split_loops(
      m, ridges, v, split_at_vrepips(m.local, ridges, loops, v, point_light), point_light);
  const SlicedMesh in_pieces{m.mesh, m.sheets, split.local, split.theta, m.hidden_id};
  pair_loops(in_pieces, split.ridges, split.loops, q, slices, scratch, out, stats, walk_fallback);
}

}  // namespace

LoopBranches split_into_branches(const SlicedMesh& m, std::span<const RidgeEdge> ridges,
                                 std::span<const RidgeEdgeLoop> loops, bool point_light) {
  LoopBranches out;
  for (const RidgeEdgeLoop& loop : loops) {
    std::vector<Run> runs = runs_of(m, ridges, loop);
    const auto first = std::uint32_t(out.branches.size());
    for (Run& run : runs) out.branches.push_back(branch_of(m, ridges, std::move(run)));
    const auto n = std::uint32_t(runs.size());
    for (std::uint32_t i = 0; i < n; ++i) {
      out.turns.push_back(
          turn_between(m, ridges, out.branches, first + i, first + (i + 1) % n, point_light));
    }
  }
  // From the top down; at one theta, branches end before new ones start, and a hole-like
  // peak finds the pair around it already there.
  std::sort(out.turns.begin(), out.turns.end(), [](const Turn& a, const Turn& b) {
    return std::tuple(-a.theta, int(a.kind)) < std::tuple(-b.theta, int(b.kind));
  });
  return out;
}

std::vector<RePair> pair_branches(const SlicedMesh& m, std::span<const RidgeEdge> ridges,
                                  const LoopBranches& branches, const ThetaQuantization& q,
                                  std::span<const ThetaSlice> slices) {
  std::vector<RePair> out;
  if (branches.turns.empty() || slices.empty()) return out;
  const bool point_light = slices[0].point_light;
  BranchPairs pairs(branches.branches.size());
  const auto [first, last] =
      entry_range(q, branches.turns.back().theta, branches.turns.front().theta);
  std::size_t next = 0;
  for (int k = last; k >= first; --k) {
    const double theta = q.centre(k);
    // The turns at or above the slice (a vertex on the slice counts as above it).
    for (; next < branches.turns.size() && branches.turns[next].theta >= theta; ++next) {
      take_turn(m, ridges, branches.branches, branches.turns[next], point_light, pairs);
    }
    const int entry = q.entry(k);
    if (entry >= 0) pairs_at(m, ridges, branches.branches, pairs, slices[entry], theta, out);
  }
  return out;
}

std::vector<std::uint32_t> hidden_edges(const Mesh& mesh, const FarSheets& sheets) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t e = 0; e < mesh.edges.size(); ++e) {
    const MeshEdge& edge = mesh.edges[e];
    if (edge.use_count != 2) continue;
    const std::uint32_t f = mesh.edge_uses[edge.first_use].face;
    if (sheets.occludes(f) && sheet_neighbour(mesh, sheets, f, e) >= 0) out.push_back(e);
  }
  return out;
}

void insert_hidden_edges(const SlicedMesh& m, std::span<const RidgeEdge> ridges,
                         std::span<const std::uint32_t> hidden, std::span<const RePair> pairs,
                         std::span<const ThetaSlice> slices, SliceScratch& scratch,
                         std::vector<EntryPair>& out, PairingStats& stats, bool walk_fallback) {
  if (slices.empty()) return;
  HiddenEdgeSweep sweep(m, hidden, slices[0].point_light);
  std::vector<Crossing> at_slice;
  std::int64_t entry = -1;
  for (const RePair& p : pairs) {
    const ThetaSlice& s = slices[p.entry];
    if (std::int64_t(p.entry) != entry) {
      entry = p.entry;
      hidden_crossings(m, sweep.at(p.theta), s, at_slice);
    }
    ++stats.re_pairs;
    const std::size_t mark = out.size();
    if (p.end >= 0 && fill_pair(m, ridges, p, at_slice, out)) continue;
    // Hazard: no partner, or faces that do not lead to it: walked instead, and counted.
    // Without the walk, the rules' pairs stay as they are: a begin without a partner shadows
    // nothing, and the last face the hidden edges led to ends the pair.
    ++stats.fallbacks;
    if (!walk_fallback) continue;
    out.resize(mark);
    scratch.path.clear();
    walk(m, s, ridges[p.begin].face, p.from, scratch, out);
  }
}

bool paper_pairing_applies(const FarSheets& sheets, std::span<const RidgeEdgeLoop> loops,
                           bool wraps, bool axis_faces) {
  return sheets.solid && !wraps && !axis_faces &&
         std::ranges::all_of(loops, [](const RidgeEdgeLoop& l) { return l.closed; });
}

void pair_re_loops(const SlicedMesh& m, std::span<const RidgeEdge> ridges,
                   std::span<const RidgeEdgeLoop> loops, const ThetaQuantization& q,
                   std::span<const ThetaSlice> slices, SliceScratch& scratch,
                   std::vector<EntryPair>& out, PairingStats& stats, bool walk_fallback) {
  if (slices.empty()) return;
  const std::size_t mark = out.size();
  PairingStats whole;
  pair_loops(m, ridges, loops, q, slices, scratch, out, whole, walk_fallback);
  const bool point_light = slices[0].point_light;
  const Vrepips v =
      whole.fallbacks == 0
          ? Vrepips{}
          : where_branches_cross(m, ridges, find_vrepips(m.local, ridges, loops, point_light));
  if (!v.points.empty()) {
    std::vector<EntryPair> split_out;
    PairingStats split{0, 0, v.points.size()};
    pair_split_loops(m, ridges, loops, v, q, slices, scratch, split_out, split, walk_fallback);
    // Hazard: a split at a VREPIP can pair what the far sheet does not join (the split loops
    // are the shadow polygons' outlines, not the far sheet's layers): it is kept only where
    // its pairs fall back less.
    if (split.fallbacks < whole.fallbacks) {
      out.resize(mark);
      out.insert(out.end(), split_out.begin(), split_out.end());
      whole = split;
    }
  }
  stats.re_pairs += whole.re_pairs;
  stats.fallbacks += whole.fallbacks;
  stats.vrepips += whole.vrepips;
}

}  // namespace shadowkit::angular
