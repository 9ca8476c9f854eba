#include "angular_table.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>

#include "loop_slicer.h"
#include "view_theta.h"

namespace shadowkit {
namespace {

constexpr double kPi = std::numbers::pi;

// One object's RE loops in the light's frame.
struct ObjectLoops {
  std::vector<Vec3> local;    // light-frame vertices
  std::vector<double> theta;  // per vertex on an RE
  std::vector<RidgeEdge> ridges;
  std::vector<RidgeEdgeLoop> loops;
  std::vector<std::uint32_t> hidden_id;   // per face, into AngularTable::hidden_
  std::vector<std::uint32_t> axis_faces;  // occluding faces the light's X axis pierces at X < 0
  double theta_lo = std::numeric_limits<double>::infinity(), theta_hi = -theta_lo;
  bool wraps = false;  // an RE passes behind the light's back (theta = +-pi)
};

// Sec. 7, steps 1.1-1.3: ridge edges, their loops, light-frame coordinates and theta range.
void find_loops(const Mesh& mesh, const FarSheets& sheets, const LightFrame& frame,
                ObjectLoops& o) {
  o.local.resize(mesh.vertices.size());
  for (std::size_t v = 0; v < o.local.size(); ++v) o.local[v] = frame.local(mesh.vertices[v]);
  o.ridges = find_ridge_edges(mesh, sheets);
  o.loops = chain_ridge_edge_loops(o.ridges);
  o.theta.assign(mesh.vertices.size(), 0);
  for (const RidgeEdge& re : o.ridges) {
    for (const std::uint32_t v : {re.from, re.to}) {
      const Vec3 p = o.local[v];
      o.theta[v] = frame.point_light() ? std::atan2(p.y, p.z) : p.y;
    }
  }
  for (const RidgeEdge& re : o.ridges) {
    double a = o.theta[re.from], b = o.theta[re.to];
    if (a > b) std::swap(a, b);
    o.wraps = o.wraps || (frame.point_light() && b - a > kPi);
    o.theta_lo = std::min(o.theta_lo, a);
    o.theta_hi = std::max(o.theta_hi, b);
  }
}

// Sec. 3: theta from the global minimum to the global maximum over the RE loops (the whole
// turn when they go around the light), cut to the theta the camera can see (eq. 4's range
// "based on the view volume"), in R entries; one more entry at each end against rounding.
ThetaQuantization quantize(const Scene& scene, const LightFrame& frame,
                           const std::vector<ObjectLoops>& objects, int resolution) {
  ThetaQuantization q;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const ObjectLoops& o : objects) {
    q.full_turn = q.full_turn || o.wraps || !o.axis_faces.empty();
    lo = std::min(lo, o.theta_lo);
    hi = std::max(hi, o.theta_hi);
  }
  if (q.full_turn) lo = -kPi, hi = kPi;
  const ViewTheta view = view_theta(scene, frame);
  if (view.bounded) {
    q.full_turn = false;
    lo = std::max(lo, view.lo);
    hi = std::min(hi, view.hi);
  }
  if (!(lo <= hi)) lo = 0, hi = 1;  // no ridge edge in view: an empty table of any range
  const double range = std::max(hi - lo, 1e-12);
  const int inner = resolution > 0 ? resolution : automatic_resolution(scene, frame, range);
  q.step = range / inner;
  q.theta_min = lo - (q.full_turn ? 0 : q.step);
  q.resolution = inner + (q.full_turn ? 0 : 2);
  return q;
}

// The ray from the light at (theta, phi) of slice s meets \p plane at distance t along it (a
// point light's ray direction scaled to unit rho); +inf if it does not.
double ray_depth(const ThetaSlice& s, const FrameAffine& plane, double phi) {
  const double along =
      s.point_light ? plane.a.x * phi + plane.a.y * s.sin + plane.a.z * s.cos : plane.a.z;
  const double offset = s.point_light ? plane.b : plane.a.x * phi + plane.a.y * s.theta + plane.b;
  const double t = -offset / along;
  return std::isfinite(t) && t > 0 ? t : std::numeric_limits<double>::infinity();
}

// Sec. 10: \p q adds nothing to \p p when p holds q's phi range and q lies beyond p's face
// over it (depth along rays is linear-fractional in phi, so both ends decide).
bool covers(const ThetaSlice& s, const HiddenFace& p, const AngularPair& pp, const HiddenFace& q,
            const AngularPair& qp) {
  if (pp.phi_begin > qp.phi_begin || pp.phi_end < qp.phi_end) return false;
  if (!std::isfinite(qp.phi_begin) || !std::isfinite(qp.phi_end)) return false;
  for (const double phi : {qp.phi_begin, qp.phi_end}) {
    const double tp = ray_depth(s, p.plane, phi), tq = ray_depth(s, q.plane, phi);
    if (!(tq > tp * (1 + 1e-9)) || !std::isfinite(tq)) return false;
  }
  return true;
}

}  // namespace

