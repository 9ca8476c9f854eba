#include "angular_table.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <tuple>

#include "loop_slicer.h"
#include "parallel_each.h"
#include "re_loop_pairing.h"
#include "view_theta.h"

namespace shadowkit::angular {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The RE loops are sliced in this many chunks, each a task with its own list of pairs:
// enough for both cores to balance on small scenes too, few enough lists to merge.
constexpr std::size_t kChunks = 16;

// One object's RE loops in the light's frame.
struct ObjectLoops {
  std::vector<Vec3> local;    // light-frame vertices
  std::vector<double> theta;  // per vertex on an RE
  std::vector<RidgeEdge> ridges;
  std::vector<RidgeEdgeLoop> loops;
  std::vector<double> loop_phi;           // per loop, the least phi of its vertices
  std::vector<std::uint32_t> hidden_id;   // per face, into AngularTable::hidden_
  std::vector<std::uint32_t> axis_faces;  // occluding faces the light's X axis pierces at X < 0
  double theta_lo = kInf, theta_hi = -theta_lo;
  bool wraps = false;  // an RE passes behind the light's back (theta = +-pi)
};

// One task of the slicing: an RE loop of an object, or a walk from the light's X axis in an
// occluding face (loop = ~face), and the least phi that orders it.
struct LoopWork {
  double phi = 0;
  std::uint32_t object = 0, loop = 0;
  bool whole_object = false;  ///< all the object's loops, paired as the RE-loops paper does
};

// The objects whose loops paper pairing takes (RE-loops paper, Sec. 3.2): per object, 1 or 0.
std::vector<char> paper_paired(const std::vector<ObjectLoops>& objects,
                               const std::vector<FarSheets>& sheets, bool paper) {
  std::vector<char> out(objects.size(), 0);
  for (std::size_t o = 0; paper && o < objects.size(); ++o) {
    out[o] = paper_pairing_applies(sheets[o], objects[o].loops, objects[o].wraps,
                                   !objects[o].axis_faces.empty());
  }
  return out;
}

// Writes the pairs of \p sorted (by phi_begin) that \p keep takes to the front of \p out:
// the narrow ones, each with its reach, then the wide ones (longer than a sixteenth of the
// extent of \p sorted), out of their reach, which then skips well. Returns the counts of
// pairs kept and of wide ones.
template <class Keep>
std::pair<std::uint32_t, std::uint32_t> split_wide(std::span<const AngularPair> sorted,
                                                   std::span<AngularPair> out,
                                                   std::vector<AngularPair>& wide_pairs,
                                                   Keep keep) {
  if (sorted.empty()) return {0, 0};
  double extent_end = -kInf;
  for (const AngularPair& pair : sorted) extent_end = std::max(extent_end, pair.phi_end);
  const double wide = (extent_end - sorted.front().phi_begin) / 16;
  wide_pairs.clear();
  std::size_t narrow = 0;
  double reach = -kInf;
  for (const AngularPair& pair : sorted) {
    if (!keep(pair)) continue;
    if (pair.phi_end - pair.phi_begin > wide) {
      wide_pairs.push_back(pair);
      continue;
    }
    out[narrow] = pair;
    out[narrow++].reach = reach = std::max(reach, pair.phi_end);
  }
  std::copy(wide_pairs.begin(), wide_pairs.end(), out.begin() + narrow);
  return {std::uint32_t(narrow + wide_pairs.size()), std::uint32_t(wide_pairs.size())};
}

// One block's pairs while they are made, per thread: per hidden face, the block it was last
// seen in and its pair's slot there.
struct BlockScratch {
  std::vector<int> block;
  std::vector<std::uint32_t> slot;
  std::vector<AngularPair> spans, wide;
  PhiBeginSort sort;
};

// Block \p b of \p entries' pairs in \p out: one pair per hidden face, from the least
// phi_begin of its pairs to the largest phi_end, narrow and wide as split_wide orders them;
// returns the wide ones' count.
std::uint32_t span_faces(std::span<const AngularPair> entries, int b, BlockScratch& scratch,
                         std::vector<AngularPair>& out) {
  std::vector<AngularPair>& spans = scratch.spans;
  spans.clear();
  for (const AngularPair& pair : entries) {
    if (scratch.block[pair.hidden] != b) {
      scratch.block[pair.hidden] = b;
      scratch.slot[pair.hidden] = std::uint32_t(spans.size());
      spans.push_back(pair);
      continue;
    }
    AngularPair& span = spans[scratch.slot[pair.hidden]];
    span.phi_begin = std::min(span.phi_begin, pair.phi_begin);
    span.phi_end = std::max(span.phi_end, pair.phi_end);
  }
  const std::span<const AngularPair> sorted = scratch.sort(spans);
  out.resize(sorted.size());
  return split_wide(sorted, out, scratch.wide, [](const AngularPair&) { return true; }).second;
}

// Every object's vertices in the light's frame, in parallel.
void place_vertices(const Scene& scene, const LightFrame& frame,
                    std::vector<ObjectLoops>& objects) {
  tbb::parallel_for(std::size_t(0), objects.size(), [&](std::size_t o) {
    const Mesh& mesh = scene.objects[o].mesh;
    objects[o].local.resize(mesh.vertices.size());
    parallel_each(mesh.vertices.size(),
                  [&](std::size_t v) { objects[o].local[v] = frame.local(mesh.vertices[v]); });
  });
}

// Some vertices lie on each side of the light's X axis in Y and in F, and some at X <= 0: a
// point light's axis may then pierce a face at X < 0 (Sec. 11.2), which is rare.
bool straddles_negative_axis(std::span<const Vec3> local) {
  Vec3 lo{kInf, kInf, kInf}, hi = -lo;
  for (const Vec3& v : local) lo = min(lo, v), hi = max(hi, v);
  return lo.x <= 0 && lo.y <= 0 && hi.y >= 0 && lo.z <= 0 && hi.z >= 0;
}

// The occluding faces' planes (the depth of Sec. 5) from \p first on, in parallel over one
// object's faces, and every face's hidden id in \p of_face (kNoFace where it occludes not).
void place_hidden_faces(const Scene& scene, std::size_t o, const FarSheets& sheets,
                        const LightFrame& frame, std::uint32_t first, ObjectLoops& loops,
                        std::vector<HiddenFace>& hidden, std::vector<std::uint32_t>& of_face) {
  const SceneObject& object = scene.objects[o];
  const Mesh& mesh = object.mesh;
  loops.hidden_id.assign(mesh.face_count(), 0);
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
    const bool occludes = sheets.occludes(f);
    of_face[object.first_face + f] = occludes ? first : kNoFace;
    if (occludes) loops.hidden_id[f] = first++;
  }
  const bool may_pierce = frame.point_light() && straddles_negative_axis(loops.local);
  std::vector<char> pierced(may_pierce ? mesh.face_count() : 0, 0);
  parallel_each(std::uint32_t(mesh.face_count()), [&](std::uint32_t f) {
    if (!sheets.occludes(f)) return;
    const std::uint32_t face = object.first_face + f;
    hidden[loops.hidden_id[f]] = {frame.plane(scene.face_plane(face)), double(sheets.side[f]),
                                  face};
    if (pierced.empty()) return;
    const SlicedMesh m{mesh, sheets, loops.local, {}, loops.hidden_id};
    pierced[f] = axis_piercing(m, f) < 0;
  });
  for (std::uint32_t f = 0; f < pierced.size(); ++f) {
    if (pierced[f]) loops.axis_faces.push_back(f);
  }
}

