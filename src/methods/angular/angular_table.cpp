#include "angular_table.h"

#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace shadowkit {
namespace {

constexpr double kPi = std::numbers::pi;

// theta-arc of one triangle seen from the light (lo <= hi, hi - lo < pi, hi may pass pi), or
// the whole turn when the axis through the light along X pierces it.
struct ThetaArc {
  double lo = 0, hi = 0;
  bool all = false;
};

ThetaArc theta_arc(const LightFrame& frame, const Vec3 (&v)[3]) {
  if (!frame.point_light()) {
    const double lo = std::min({v[0].y, v[1].y, v[2].y});
    return {lo, std::max({v[0].y, v[1].y, v[2].y}), false};
  }
  // Pierced: the origin inside the triangle's projection on the (Y, F) plane.
  double s[3];
  for (int i = 0; i < 3; ++i) {
    const Vec3 a = v[i], b = v[(i + 1) % 3];
    s[i] = a.y * b.z - a.z * b.y;
  }
  if ((s[0] >= 0 && s[1] >= 0 && s[2] >= 0) || (s[0] <= 0 && s[1] <= 0 && s[2] <= 0)) {
    return {0, 0, true};
  }
  double t[3];
  for (int i = 0; i < 3; ++i) t[i] = std::atan2(v[i].y, v[i].z);
  double lo = std::min({t[0], t[1], t[2]}), hi = std::max({t[0], t[1], t[2]});
  if (hi - lo > kPi) {  // the arc crosses theta = +-pi, behind the light
    for (double& a : t) a += a < 0 ? 2 * kPi : 0;
    lo = std::min({t[0], t[1], t[2]});
    hi = std::max({t[0], t[1], t[2]});
  }
  return {lo, hi, false};
}

// phi (tan(phi) for a point light) of a point of the theta-plane given its coordinate x
// along X and its signed distance rho >= 0 from the light's X axis inside the half-plane.
double plane_phi(const LightFrame& frame, Vec3 p, double rho) {
  return frame.point_light() ? p.x / rho : p.x;
}

// The light-frame corners of triangle \p t, sorted by vertex id so that a shared edge is cut
// bit-identically by both of its triangles.
void light_frame_corners(const TriangleList& tris, const LightFrame& frame, std::uint32_t t,
                         Vec3 (&v)[3]) {
  auto ids = tris.triangles[t];
  std::sort(ids.begin(), ids.end());
  for (int i = 0; i < 3; ++i) v[i] = frame.local(tris.positions[ids[i]]);
}

// Sec. 3: theta from the global minimum to the global maximum over the hidden triangles
// (the whole turn when they go around the light), in R entries.
ThetaQuantization quantize(const Scene& scene, const LightFrame& frame,
                           const std::vector<ThetaArc>& arcs, int resolution) {
  ThetaQuantization q;
  double lo = 0, hi = 1;  // no hidden face: an empty table of any range
  for (std::size_t i = 0; i < arcs.size(); ++i) {
    q.full_turn = q.full_turn || arcs[i].all || (frame.point_light() && arcs[i].hi > kPi);
    lo = i == 0 ? arcs[i].lo : std::min(lo, arcs[i].lo);
    hi = i == 0 ? arcs[i].hi : std::max(hi, arcs[i].hi);
  }
  if (q.full_turn) lo = -kPi, hi = kPi;
  const double range = std::max(hi - lo, 1e-12);
  q.resolution = resolution > 0 ? resolution : automatic_resolution(scene, frame, range);
  q.theta_min = lo;
  q.step = range / q.resolution;
  return q;
}

// The pairs of one triangle (corners \p v, theta arc \p arc) in every entry it spans.
void append_pairs(const LightFrame& frame, const Vec3 (&v)[3], const ThetaQuantization& q,
                  const ThetaArc& arc, AngularPair pair, std::vector<EntryPair>& out) {
  int k0 = 0, k1 = q.resolution - 1;
  if (!arc.all) {
    k0 = int(std::floor((arc.lo - q.theta_min) / q.step));
    k1 = int(std::floor((arc.hi - q.theta_min) / q.step));
    if (!q.full_turn) k0 = std::max(k0, 0), k1 = std::min(k1, q.resolution - 1);
  }
  for (int k = k0; k <= k1; ++k) {
    const int entry = q.entry(k);
    if (entry_span(frame, v, q, entry, pair)) out.emplace_back(entry, pair);
  }
}

}  // namespace