std::pair<const AngularPair*, std::span<const AngularPair>> AngularTable::narrow_from(
    int k, double phi) const {
  if (k < 0) return {};
  const std::span<const AngularPair> narrow = entry(k).subspan(wide_[k]);
  const auto first = std::partition_point(narrow.begin(), narrow.end(),
                                          [phi](const AngularPair& p) { return p.reach < phi; });
  const std::size_t skipped = std::size_t(first - narrow.begin());
  return {skipped ? &narrow[skipped - 1] : nullptr, narrow.subspan(skipped)};
}

int ThetaQuantization::entry(int k) const {
  if (full_turn) return ((k % resolution) + resolution) % resolution;
  return k >= 0 && k < resolution ? k : -1;
}

AngularTable AngularTable::build(const Scene& scene, const LightFrame& frame,
                                 const std::vector<FarSheets>& sheets,
                                 const AngularTableOptions& options) {
  AngularTable table;
  // Steps 1.1-1.3 per object, and the occluding faces' planes (the depth of Sec. 5).
  std::vector<ObjectLoops> objects(scene.objects.size());
  std::vector<std::uint32_t> first_hidden(objects.size() + 1, 0);
  for (std::size_t o = 0; o < objects.size(); ++o) {
    std::uint32_t n = 0;
    for (std::uint32_t f = 0; f < scene.objects[o].mesh.face_count(); ++f) {
      n += sheets[o].occludes(f);
    }
    first_hidden[o + 1] = first_hidden[o] + n;
  }
  table.hidden_.resize(first_hidden.back());
  tbb::parallel_for(std::size_t(0), objects.size(), [&](std::size_t o) {
    const SceneObject& object = scene.objects[o];
    ObjectLoops& loops = objects[o];
    find_loops(object.mesh, sheets[o], frame, loops);
    loops.hidden_id.assign(object.mesh.face_count(), 0);
    std::uint32_t next = first_hidden[o];
    for (std::uint32_t f = 0; f < object.mesh.face_count(); ++f) {
      if (!sheets[o].occludes(f)) continue;
      const std::uint32_t face = object.first_face + f;
      table.hidden_[next] = {frame.plane(scene.face_plane(face)), double(sheets[o].side[f]), face};
      loops.hidden_id[f] = next++;
      if (!frame.point_light()) continue;
      const SlicedMesh m{object.mesh, sheets[o], loops.local, loops.theta, loops.hidden_id};
      if (axis_piercing(m, f) < 0) loops.axis_faces.push_back(f);
    }
  });
  table.theta_ = quantize(scene, frame, objects, options.resolution);
  for (const ObjectLoops& o : objects) {
    table.loop_stats_.ridge_edges += double(o.ridges.size());
    table.loop_stats_.loops += double(o.loops.size());
    for (const RidgeEdgeLoop& loop : o.loops) table.loop_stats_.open_loops += !loop.closed;
  }
  std::vector<ThetaSlice> slices(table.theta_.resolution);
  for (int k = 0; k < table.theta_.resolution; ++k) {
    slices[k] = theta_slice(table.theta_, frame.point_light(), k);
  }
  // Steps 1.5-1.6: one loop at a time, the loops of all objects in parallel.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> work;  // (object, loop or ~axis face)
  for (std::uint32_t o = 0; o < objects.size(); ++o) {
    for (std::uint32_t l = 0; l < objects[o].loops.size(); ++l) work.emplace_back(o, l);
    for (const std::uint32_t f : objects[o].axis_faces) work.emplace_back(o, ~f);
  }
  struct Output {
    std::vector<Crossing> scratch;
    std::vector<EntryPair> pairs;
  };
  tbb::enumerable_thread_specific<Output> outputs;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, work.size(), 64), [&](const auto& range) {
    Output& out = outputs.local();
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const auto [o, l] = work[i];
      const ObjectLoops& loops = objects[o];
      const SlicedMesh m{scene.objects[o].mesh, sheets[o], loops.local, loops.theta,
                         loops.hidden_id};
      if (l < loops.loops.size()) {
        slice_loop(m, loops.ridges, loops.loops[l], table.theta_, slices, out.scratch, out.pairs);
      } else {
        slice_from_axis(m, ~l, slices, out.scratch, out.pairs);
      }
    }
  });
  std::vector<std::vector<EntryPair>> lists;
  for (Output& out : outputs) lists.push_back(std::move(out.pairs));
  table.fill_entries(lists);
  // Step 1.7: sort each entry by phi; Sec. 10: saturate.
  table.wide_.assign(table.theta_.resolution, 0);
  std::vector<std::uint32_t> kept(table.theta_.resolution);
  tbb::enumerable_thread_specific<SortScratch> scratch;
  tbb::parallel_for(0, table.theta_.resolution, [&](int k) {
    kept[k] = table.sort_entry(k, options.saturated ? &slices[k] : nullptr, scratch.local());
  });
  table.compact(kept);
  return table;
}