// Eq. 2 once per vertex on a ridge edge, in parallel.
void ridge_thetas(const Mesh& mesh, const LightFrame& frame, ObjectLoops& o) {
  std::vector<char> on_ridge(mesh.vertices.size(), 0);
  for (const RidgeEdge& re : o.ridges) on_ridge[re.from] = on_ridge[re.to] = 1;
  o.theta.assign(mesh.vertices.size(), 0);
  parallel_each(o.theta.size(), [&](std::size_t v) {
    if (!on_ridge[v]) return;
    const Vec3 p = o.local[v];
    o.theta[v] = frame.point_light() ? std::atan2(p.y, p.z) : p.y;
  });
}

// The ridge edges chained into loops, and each loop's least phi, which orders the slicing.
void chain_loops(const LightFrame& frame, ObjectLoops& o) {
  o.loops = chain_ridge_edge_loops(o.ridges);
  o.loop_phi.assign(o.loops.size(), kInf);
  for (std::size_t l = 0; l < o.loops.size(); ++l) {
    for (const std::uint32_t e : o.loops[l].edges) {
      o.loop_phi[l] = std::min(o.loop_phi[l], frame.phi_local(o.local[o.ridges[e].from]));
    }
  }
}

// Sec. 7, steps 1.1-1.3: ridge edges, their loops (on a large object chained while eq. 2 is
// computed) and their theta range.
void find_loops(const Mesh& mesh, const FarSheets& sheets, const LightFrame& frame,
                ObjectLoops& o) {
  o.ridges = find_ridge_edges(mesh, sheets);
  if (o.ridges.size() <= kParallelGrain) {
    chain_loops(frame, o);
    ridge_thetas(mesh, frame, o);
  } else {
    tbb::parallel_invoke([&] { chain_loops(frame, o); }, [&] { ridge_thetas(mesh, frame, o); });
  }
  for (const RidgeEdge& re : o.ridges) {
    double a = o.theta[re.from], b = o.theta[re.to];
    if (a > b) std::swap(a, b);
    // Half a turn may pass behind the light too (kHalfTurnTolerance).
    o.wraps = o.wraps || (frame.point_light() && (b - a > kPi || half_a_turn(a, b)));
    o.theta_lo = std::min(o.theta_lo, a);
    o.theta_hi = std::max(o.theta_hi, b);
  }
}