HiddenTriangle hidden_triangle(const LightFrame& frame, const Vec3 (&v)[3], const Plane& plane) {
  HiddenTriangle h;
  h.plane = frame.plane(plane);
  h.light_side = (frame.point_light() ? h.plane.b : -h.plane.a.z) > 0 ? 1 : -1;
  for (int i = 0; i < 3; ++i) {
    FrameAffine s = frame.ray_plane(v[i], v[(i + 1) % 3]);
    if (s.at(v[(i + 2) % 3]) < 0) s = {-s.a, -s.b};
    h.side[i] = s;
  }
  return h;
}

std::span<const AngularPair> AngularTable::narrow_from(int k, double phi) const {
  if (k < 0) return {};
  const std::span<const AngularPair> narrow = entry(k).subspan(wide_[k]);
  const auto first = std::partition_point(narrow.begin(), narrow.end(),
                                          [phi](const AngularPair& p) { return p.reach < phi; });
  return narrow.subspan(std::size_t(first - narrow.begin()));
}

const AngularPair* AngularTable::narrow_before(int k, double phi) const {
  if (k < 0) return nullptr;
  const std::span<const AngularPair> narrow = entry(k).subspan(wide_[k]);
  const std::size_t skipped = narrow.size() - narrow_from(k, phi).size();
  return skipped ? &narrow[skipped - 1] : nullptr;
}

int ThetaQuantization::entry(int k) const {
  if (full_turn) return ((k % resolution) + resolution) % resolution;
  return k >= 0 && k < resolution ? k : -1;
}

bool cut_triangle(const LightFrame& frame, const Vec3 (&v)[3], double theta, AngularPair& out) {
  const FrameAffine plane = frame.theta_plane(theta);
  double g[3];
  for (int i = 0; i < 3; ++i) g[i] = plane.at(v[i]);
  // Sec. 3.1: the points where the constant-theta plane crosses the triangle's edges.
  Vec3 p[2];
  int n = 0;
  for (int i = 0; i < 3 && n < 2; ++i) {
    for (int j = i + 1; j < 3 && n < 2; ++j) {
      if ((g[i] >= 0) == (g[j] >= 0)) continue;
      p[n++] = v[i] + (v[j] - v[i]) * (g[i] / (g[i] - g[j]));
    }
  }
  if (n < 2) return false;
  double rho[2] = {0, 0};
  if (frame.point_light()) {
    // Keep the part in the half-plane at theta (rho >= 0), not the one at theta + pi.
    const double sn = -plane.a.z, cs = plane.a.y;  // theta_plane is (0, cos, -sin)
    for (int i = 0; i < 2; ++i) rho[i] = p[i].y * sn + p[i].z * cs;
    if (rho[0] < 0 && rho[1] < 0) return false;
    if (rho[0] < 0 || rho[1] < 0) {
      const int out_side = rho[0] < 0 ? 0 : 1;
      const double t = rho[0] / (rho[0] - rho[1]);
      p[out_side] = p[0] + (p[1] - p[0]) * t;
      rho[out_side] = 0;
    }
  }
  double a = plane_phi(frame, p[0], rho[0]), b = plane_phi(frame, p[1], rho[1]);
  if (a > b) std::swap(a, b);
  out.phi_begin = a;
  out.phi_end = b;
  return true;
}

bool entry_span(const LightFrame& frame, const Vec3 (&v)[3], const ThetaQuantization& q, int k,
                AngularPair& out) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  AngularPair cut;
  for (double theta : {q.lower(k), q.centre(k), q.lower(k + 1)}) {
    if (!cut_triangle(frame, v, theta, cut)) continue;
    lo = std::min(lo, cut.phi_begin);
    hi = std::max(hi, cut.phi_end);
  }
  for (const Vec3& corner : v) {
    const AngularPoint a = frame.angular_local(corner);
    if (q.entry(q.index(a.theta)) != k) continue;
    lo = std::min(lo, a.phi);
    hi = std::max(hi, a.phi);
  }
  if (lo > hi) return false;
  if (!std::isfinite(lo) || !std::isfinite(hi)) {  // a corner on the light's X axis
    out.phi_begin = -std::numeric_limits<double>::infinity();
    out.phi_end = std::numeric_limits<double>::infinity();
    return true;
  }
  // Hazard: phi along an edge may bulge slightly between the sampled thetas.
  const double slope = frame.point_light() ? 1 + std::max(lo * lo, hi * hi) : 1;  // sec^2
  const double margin = (q.step + 1e-3 * (hi - lo)) * slope;
  out.phi_begin = lo - margin;
  out.phi_end = hi + margin;
  return true;
}

