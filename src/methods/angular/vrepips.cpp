#include "vrepips.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <tuple>

#include "light_frame.h"

namespace shadowkit::angular {
namespace {

// Two VREPIPs of one edge closer than this (in its parameter) are one point: where more than
// two VREs cross at one point (Sec. 2.4), each pair's test finds it up to rounding.
constexpr double kSamePoint = 1e-9;

// The light's ray through light-frame point v as a vector whose orientation tests are the
// projection's: v itself for a point light at the origin; (x, y, 1) for a light along +Z,
// which makes them the 2D orientation tests of the (x, y) plane.
Vec3 ray(Vec3 v, bool point_light) {
  return point_light ? v : Vec3{v.x, v.y, 1};
}

double orient(Vec3 a, Vec3 b, Vec3 c) {
  return dot(a, cross(b, c));
}

bool opposite(double a, double b) {
  return (a < 0 && b > 0) || (a > 0 && b < 0);
}

Vec3 lerp(Vec3 a, Vec3 b, double t) {
  return a + (b - a) * t;
}

// A VRE of a closed loop and its theta range (eq. 2), for the sweep that pairs the edges to
// test.
struct ThetaSpan {
  double lo = 0, hi = 0;
  std::uint32_t ridge = 0;
};

std::vector<ThetaSpan> vre_spans(std::span<const Vec3> local, std::span<const RidgeEdge> ridges,
                                 std::span<const RidgeEdgeLoop> loops, bool point_light) {
  std::vector<ThetaSpan> out;
  for (const RidgeEdgeLoop& loop : loops) {
    if (!loop.closed) continue;
    for (const std::uint32_t r : loop.edges) {
      const RidgeEdge& re = ridges[r];
      if (re.hidden_ridge) continue;  // Sec. 2.1: VREPIPs are between VREs only
      double lo = local_theta(local[re.from], point_light);
      double hi = local_theta(local[re.to], point_light);
      if (lo > hi) std::swap(lo, hi);
      // Hazard: an edge across the light's back (theta wraps) is tested against every other.
      if (point_light && hi - lo > std::numbers::pi) lo = -std::numbers::pi, hi = std::numbers::pi;
      out.push_back({lo, hi, r});
    }
  }
  std::ranges::sort(out, {}, &ThetaSpan::lo);
  return out;
}

// One crossing of two VREs' projections: ridge edges a and b, at s along a and t along b.
struct CrossingRecord {
  std::uint32_t a = 0, b = 0;
  double s = 0, t = 0;
};

// Sec. 2.4's "extensive edge-edge intersection tests", limited to the VREs whose theta
// ranges overlap: a crossing lies at one theta on both.
std::vector<CrossingRecord> crossings(std::span<const Vec3> local,
                                      std::span<const RidgeEdge> ridges,
                                      std::span<const ThetaSpan> spans, bool point_light) {
  std::vector<CrossingRecord> out;
  for (std::size_t i = 0; i < spans.size(); ++i) {
    const RidgeEdge& a = ridges[spans[i].ridge];
    for (std::size_t j = i + 1; j < spans.size() && spans[j].lo <= spans[i].hi; ++j) {
      const RidgeEdge& b = ridges[spans[j].ridge];
      const auto c =
          projections_cross(local[a.from], local[a.to], local[b.from], local[b.to], point_light);
      if (c) out.push_back({spans[i].ridge, spans[j].ridge, c->s, c->t});
    }
  }
  return out;
}

// Union-find over crossing records: the records of one projected point.
class RecordGroups {
 public:
  explicit RecordGroups(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void unite(std::size_t a, std::size_t b) { parent_[find(a)] = find(b); }

 private:
  std::vector<std::size_t> parent_;
};

// Records whose points on a shared edge agree meet at one point (Sec. 2.4, Fig. 15: three
// VREs crossing at one point give three records, each sharing an edge with the others).
RecordGroups group_records(std::span<const CrossingRecord> records) {
  std::vector<std::tuple<std::uint32_t, double, std::size_t>> on_edge;
  for (std::size_t k = 0; k < records.size(); ++k) {
    on_edge.emplace_back(records[k].a, records[k].s, k);
    on_edge.emplace_back(records[k].b, records[k].t, k);
  }
  std::ranges::sort(on_edge);
  RecordGroups groups(records.size());
  for (std::size_t i = 1; i < on_edge.size(); ++i) {
    const auto& [ridge, t, k] = on_edge[i];
    const auto& [previous_ridge, previous_t, previous_k] = on_edge[i - 1];
    if (ridge == previous_ridge && t - previous_t <= kSamePoint) groups.unite(k, previous_k);
  }
  return groups;
}

// Adds the VREPIP of \p ridge at \p t to \p at unless that VRE already has one there.
void add_vrepip(std::span<const Vec3> local, std::span<const RidgeEdge> ridges, std::uint32_t ridge,
                double t, bool point_light, PseudoIntersection& at, Vrepips& out) {
  for (const std::uint32_t v : at.vrepips) {
    if (out.points[v].ridge == ridge) return;
  }
  const Vec3 p = lerp(local[ridges[ridge].from], local[ridges[ridge].to], t);
  at.vrepips.push_back(std::uint32_t(out.points.size()));
  out.points.push_back({ridge, t, p, point_light ? length(p) : p.z});
}

// Each VRE's VREPIPs by t, and each VREPIP's place among them.
struct Stops {
  std::vector<std::vector<std::uint32_t>> on;  ///< per ridge edge: VREPIPs, by t
  std::vector<std::size_t> slot;               ///< per VREPIP: its index in its edge's list