// kappa of ThetaQuantization: tan(kappa pi / 2) = kHemisphereTan.
double hemisphere_kappa() {
  return 2 * std::atan(kHemisphereTan) / kPi;
}

// Sec. 3: theta from the global minimum to the global maximum over the RE loops (the whole
// turn when they go around the light), cut to the theta the camera can see (eq. 4's range
// "based on the view volume"), in R entries.
ThetaQuantization quantize(const Scene& scene, const LightFrame& frame,
                           const std::vector<ObjectLoops>& objects, const ViewTheta& view,
                           double view_scale, const AngularTableOptions& options) {
  ThetaQuantization q;
  double lo = kInf, hi = -lo;
  for (const ObjectLoops& o : objects) {
    q.full_turn = q.full_turn || o.wraps || !o.axis_faces.empty();
    lo = std::min(lo, o.theta_lo);
    hi = std::max(hi, o.theta_hi);
  }
  if (q.full_turn) lo = -kPi, hi = kPi;
  // Sec. 11.2 splits the turn at the light's XY plane, which the view's cut would not keep.
  q.hemispheres = q.full_turn && options.hemispheres;
  if (view.bounded && !q.hemispheres) {
    q.full_turn = false;
    lo = std::max(lo, view.lo);
    hi = std::min(hi, view.hi);
  }
  if (!(lo <= hi)) lo = 0, hi = 1;  // no ridge edge in view: an empty table of any range
  if (!q.full_turn) {  // hazard: a visible point on the range's edge must round into it
    const double pad = 1e-9 * std::max({std::abs(lo), std::abs(hi), hi - lo});
    lo -= pad, hi += pad;
  }
  const double range = std::max(hi - lo, 1e-12);
  if (options.resolution > 0) {
    q.resolution = options.resolution;
  } else if (options.eq4) {
    q.resolution = eq4_resolution(scene, view_scale, lo, hi, frame.point_light());
  } else {
    q.resolution = automatic_resolution(scene, view_scale, range);
  }
  // Each hemisphere's entries split at theta' = 0 too, R / 4 to a side: the XY plane, where
  // Sec. 11.2 splits the loops, then falls between entries.
  if (q.hemispheres) q.resolution = (q.resolution + 3) / 4 * 4;
  q.step = range / q.resolution;
  q.theta_min = lo;
  return q;
}

}  // namespace

// Hemisphere h (0: in front of the light, F > 0; 1 behind it, and -1 a turn lower) holds
// theta in [h pi - pi/2, h pi + pi/2); theta' = theta - h pi is eq. 2's angle within it.
// Position: R / 4 at theta = -pi/2, so that theta in [-pi, pi] maps to [0, R].
double ThetaQuantization::hemisphere_position(double theta) const {
  const double h = std::floor((theta + kPi / 2) / kPi);
  const double w = std::tan(hemisphere_kappa() * (theta - h * kPi)) / kHemisphereTan;
  return (h + (w + 1) / 2) * (resolution / 2.0) + resolution / 4.0;
}

double ThetaQuantization::hemisphere_theta(double p) const {
  const double u = (p - resolution / 4.0) / (resolution / 2.0);
  const double h = std::floor(u);
  const double w = 2 * (u - h) - 1;
  return h * kPi + std::atan(w * kHemisphereTan) / hemisphere_kappa();
}