void AngularTable::fill_entries(std::span<const std::vector<EntryPair>> lists) {
  start_.assign(theta_.resolution + 1, 0);
  for (const auto& list : lists) {
    for (const EntryPair& it : list) ++start_[it.first + 1];
  }
  for (int k = 0; k < theta_.resolution; ++k) start_[k + 1] += start_[k];
  pairs_.resize(start_.back());
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (const auto& list : lists) {
    for (const EntryPair& it : list) pairs_[fill[it.first]++] = it.second;
  }
}

namespace {

// A double's bits as an unsigned integer of the same order (NaN excluded).
std::uint64_t ordered_bits(double x) {
  std::uint64_t u;
  std::memcpy(&u, &x, sizeof u);
  return u >> 63 ? ~u : u | (std::uint64_t(1) << 63);
}

// Sec. 10: \p q adds nothing when one of the last few kept pairs, or the one reaching
// furthest, already covers it.
bool saturated_by(const AngularTable& table, const ThetaSlice& s, std::span<const AngularPair> kept,
                  std::size_t furthest, const AngularPair& q) {
  constexpr std::size_t kRecent = 2;
  const HiddenFace& hq = table.hidden(q.hidden);
  const std::size_t first = kept.size() > kRecent ? kept.size() - kRecent : 0;
  for (std::size_t i = first; i < kept.size(); ++i) {
    if (covers(s, table.hidden(kept[i].hidden), kept[i], hq, q)) return true;
  }
  return furthest < first && covers(s, table.hidden(kept[furthest].hidden), kept[furthest], hq, q);
}

}  // namespace

std::uint32_t AngularTable::sort_entry(int k, const ThetaSlice* saturate, SortScratch& scratch) {
  const std::span<AngularPair> entry(pairs_.data() + start_[k], pairs_.data() + start_[k + 1]);
  if (entry.empty()) return 0;
  // Step 1.7: sort by phi_begin, on 16-byte keys rather than whole pairs.
  std::vector<SortKey>& keys = scratch.keys;
  keys.resize(entry.size());
  for (std::uint32_t i = 0; i < entry.size(); ++i) {
    keys[i] = {ordered_bits(entry[i].phi_begin), entry[i].hidden, i};
  }
  std::sort(keys.begin(), keys.end(), [](const SortKey& a, const SortKey& b) {
    return a.phi != b.phi ? a.phi < b.phi : a.hidden < b.hidden;
  });
  std::vector<AngularPair>& sorted = scratch.pairs;
  sorted.clear();
  std::size_t furthest = 0;
  for (const SortKey& key : keys) {
    const AngularPair& pair = entry[key.index];
    if (saturate && !sorted.empty() && saturated_by(*this, *saturate, sorted, furthest, pair)) {
      continue;
    }
    if (sorted.empty() || pair.phi_end > sorted[furthest].phi_end) furthest = sorted.size();
    sorted.push_back(pair);
  }
  // Wide pairs first, so that the reach of the narrow ones skips well.
  const double wide = (sorted[furthest].phi_end - sorted.front().phi_begin) / 16;
  const auto is_wide = [wide](const AngularPair& p) { return p.phi_end - p.phi_begin > wide; };
  std::size_t out = 0;
  for (const AngularPair& pair : sorted) {
    if (is_wide(pair)) entry[out++] = pair;
  }
  wide_[k] = std::uint32_t(out);
  double reach = -std::numeric_limits<double>::infinity();
  for (const AngularPair& pair : sorted) {
    if (is_wide(pair)) continue;
    entry[out] = pair;
    entry[out++].reach = reach = std::max(reach, pair.phi_end);
  }
  return std::uint32_t(out);
}

void AngularTable::compact(const std::vector<std::uint32_t>& kept) {
  std::uint32_t out = 0;
  for (int k = 0; k < theta_.resolution; ++k) {
    const std::uint32_t from = start_[k];
    std::copy_n(pairs_.begin() + from, kept[k], pairs_.begin() + out);
    start_[k] = out;
    out += kept[k];
    saturated_ += start_[k + 1] - from - kept[k];
  }
  start_[theta_.resolution] = out;
  pairs_.resize(out);
  pairs_.shrink_to_fit();
}

}  // namespace shadowkit