int automatic_resolution(const Scene& scene, const LightFrame& frame, double theta_range) {
  const Camera& cam = scene.camera;
  const Vec3 eye = cam.position, fwd = cam.forward();
  const double row_step = cam.pixel_grid().step;  // tan of one scan line at unit depth
  const double near = 1e-3 * std::max(scene.bounds().diagonal(), 1e-12);
  double finest = kPi;  // smallest theta step of one scan line over the vertices in view
  for (const auto& object : scene.objects) {
    for (Vec3 p : object.mesh.vertices) {
      const double depth = dot(p - eye, fwd);
      if (depth < near) continue;
      const Vec3 v = frame.local(p);
      const double span = frame.point_light() ? std::hypot(v.y, v.z) : 1.0;
      if (span > 0) finest = std::min(finest, depth * row_step / span);
    }
  }
  const double r = theta_range / finest;
  return int(std::clamp(r, 0.5 * cam.height, double(cam.height)));
}

AngularTable AngularTable::build(const Scene& scene, const LightFrame& frame,
                                 const AngularTableInput& input, const Context& /*ctx*/) {
  const TriangleList& tris = scene.triangles();
  std::vector<std::uint32_t> hidden;
  for (std::uint32_t t = 0; t < tris.triangles.size(); ++t) {
    if (input.occluder[tris.triangle_face[t]]) hidden.push_back(t);
  }
  AngularTable table;
  // Sec. 7, step 1.3: the hidden triangles in the light's frame, and their theta range.
  std::vector<ThetaArc> arcs(hidden.size());
  table.hidden_.resize(hidden.size());
  tbb::parallel_for(std::size_t(0), hidden.size(), [&](std::size_t i) {
    Vec3 v[3];
    light_frame_corners(tris, frame, hidden[i], v);
    arcs[i] = theta_arc(frame, v);
    table.hidden_[i] = hidden_triangle(frame, v, scene.face_plane(tris.triangle_face[hidden[i]]));
    table.hidden_[i].triangle = hidden[i];
  });
  table.theta_ = quantize(scene, frame, arcs, input.resolution);
  // Steps 1.5-1.6: every entry a hidden triangle spans gets its cut as one pair.
  tbb::combinable<std::vector<EntryPair>> pairs;
  tbb::parallel_for(std::size_t(0), hidden.size(), [&](std::size_t i) {
    Vec3 v[3];
    light_frame_corners(tris, frame, hidden[i], v);
    AngularPair pair;
    pair.hidden = std::uint32_t(i);
    pair.face = tris.triangle_face[hidden[i]];
    append_pairs(frame, v, table.theta_, arcs[i], pair, pairs.local());
  });
  table.fill_entries(pairs);
  // Step 1.7: sort each entry by phi.
  table.wide_.assign(table.theta_.resolution, 0);
  tbb::parallel_for(0, table.theta_.resolution, [&](int k) { table.sort_entry(k); });
  return table;
}

void AngularTable::fill_entries(tbb::combinable<std::vector<EntryPair>>& pairs) {
  start_.assign(theta_.resolution + 1, 0);
  pairs.combine_each([&](const std::vector<EntryPair>& list) {
    for (const EntryPair& it : list) ++start_[it.first + 1];
  });
  for (int k = 0; k < theta_.resolution; ++k) start_[k + 1] += start_[k];
  pairs_.resize(start_.back());
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  pairs.combine_each([&](const std::vector<EntryPair>& list) {
    for (const EntryPair& it : list) pairs_[fill[it.first]++] = it.second;
  });
}

void AngularTable::sort_entry(int k) {
  const auto begin = pairs_.begin() + start_[k], last = pairs_.begin() + start_[k + 1];
  if (begin == last) return;
  std::sort(begin, last, [](const AngularPair& a, const AngularPair& b) {
    if (a.phi_begin != b.phi_begin) return a.phi_begin < b.phi_begin;
    return a.hidden != b.hidden ? a.hidden < b.hidden : a.phi_end < b.phi_end;
  });
  // Wide pairs first, so that the reach of the narrow ones skips well.
  double extent_end = begin->phi_end;
  for (auto it = begin; it != last; ++it) extent_end = std::max(extent_end, it->phi_end);
  const double wide = (extent_end - begin->phi_begin) / 16;
  const auto narrow = std::stable_partition(
      begin, last, [wide](const AngularPair& p) { return p.phi_end - p.phi_begin > wide; });
  wide_[k] = std::uint32_t(narrow - begin);
  double reach = -std::numeric_limits<double>::infinity();
  for (auto it = narrow; it != last; ++it) it->reach = reach = std::max(reach, it->phi_end);
}

}  // namespace shadowkit