double ThetaQuantization::widest() const {
  // d theta' / d p is largest at w = 0: (4 / R) kHemisphereTan / kappa.
  return hemispheres ? 4 * kHemisphereTan / (hemisphere_kappa() * resolution) : step;
}

// A plane's depth along the rays of a slice as a linear form in (phi, u, v): for a point
// light the inverse depth 1 / t = (a.x phi + a.y sin + a.z cos) / -b of the plane
// a.p + b = 0 along the ray (phi, sin, cos) of the slice at theta (scaled to unit rho), with
// (u, v) = (sin, cos); for a directional light the depth t = (a.x phi + a.y theta + b) / -a.z
// along the ray through (phi, theta), with (u, v) = (theta, 1).
struct DepthForm {
  Vec3 c;  ///< NaN for a plane through the light or parallel to the rays: never compared

  static DepthForm of(const FrameAffine& plane, bool point_light) {
    const Vec3 c = point_light ? plane.a * (1 / -plane.b)
                               : Vec3{plane.a.x, plane.a.y, plane.b} * (1 / -plane.a.z);
    const bool finite = std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z);
    return {finite ? c : Vec3{kNaN, kNaN, kNaN}};
  }
};

// The directions of theta at every entry's centre and bounds, each computed once per build
// for the slices and saturation: (sin, cos) of theta for a point light, (theta, 1) for a
// directional light.
class EntryRays {
 public:
  EntryRays(const ThetaQuantization& q, bool point_light) : rays_(2 * q.resolution + 1) {
    tbb::parallel_for(0, int(rays_.size()), [&](int i) {
      const double theta = i % 2 ? q.centre(i / 2) : q.lower(i / 2);
      rays_[i] = point_light ? std::pair{std::sin(theta), std::cos(theta)} : std::pair{theta, 1.0};
    });
  }
  std::pair<double, double> lower(int k) const { return rays_[2 * std::size_t(k)]; }
  std::pair<double, double> centre(int k) const { return rays_[2 * std::size_t(k) + 1]; }

 private:
  std::vector<std::pair<double, double>> rays_;
};

// Sec. 10 within one entry, its pairs offered in order of phi_begin: a pair adds nothing
// when one of the last two kept pairs holds its phi range and lies nearer the light at both
// its ends, at the entry's centre and at its two theta bounds: a pair answers for the whole
// entry, and a face nearly edge-on to the light (a ground under a grazing light) can be
// nearer at the centre and far beyond at a bound. Depth along the rays is linear-fractional
// in phi, so the ends decide; across the entry the bounds and the centre stand for theta.
// The pair reaching furthest is no better a candidate: on the cube field it is the
// ground's, behind everything.
class Saturation {
 public:
  // \p rays: entry k's rays as EntryRays holds them.
  Saturation(std::span<const DepthForm> forms, const EntryRays& rays, int k, bool point_light)
      : forms_(forms),
        point_light_(point_light),
        rays_{rays.centre(k), rays.lower(k), rays.lower(k + 1)} {}  // most fail at the centre

  bool covers(const AngularPair& q) {
    if (!std::isfinite(q.phi_begin) || !std::isfinite(q.phi_end)) return false;
    for (std::size_t i = 0; i < std::min<std::size_t>(kept_, 2); ++i) {
      const Kept& p = recent_[i];
      if (p.begin > q.phi_begin || p.end < q.phi_end) continue;
      if (nearer(*p.depth, forms_[q.hidden], q.phi_begin, q.phi_end)) return true;
    }
    return false;
  }
  void keep(const AngularPair& p) {
    recent_[kept_++ % 2] = {p.phi_begin, p.phi_end, &forms_[p.hidden]};
  }

 private:
  struct Kept {
    double begin = 0, end = 0;
    const DepthForm* depth = nullptr;
  };
  // Plane p lies nearer the light than plane q, which the rays meet, along every ray at
  // phi0 and phi1 of the entry's three thetas. For a point light w = 1 / t: p's w exceeds
  // q's, which is positive; for a directional light w = t: q's exceeds p's, positive. Both
  // differences are linear forms, so each is checked at the phi end where it is least.
  bool nearer(const DepthForm& p, const DepthForm& q, double phi0, double phi1) const {
    constexpr double kTolerance = 1 + 1e-9;
    const Vec3 larger = point_light_ ? p.c : q.c, positive = point_light_ ? q.c : p.c;
    return positive_on_rays(larger - positive * kTolerance, phi0, phi1) &&
           positive_on_rays(positive, phi0, phi1);
  }
  // A linear form in (phi, u, v) is positive on every ray at phi0 and phi1 (false for NaN).
  bool positive_on_rays(const Vec3& form, double phi0, double phi1) const {
    const double along = form.x * (form.x > 0 ? phi0 : phi1);
    bool positive = true;
    for (const auto& [u, v] : rays_) positive &= along + form.y * u + form.z * v > 0;
    return positive;
  }