  Stops(std::size_t ridges, const Vrepips& v) : on(ridges), slot(v.points.size()) {
    for (std::uint32_t i = 0; i < v.points.size(); ++i) on[v.points[i].ridge].push_back(i);
    for (std::vector<std::uint32_t>& list : on) {
      std::ranges::sort(list, {}, [&](std::uint32_t i) { return v.points[i].t; });
      for (std::size_t k = 0; k < list.size(); ++k) slot[list[k]] = k;
    }
  }
};

// Sec. 2.4 at one pseudo intersection: \p leave[v] for each of its VREPIPs v, the VREPIP
// whose edge the traversal takes on arriving at v. Around the point as the light sees it, in
// increasing angle from u towards w = n x u (taken as the paper's clockwise: what matters is
// one fixed sense), the VREs' halves coming in and going out are matched like parentheses,
// each coming-in half to a going-out half after it, so that the loops that come out do not
// cross there. Where the halves alternate, that is "the edge closest to the incoming edge
// clockwise"; of two VREs crossing, each leaves on the other (Sec. 2.2).
void match_at(std::span<const Vec3> local, std::span<const RidgeEdge> ridges, const Vrepips& v,
              const PseudoIntersection& at, bool point_light, std::vector<std::uint32_t>& leave) {
  const Vec3 n = point_light ? normalize(v.points[at.vrepips[0]].p) : Vec3{0, 0, 1};
  const Vec3 u = normalize(cross(n, std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
  const Vec3 w = cross(n, u);
  struct Half {
    double angle = 0;
    std::uint32_t vrepip = 0;
    int in = 0;  ///< +1 coming in, -1 going out
  };
  std::vector<Half> halves;
  for (const std::uint32_t i : at.vrepips) {
    const RidgeEdge& re = ridges[v.points[i].ridge];
    const Vec3 d = local[re.to] - local[re.from];
    const double out = std::atan2(dot(d, w), dot(d, u));
    halves.push_back({out, i, -1});
    halves.push_back({out > 0 ? out - std::numbers::pi : out + std::numbers::pi, i, 1});
  }
  std::ranges::sort(halves, {}, &Half::angle);
  // Start after the lowest running count, so that every half going out has one coming in
  // open before it.
  int count = 0, lowest = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i < halves.size(); ++i) {
    count += halves[i].in;
    if (count < lowest) lowest = count, start = i + 1;
  }
  std::vector<std::uint32_t> open;
  for (std::size_t k = 0; k < halves.size(); ++k) {
    const Half& h = halves[(start + k) % halves.size()];
    if (h.in > 0) {
      open.push_back(h.vrepip);
      continue;
    }
    leave[open.back()] = h.vrepip;
    open.pop_back();
  }
}

// The split's segments: every ridge edge of a closed loop cut at its VREPIPs, and where the
// traversal goes from each (Sec. 2.2): to the next ridge edge of the loop at the edge's end,
// across the imaginary edge at a VREPIP.
class Segments {
 public:
  Segments(std::span<const RidgeEdge> ridges, std::span<const RidgeEdgeLoop> loops,
           const Vrepips& v, std::vector<std::uint32_t> leave)
      : v_(v), stops_(ridges.size(), v), leave_(std::move(leave)), next_ridge_(ridges.size()) {
    for (std::size_t r = 0; r < ridges.size(); ++r) {
      first_.push_back(ridge_of_.size());
      ridge_of_.insert(ridge_of_.end(), stops_.on[r].size() + 1, std::uint32_t(r));
    }
    first_.push_back(ridge_of_.size());
    for (const RidgeEdgeLoop& loop : loops) {
      if (!loop.closed) continue;
      for (std::size_t i = 0; i < loop.edges.size(); ++i) {
        next_ridge_[loop.edges[i]] = loop.edges[(i + 1) % loop.edges.size()];
      }
    }
  }

  std::size_t size() const { return ridge_of_.size(); }
  /// The segments of \p ridge: [first(ridge), first(ridge + 1)).
  std::size_t first(std::uint32_t ridge) const { return first_[ridge]; }

  LoopPiece piece(std::size_t s) const {
    const std::uint32_t r = ridge_of_[s];
    const std::vector<std::uint32_t>& on = stops_.on[r];
    const std::size_t k = s - first_[r];
    return {r, k == 0 ? 0 : v_.points[on[k - 1]].t, k == on.size() ? 1 : v_.points[on[k]].t};
  }

  std::size_t next(std::size_t s) const {
    const std::uint32_t r = ridge_of_[s];
    const std::size_t k = s - first_[r];
    if (k == stops_.on[r].size()) return first_[next_ridge_[r]];
    const std::uint32_t w = leave_[stops_.on[r][k]];
    return first_[v_.points[w].ridge] + stops_.slot[w] + 1;
  }

 private:
  const Vrepips& v_;
  Stops stops_;
  std::vector<std::uint32_t> leave_;
  std::vector<std::uint32_t> next_ridge_;
  std::vector<std::size_t> first_;
  std::vector<std::uint32_t> ridge_of_;
};

}  // namespace

std::optional<ProjectedCrossing> projections_cross(Vec3 a0, Vec3 a1, Vec3 b0, Vec3 b1,
                                                   bool point_light) {
  const Vec3 ra0 = ray(a0, point_light), ra1 = ray(a1, point_light);
  const Vec3 rb0 = ray(b0, point_light), rb1 = ray(b1, point_light);
  const double b0_side = orient(ra0, ra1, rb0), b1_side = orient(ra0, ra1, rb1);
  const double a0_side = orient(rb0, rb1, ra0), a1_side = orient(rb0, rb1, ra1);
  if (!opposite(b0_side, b1_side) || !opposite(a0_side, a1_side)) return std::nullopt;
  const ProjectedCrossing c{a0_side / (a0_side - a1_side), b0_side / (b0_side - b1_side)};
  // The planes of the two segments' rays meet in a line through a point light: the crossing
  // is on one ray only if both points lie on the same side of the light.
  if (point_light && dot(lerp(a0, a1, c.s), lerp(b0, b1, c.t)) <= 0) return std::nullopt;
  return c;
}

Vrepips find_vrepips(std::span<const Vec3> local, std::span<const RidgeEdge> ridges,
                     std::span<const RidgeEdgeLoop> loops, bool point_light) {
  const std::vector<CrossingRecord> records =
      crossings(local, ridges, vre_spans(local, ridges, loops, point_light), point_light);
  RecordGroups groups = group_records(records);
  Vrepips out;
  std::vector<std::int64_t> point_of(records.size(), -1);  // per group root
  for (std::size_t k = 0; k < records.size(); ++k) {
    std::int64_t& point = point_of[groups.find(k)];
    if (point < 0) point = std::int64_t(out.at.size()), out.at.emplace_back();
    PseudoIntersection& at = out.at[std::size_t(point)];
    add_vrepip(local, ridges, records[k].a, records[k].s, point_light, at, out);
    add_vrepip(local, ridges, records[k].b, records[k].t, point_light, at, out);
  }
  for (PseudoIntersection& at : out.at) {
    std::ranges::sort(at.vrepips, {}, [&](std::uint32_t i) { return out.points[i].depth; });
  }
  return out;
}

std::vector<SimpleLoop> split_at_vrepips(std::span<const Vec3> local,
                                         std::span<const RidgeEdge> ridges,
                                         std::span<const RidgeEdgeLoop> loops, const Vrepips& v,
                                         bool point_light) {
  std::vector<std::uint32_t> leave(v.points.size());
  for (const PseudoIntersection& at : v.at) match_at(local, ridges, v, at, point_light, leave);
  const Segments segments(ridges, loops, v, std::move(leave));
  // Each segment lies on one loop of the split: the traversal from any one of them returns to
  // it. A loop starts at the first segment, in the loops' order, that none has taken.
  std::vector<char> taken(segments.size(), 0);
  std::vector<SimpleLoop> out;
  for (const RidgeEdgeLoop& loop : loops) {
    if (!loop.closed) continue;
    for (const std::uint32_t r : loop.edges) {
      for (std::size_t s = segments.first(r); s < segments.first(r + 1); ++s) {
        if (taken[s]) continue;
        SimpleLoop& simple = out.emplace_back();
        for (std::size_t at = s; !taken[at]; at = segments.next(at)) {
          taken[at] = 1;
          simple.push_back(segments.piece(at));
        }
      }
    }
  }
  return out;
}

}  // namespace shadowkit::angular