  std::span<const DepthForm> forms_;  // per occluding face
  bool point_light_;
  std::pair<double, double> rays_[3];
  std::size_t kept_ = 0;
  Kept recent_[2];
};

namespace {

// The occluding faces in hidden-id order: their planes (the depth of Sec. 5) and corners.
struct Occluders {
  std::vector<HiddenFace> hidden;
  std::vector<std::uint32_t> of_face;  // per global face, its hidden id or kNoFace
  std::vector<std::uint32_t> corner_start;
  std::vector<Vec3> corners;
  std::vector<std::uint32_t> across;
};

// The occluding face across manifold edge \p e from face \p f, or -1.
std::int64_t occluding_neighbour(const Mesh& mesh, const FarSheets& sheets, std::uint32_t f,
                                 std::uint32_t e) {
  const MeshEdge& edge = mesh.edges[e];
  if (edge.use_count != 2) return -1;
  const std::uint32_t a = mesh.edge_uses[edge.first_use].face;
  const std::uint32_t other = a == f ? mesh.edge_uses[edge.first_use + 1].face : a;
  return sheets.occludes(other) ? std::int64_t(other) : -1;
}

// Object o's occluding faces' corners in the light frame, and their occluding neighbours
// across each side, from hidden id \p id and corner \p corner on (ids go by object, then by face,
// as place_hidden_faces assigns them).
void place_corners(const Mesh& mesh, const FarSheets& sheets, const ObjectLoops& loops,
                   std::uint32_t id, std::uint32_t corner, Occluders& out) {
  const std::uint32_t first_id = id, first_corner = corner;
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
    if (!sheets.occludes(f)) continue;
    corner += mesh.face_size(f);
    out.corner_start[++id] = corner;
  }
  // The object's first start is the previous object's end, which its own task writes.
  parallel_each(std::uint32_t(mesh.face_count()), [&](std::uint32_t f) {
    if (!sheets.occludes(f)) return;
    const std::uint32_t i = loops.hidden_id[f];
    std::uint32_t c = i == first_id ? first_corner : out.corner_start[i];
    for (std::uint32_t k = 0; k < mesh.face_size(f); ++k, ++c) {
      const std::int64_t next =
          occluding_neighbour(mesh, sheets, f, mesh.corner_edge[mesh.face_start[f] + k]);
      out.across[c] = next < 0 ? kNoFace : loops.hidden_id[std::size_t(next)];
      out.corners[c] = loops.local[mesh.face_vertex(f, k)];
    }
  });
}

// Also numbers each object's occluding faces and marks the axis faces.
Occluders place_occluders(const Scene& scene, const std::vector<FarSheets>& sheets,
                          const LightFrame& frame, std::vector<ObjectLoops>& objects) {
  // Per object, its first hidden id and first corner.
  std::vector<std::uint32_t> first_hidden(objects.size() + 1, 0), first_corner = first_hidden;
  for (std::size_t o = 0; o < objects.size(); ++o) {
    const Mesh& mesh = scene.objects[o].mesh;
    std::uint32_t faces = 0, corners = 0;
    for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
      if (!sheets[o].occludes(f)) continue;
      ++faces;
      corners += mesh.face_size(f);
    }
    first_hidden[o + 1] = first_hidden[o] + faces;
    first_corner[o + 1] = first_corner[o] + corners;
  }
  Occluders out;
  out.hidden.resize(first_hidden.back());
  out.of_face.resize(scene.face_count());
  out.corner_start.assign(first_hidden.back() + 1, 0);
  out.corners.resize(first_corner.back());
  out.across.resize(first_corner.back());
  tbb::parallel_for(std::size_t(0), objects.size(), [&](std::size_t o) {
    place_hidden_faces(scene, o, sheets[o], frame, first_hidden[o], objects[o], out.hidden,
                       out.of_face);
    place_corners(scene.objects[o].mesh, sheets[o], objects[o], first_hidden[o], first_corner[o],
                  out);
  });
  return out;
}

}  // namespace

std::pair<const AngularPair*, std::span<const AngularPair>> PairLists::narrow_from(
    int k, double phi) const {
  if (k < 0) return {};
  const std::span<const AngularPair> sorted = narrow(k);
  const auto first = std::partition_point(sorted.begin(), sorted.end(),
                                          [phi](const AngularPair& p) { return p.reach < phi; });
  const std::size_t skipped = std::size_t(first - sorted.begin());
  return {skipped ? &sorted[skipped - 1] : nullptr, sorted.subspan(skipped)};
}

bool AngularTable::blocks(std::uint32_t i, Vec3 p, bool point_light, double tolerance) const {
  const HiddenFace& h = hidden_[i];
  if (!h.behind(p, tolerance)) return false;
  // Where the ray meets the face's plane, then the crossing number of that point in the
  // face, both projected along the plane normal's largest axis.
  const FrameAffine& plane = h.plane;
  const Vec3 at =
      point_light ? p * (-plane.b / dot(plane.a, p)) : p - Vec3{0, 0, plane.at(p) / plane.a.z};
  const Vec3 n{std::abs(plane.a.x), std::abs(plane.a.y), std::abs(plane.a.z)};
  const int u = n.x >= n.y && n.x >= n.z ? 1 : 0, v = n.z >= n.x && n.z >= n.y ? 1 : 2;
  bool inside = false;
  const std::uint32_t first = corner_start_[i], count = corner_start_[i + 1] - first;
  for (std::uint32_t k = 0; k < count; ++k) {
    const Vec3 a = corners_[first + k], b = corners_[first + (k + 1) % count];
    if ((a[v] > at[v]) != (b[v] > at[v]) &&
        at[u] < a[u] + (b[u] - a[u]) * (at[v] - a[v]) / (b[v] - a[v])) {
      inside = !inside;
    }
  }
  return inside;
}

AngularTable AngularTable::build(const Scene& scene, const LightFrame& frame,
                                 const std::vector<FarSheets>& sheets,
                                 const AngularTableOptions& options, AngularTableBuffers* buffers) {
  AngularTableBuffers own;
  AngularTableBuffers& storage = buffers ? *buffers : own;
  AngularTable table;
  std::vector<ObjectLoops> objects(scene.objects.size());
  place_vertices(scene, frame, objects);
  // Three independent tasks at once: steps 1.1-1.3 per object; the occluding faces' planes
  // and corners (the depth of Sec. 5); eq. 4's inputs from the view.
  Occluders occluders;
  ViewTheta view;
  double view_scale = 0;  // eq. 4's scale: an entry's theta, or (eq4) Z_f in scan lines
  tbb::parallel_invoke(
      [&] {
        tbb::parallel_for(std::size_t(0), objects.size(), [&](std::size_t o) {
          find_loops(scene.objects[o].mesh, sheets[o], frame, objects[o]);
        });
      },
      [&] { occluders = place_occluders(scene, sheets, frame, objects); },
      [&] {
        view = view_theta(scene, frame);
        if (options.resolution > 0) return;
        view_scale = options.eq4 ? farthest_depth(scene, frame) : entry_theta(scene, frame);
      });
  table.hidden_ = std::move(occluders.hidden);
  table.hidden_of_face_ = std::move(occluders.of_face);
  table.corner_start_ = std::move(occluders.corner_start);
  table.corners_ = std::move(occluders.corners);
  table.across_ = std::move(occluders.across);
  table.theta_ = quantize(scene, frame, objects, view, view_scale, options);
  for (const ObjectLoops& o : objects) {
    table.loop_stats_.ridge_edges += double(o.ridges.size());
    table.loop_stats_.loops += double(o.loops.size());
    for (const RidgeEdgeLoop& loop : o.loops) table.loop_stats_.open_loops += !loop.closed;
  }
  // Steps 1.5-1.6: one loop at a time, the loops of all objects in parallel, in order of
  // their least phi, so that each entry's pairs arrive nearly sorted (step 1.7): a walk
  // starts where an RE rises through the slice, on the loop's side of smaller phi (its far
  // sheet lies towards larger phi). The walks from the light's axis come first.
  std::vector<LoopWork> work;
  const std::vector<char> paper = paper_paired(objects, sheets, options.paper_pairing);
  for (std::uint32_t o = 0; o < objects.size(); ++o) {
    if (paper[o] && !objects[o].loops.empty()) {
      const auto least = std::ranges::min_element(objects[o].loop_phi);
      work.push_back({*least, o, 0, true});
      continue;
    }
    for (std::uint32_t l = 0; l < objects[o].loops.size(); ++l) {
      work.push_back({objects[o].loop_phi[l], o, l});
    }
    for (const std::uint32_t f : objects[o].axis_faces) work.push_back({-kInf, o, ~f});
  }
  const EntryRays rays(table.theta_, frame.point_light());
  std::vector<ThetaSlice> slices(table.theta_.resolution);
  tbb::parallel_invoke(
      [&] {
        std::sort(work.begin(), work.end(), [](const LoopWork& a, const LoopWork& b) {
          return std::tie(a.phi, a.object, a.loop) < std::tie(b.phi, b.object, b.loop);
        });
      },
      [&] {
        tbb::parallel_for(0, table.theta_.resolution, [&](int k) {
          slices[k] = ThetaSlice::at(table.theta_.centre(k), rays.centre(k), frame.point_light(),
                                     std::uint32_t(k));
        });
      });
  // Fixed chunks of that order, each into its own list: the lists in chunk order keep the
  // loops' order in every entry whichever thread sliced them.
  const std::size_t per_chunk = (work.size() + kChunks - 1) / kChunks;
  std::vector<std::vector<EntryPair>>& lists = storage.lists;
  lists.resize(kChunks);
  for (std::vector<EntryPair>& list : lists) list.clear();
  tbb::enumerable_thread_specific<SliceScratch> scratch;
  tbb::enumerable_thread_specific<PairingStats> pairing;
  tbb::parallel_for(std::size_t(0), kChunks, [&](std::size_t c) {
    SliceScratch& local = scratch.local();
    for (std::size_t i = c * per_chunk; i < std::min(work.size(), (c + 1) * per_chunk); ++i) {
      const std::uint32_t o = work[i].object, l = work[i].loop;
      const ObjectLoops& loops = objects[o];
      const SlicedMesh m{scene.objects[o].mesh, sheets[o], loops.local, loops.theta,
                         loops.hidden_id};
      if (work[i].whole_object) {
        pair_re_loops(m, loops.ridges, loops.loops, table.theta_, slices, local, lists[c],
                      pairing.local(), options.walk_fallback);
      } else if (l < loops.loops.size()) {
        slice_loop(m, loops.ridges, loops.loops[l], table.theta_, slices, local, lists[c]);
      } else {
        slice_from_axis(m, ~l, slices, local, lists[c]);
      }
    }
  });
  if (options.paper_pairing) {
    for (const char p : paper) (p ? table.pairing_.paper_objects : table.pairing_.walked_objects)++;
    pairing.combine_each([&](const PairingStats& s) {
      table.pairing_.re_pairs += double(s.re_pairs);
      table.pairing_.fallbacks += double(s.fallbacks);
      table.pairing_.vrepips += double(s.vrepips);
    });
  }
  table.entries_.pairs = std::move(storage.unsorted);
  table.fill_entries(lists);
  // Step 1.7: sort each entry by phi; Sec. 10: saturate.
  table.entries_.wide_count.assign(table.theta_.resolution, 0);
  std::vector<std::uint32_t> kept(table.theta_.resolution);
  std::vector<DepthForm> forms(options.saturated ? table.hidden_.size() : 0);
  tbb::parallel_for(std::size_t(0), forms.size(), [&](std::size_t i) {
    forms[i] = DepthForm::of(table.hidden_[i].plane, frame.point_light());
  });
  tbb::enumerable_thread_specific<SortScratch> sort_scratch;
  tbb::parallel_for(tbb::blocked_range<int>(0, table.theta_.resolution),
                    [&](const tbb::blocked_range<int>& entries) {
                      SortScratch& local = sort_scratch.local();
                      for (int k = entries.begin(); k < entries.end(); ++k) {
                        std::optional<Saturation> saturation;
                        if (!forms.empty()) saturation.emplace(forms, rays, k, frame.point_light());
                        kept[k] = table.sort_entry(k, saturation ? &*saturation : nullptr, local);
                      }
                    });
  storage.unsorted = table.compact(kept, std::move(storage.kept));
  // Blocks answer where entries are narrow on screen, near a light inside the scene, whose
  // RE loops go all around it (the variable resolution of Sec. 11.2, coarse where the answer
  // holds); elsewhere runs rarely outlast their entry lit.
  if (std::ranges::any_of(objects,
                          [](const ObjectLoops& o) { return o.wraps || !o.axis_faces.empty(); })) {
    table.fill_blocks();
  }
  return table;
}

void AngularTable::fill_entries(std::span<const std::vector<EntryPair>> lists) {
  // Count per list and entry, then every list scatters into its own slots, in parallel.
  const std::size_t r = std::size_t(theta_.resolution);
  std::vector<std::vector<std::uint32_t>> slot(lists.size(), std::vector<std::uint32_t>(r, 0));
  tbb::parallel_for(std::size_t(0), lists.size(), [&](std::size_t l) {
    for (const EntryPair& it : lists[l]) ++slot[l][it.entry];
  });
  entries_.start.assign(r + 1, 0);
  std::uint32_t total = 0;
  for (std::size_t k = 0; k < r; ++k) {
    entries_.start[k] = total;
    for (std::vector<std::uint32_t>& counts : slot) {
      const std::uint32_t n = counts[k];
      counts[k] = total;
      total += n;
    }
  }
  entries_.start[r] = total;
  entries_.pairs.resize(total);
  tbb::parallel_for(std::size_t(0), lists.size(), [&](std::size_t l) {
    for (const EntryPair& it : lists[l]) {
      entries_.pairs[slot[l][it.entry]++] = {it.phi_begin, it.phi_end, 0, it.hidden};
    }
  });
}

std::uint32_t AngularTable::sort_entry(int k, Saturation* saturation, SortScratch& scratch) {
  const std::span<AngularPair> entry(entries_.pairs.data() + entries_.start[k],
                                     entries_.pairs.data() + entries_.start[k + 1]);
  if (entry.empty()) return 0;
  const std::span<const AngularPair> sorted = scratch.sort(entry);  // step 1.7
  // Sec. 10 drops only pairs within a kept one, and never the first: the kept pairs have the
  // extent of all.
  const auto [kept, wide] = split_wide(sorted, entry, scratch.pairs, [&](const AngularPair& pair) {
    if (!saturation) return true;
    if (saturation->covers(pair)) return false;
    saturation->keep(pair);
    return true;
  });
  entries_.wide_count[k] = wide;
  return kept;
}

std::vector<AngularPair> AngularTable::compact(const std::vector<std::uint32_t>& kept,
                                               std::vector<AngularPair> pairs) {
  std::vector<std::uint32_t> start(kept.size() + 1, 0);
  for (std::size_t k = 0; k < kept.size(); ++k) start[k + 1] = start[k] + kept[k];
  pairs.resize(start.back());
  tbb::parallel_for(std::size_t(0), kept.size(), [&](std::size_t k) {
    std::copy_n(entries_.pairs.begin() + entries_.start[k], kept[k], pairs.begin() + start[k]);
  });
  saturated_ = entries_.pairs.size() - pairs.size();
  std::swap(entries_.pairs, pairs);
  entries_.start = std::move(start);
  return pairs;
}

void AngularTable::fill_blocks() {
  const int r = theta_.resolution, count = (r + kBlockEntries - 1) / kBlockEntries;
  std::vector<std::vector<AngularPair>> lists(static_cast<std::size_t>(count));
  blocks_.wide_count.assign(std::size_t(count), 0);
  tbb::enumerable_thread_specific<BlockScratch> scratch;
  tbb::parallel_for(0, count, [&](int b) {
    BlockScratch& local = scratch.local();
    if (local.block.size() != hidden_.size()) {
      local.block.assign(hidden_.size(), -1);
      local.slot.resize(hidden_.size());
    }
    // The entries of a block lie together in entries_.pairs.
    const int first = b * kBlockEntries, last = std::min(r, first + kBlockEntries);
    const std::span<const AngularPair> entries(entries_.pairs.data() + entries_.start[first],
                                               entries_.pairs.data() + entries_.start[last]);
    std::vector<AngularPair>& list = lists[std::size_t(b)];
    blocks_.wide_count[std::size_t(b)] = span_faces(entries, b, local, list);
  });
  blocks_.start.assign(std::size_t(count) + 1, 0);
  for (std::size_t b = 0; b < lists.size(); ++b) {
    blocks_.start[b + 1] = blocks_.start[b] + std::uint32_t(lists[b].size());
  }
  blocks_.pairs.resize(blocks_.start.back());
  tbb::parallel_for(std::size_t(0), lists.size(), [&](std::size_t b) {
    std::copy(lists[b].begin(), lists[b].end(), blocks_.pairs.begin() + blocks_.start[b]);
  });
}

}  // namespace shadowkit::angular
