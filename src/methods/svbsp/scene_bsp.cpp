#include "scene_bsp.h"

#include <tbb/concurrent_vector.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numeric>
#include <optional>
#include <tuple>
#include <utility>

#include "convex_solids.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/scene/mesh.h"
#include "shadowkit/scene/triangulate.h"

namespace shadowkit::svbsp {
namespace {

// Candidate planes tried per node: enough to avoid bad roots, few enough for O(n log n).
constexpr std::size_t kCandidates = 8;
// Polygons the candidates are scored on: past this many, an evenly spread sample, so that
// choosing costs the same at every node and the build is the partitioning's O(n log n).
constexpr std::size_t kSample = 128;
// Subtrees of at least this many polygons are built in parallel: they are independent.
constexpr std::size_t kParallelGrain = 2048;
// No polygon defines the splitter.
constexpr std::uint32_t kNoPolygon = ~std::uint32_t(0);

using Ids = std::vector<std::uint32_t>;

bool is_convex(const Mesh& mesh, std::size_t f) {
  const std::uint32_t n = mesh.face_size(f);
  const Vec3 normal = mesh.planes[f].normal;
  for (std::uint32_t k = 0; k < n; ++k) {
    const Vec3 a = mesh.vertices[mesh.face_vertex(f, k)];
    const Vec3 b = mesh.vertices[mesh.face_vertex(f, (k + 1) % n)];
    const Vec3 c = mesh.vertices[mesh.face_vertex(f, (k + 2) % n)];
    if (dot(cross(b - a, c - b), normal) < 0) return false;
  }
  return true;
}

// A candidate's cost: each split adds a polygon, imbalance adds depth. Splits weigh more,
// but not infinitely: around a convex mesh every face plane splits nothing and leaves all
// other faces on one side, a chain n deep built in O(n^2).
constexpr std::size_t kSplitWeight = 8;

struct PlaneScore {
  std::size_t splits = 0, front = 0, back = 0;
  std::size_t cost() const {
    return kSplitWeight * splits + (front > back ? front - back : back - front);
  }
};

using Sample = std::vector<const ConvexPolygon*>;

PlaneScore score(const Sample& polygons, const Plane& plane, double eps) {
  PlaneScore s;
  for (const ConvexPolygon* p : polygons) {
    const PlaneSides sides = classify(*p, plane, eps);
    s.splits += sides.spanning();
    s.front += sides.positive;
    s.back += sides.negative;
  }
  return s;
}

// The plane across \p axis that a sweep over the polygons' extents along it finds cheapest,
// and its score from the extents: it holds no polygon, and in a field of objects it runs
// through the gaps between them.
std::pair<Plane, PlaneScore> axis_plane(const Sample& polygons, int axis) {
  std::vector<double> lo, hi;
  lo.reserve(polygons.size());
  hi.reserve(polygons.size());
  for (const ConvexPolygon* p : polygons) {
    double a = p->vertices[0][axis], b = a;
    for (const Vec3& v : p->vertices) a = std::min(a, v[axis]), b = std::max(b, v[axis]);
    lo.push_back(a);
    hi.push_back(b);
  }
  std::sort(lo.begin(), lo.end());
  std::sort(hi.begin(), hi.end());
  // Positions: at each polygon's far end, and past it halfway to the next start (in the gap
  // if there is one). At the end, polygons that end there lie behind and those that start
  // there in front: a grid's faces (a terrain, a building's walls) meet at shared
  // coordinates, where a plane splits none of them. Split: the others, counted on both sides
  // as score() does. c grows with the far end, so the counts come from pointers that only
  // move forward.
  const std::size_t n = polygons.size();
  double best = 0;
  PlaneScore best_score{n, 0, 0};
  const auto consider = [&](double c, std::size_t back, std::size_t front) {
    const std::size_t splits = n - std::min(n, back + front);
    const PlaneScore s{splits, front + splits, back + splits};
    if (s.cost() < best_score.cost()) best = c, best_score = s;
  };
  std::size_t next = 0, back = 0, ending = 0, starting = 0;
  for (const double end : hi) {
    while (ending < n && hi[ending] <= end) ++ending;
    while (starting < n && lo[starting] < end) ++starting;
    consider(end, ending, n - starting);
    while (next < n && lo[next] <= end) ++next;
    if (next == n) break;
    const double c = 0.5 * (end + lo[next]);
    while (back < n && hi[back] < c) ++back;
    consider(c, back, n - next);  // no start lies in (end, c)
  }
  Plane plane;
  plane.normal[axis] = 1;
  plane.d = -best;
  return {plane, best_score};
}

// The cheapest of the three axis planes that leave a whole polygon on each side (holding
// no polygon, a splitter must, or a half would not be smaller).
std::optional<std::pair<Plane, PlaneScore>> best_axis_plane(const Sample& polygons) {
  std::optional<std::pair<Plane, PlaneScore>> best;
  for (int axis = 0; axis < 3; ++axis) {
    const auto candidate = axis_plane(polygons, axis);
    const PlaneScore& s = candidate.second;
    if (s.front > s.splits && s.back > s.splits && (!best || s.cost() < best->second.cost())) {
      best = candidate;
    }
  }
  return best;
}

// Appends the convex pieces of face \p face of \p scene to \p out.
void append_convex_pieces(const Scene& scene, std::uint32_t face, std::vector<ConvexPolygon>& out) {
  const SceneObject& object = scene.objects[scene.object_of_face(face)];
  const Mesh& mesh = object.mesh;
  const std::size_t f = face - object.first_face;
  const std::span<const std::uint32_t> loop(&mesh.face_vertices[mesh.face_start[f]],
                                            mesh.face_size(f));
  if (is_convex(mesh, f)) {
    ConvexPolygon::Corners v;
    for (std::uint32_t i : loop) v.push_back(mesh.vertices[i]);
    out.push_back(make_polygon(v, face));
    return;
  }
  std::vector<std::array<std::uint32_t, 3>> triangles;
  triangulate_polygon(mesh.vertices, loop, mesh.planes[f].normal, triangles);
  for (const auto& t : triangles) {
    out.push_back(
        make_polygon({mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]}, face));
  }
}

}  // namespace

// Chunks of faces in parallel, then moved into place in parallel: at half a million faces
// one pass in face order costs more than the tree's top levels.
std::vector<ConvexPolygon> convex_faces(const Scene& scene) {
  constexpr std::uint32_t kChunk = 4096;
  const auto faces = std::uint32_t(scene.face_count());
  std::vector<std::vector<ConvexPolygon>> chunks((faces + kChunk - 1) / kChunk);
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t c) {
    const std::uint32_t end = std::min<std::uint32_t>(faces, std::uint32_t(c + 1) * kChunk);
    for (auto face = std::uint32_t(c * kChunk); face < end; ++face) {
      append_convex_pieces(scene, face, chunks[c]);
    }
  });
  std::vector<std::size_t> start(chunks.size() + 1, 0);
  for (std::size_t c = 0; c < chunks.size(); ++c) start[c + 1] = start[c] + chunks[c].size();
  std::vector<ConvexPolygon> out(start.back());
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t c) {
    std::move(chunks[c].begin(), chunks[c].end(), out.begin() + std::ptrdiff_t(start[c]));
  });
  return out;
}

// A node under construction: subtrees are built in parallel into drafts, which are then
// laid out in one fixed order.
struct SceneBsp::Draft {
  Plane plane;
  Ids here;  ///< pieces in the plane (or the solid's faces), builder ids
  std::int32_t solid = -1;
  std::vector<Plane> cluster;  ///< a cluster leaf: each piece's plane, turned (Builder::cluster)
  std::unique_ptr<Draft> front, back;
};

// Builds drafts over the input polygons and the pieces that splitting appends to a
// concurrent vector, so that ids and references stay valid while other subtrees add pieces.
// An id with kSolidTag names a convex solid kept whole: its faces, and its corners for the
// plane tests.
class SceneBsp::Builder {
 public:
  Builder(const Scene& scene, double eps, std::vector<ConvexPolygon> inputs,
          const ConvexSolids* solids, bool clusters)
      : scene_(scene),
        eps_(eps),
        planar_reach_(kPlanarTolerance * std::max(1.0, scene.bounds().diagonal())),
        clusters_(clusters),
        inputs_(std::move(inputs)) {
    if (solids) solids_.resize(solids->size());
    for (std::uint32_t id = 0; id < inputs_.size(); ++id) {
      const std::int32_t s = solids ? solids->solid_of(polygon(id).face) : -1;
      if (s < 0) {
        items_.push_back(id);
        continue;
      }
      Solid& solid = solids_[std::size_t(s)];
      solid.faces.push_back(id);
      for (const Vec3& v : polygon(id).vertices) solid.corners.vertices.push_back(v);
    }
    for (std::uint32_t s = 0; s < solids_.size(); ++s) {
      items_.push_back(kSolidTag | s);
      distinct_corners(solids_[s].corners.vertices);
    }
  }

  std::size_t size() const { return inputs_.size() + cut_.size(); }
  ConvexPolygon& polygon(std::uint32_t id) {
    return id < inputs_.size() ? inputs_[id] : cut_[id - inputs_.size()];
  }
  const ConvexPolygon& polygon(std::uint32_t id) const {
    return id < inputs_.size() ? inputs_[id] : cut_[id - inputs_.size()];
  }
  /// Every input polygon, a convex solid's faces as the solid.
  const Ids& items() const { return items_; }

  std::unique_ptr<Draft> build(Ids ids) {
    if (ids.empty()) return nullptr;
    auto draft = std::make_unique<Draft>();
    if (ids.size() == 1 && is_solid(ids[0])) {  // a leaf: the solid whole
      draft->solid = std::int32_t(ids[0] & ~kSolidTag);
      draft->here = faces_of(ids[0]);
      return draft;
    }
    if (std::optional<std::vector<Plane>> planes = cluster(ids)) {  // a leaf: no splits
      draft->here = std::move(ids);
      draft->cluster = std::move(*planes);
      return draft;
    }
    auto splitter = choose_splitter(ids);
    if (!splitter) {  // nothing separates the solids: their faces go on alone
      ids = dissolved(ids);
      splitter = choose_splitter(ids);
    }
    draft->plane = splitter->first;
    const bool parallel = ids.size() >= kParallelGrain;
    Ids front, back;
    partition(std::move(ids), splitter->second, *draft, front, back);
    if (parallel) {
      tbb::parallel_invoke([&] { draft->front = build(std::move(front)); },
                           [&] { draft->back = build(std::move(back)); });
    } else {
      draft->front = build(std::move(front));
      draft->back = build(std::move(back));
    }
    return draft;
  }

 private:
  static constexpr std::uint32_t kSolidTag = 1u << 31;
  static bool is_solid(std::uint32_t id) { return (id & kSolidTag) != 0; }

  /// \brief A convex solid kept whole: its faces' ids and all their corners.
  struct Solid {
    Ids faces;
    ConvexPolygon corners;
  };

  // Each corner of a solid once: its faces share them (a cube's 24 face corners are 8), and
  // every plane test of the solid reads them all.
  static void distinct_corners(ConvexPolygon::Corners& corners) {
    const auto less = [](const Vec3& a, const Vec3& b) {
      return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    };
    std::sort(corners.begin(), corners.end(), less);
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  }

  const ConvexPolygon& shape(std::uint32_t id) const {
    return is_solid(id) ? solids_[id & ~kSolidTag].corners : polygon(id);
  }
  const Ids& faces_of(std::uint32_t solid_id) const { return solids_[solid_id & ~kSolidTag].faces; }

  // \p ids with every solid replaced by its faces.
  Ids dissolved(const Ids& ids) const {
    Ids out;
    for (const std::uint32_t id : ids) {
      if (is_solid(id))
        out.insert(out.end(), faces_of(id).begin(), faces_of(id).end());
      else
        out.push_back(id);
    }
    return out;
  }

  // The planes of \p ids' polygons, all turned one way, when each polygon lies behind (or
  // within eps of) every other's: a patch of a convex surface, or of a concave one turned
  // over. None can hide another from a light in front of the hidden one's plane, nor from
  // one behind both planes (SceneBsp::visit), so the patch needs no split. Two polygons
  // of different faces in one plane could overlap, where the first one's volume would
  // hold the second: no cluster. Checked pairwise, so only up to kSample polygons.
  std::optional<std::vector<Plane>> cluster(const Ids& ids) const {
    if (!clusters_ || ids.size() < 2 || ids.size() > kSample ||
        std::any_of(ids.begin(), ids.end(), is_solid)) {
      return std::nullopt;
    }
    bool front = false, back = false;
    for (const std::uint32_t i : ids) {
      const Plane& plane = scene_.face_plane(polygon(i).face);
      for (const std::uint32_t j : ids) {
        if (j == i) continue;
        const PlaneSides sides = classify(polygon(j), plane, eps_);
        if (sides.on() && polygon(j).face != polygon(i).face) return std::nullopt;
        front = front || sides.positive;
        back = back || sides.negative;
        if (front && back) return std::nullopt;
      }
    }
    std::vector<Plane> planes;
    for (const std::uint32_t i : ids) {
      const Plane& plane = scene_.face_plane(polygon(i).face);
      planes.push_back(front ? Plane{-plane.normal, -plane.d} : plane);
    }
    return planes;
  }

  // Up to kSample of \p ids, evenly spread.
  static Ids sample(const Ids& ids) {
    const std::size_t n = std::min(ids.size(), kSample);
    Ids out(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = ids[i * ids.size() / n];
    return out;
  }

  // The splitter of \p ids and the polygon defining it (kNoPolygon for none). A plane across
  // an axis that splits nothing of the sample runs through a gap: taken at once. Else the
  // face plane or axis plane of lowest cost. None: only solids, and no plane parts them.
  std::optional<std::pair<Plane, std::uint32_t>> choose_splitter(const Ids& ids) {
    const Ids sampled = sample(ids);
    Sample polygons;
    for (const std::uint32_t id : sampled) polygons.push_back(&shape(id));
    const bool solids = std::any_of(sampled.begin(), sampled.end(), is_solid);
    std::optional<std::pair<Plane, PlaneScore>> across;
    if (polygons.size() > kCandidates || solids) across = best_axis_plane(polygons);
    if (across && across->second.splits == 0) return std::pair(across->first, kNoPolygon);
    const std::optional<FacePlane> face = best_face_plane(sampled, polygons);
    if (across && (!face || across->second.cost() < face->cost)) {
      return std::pair(across->first, kNoPolygon);
    }
    if (!face) return std::nullopt;
    return std::pair(face->plane, face->polygon);
  }

  /// \brief A face plane candidate: the plane, its polygon (kNoPolygon for a solid's face,
  /// which stays with its solid), its cost.
  struct FacePlane {
    Plane plane;
    std::uint32_t polygon = kNoPolygon;
    std::size_t cost = 0;
  };

  // Candidates: face planes of a few items spread over the sample (every face of a solid)
  // and of the largest polygon (the one most planes would split). A solid's face plane
  // leaves the solid behind it, so it parts the items only with one in front.
  std::optional<FacePlane> best_face_plane(const Ids& sampled, const Sample& polygons) const {
    const std::size_t step = std::max<std::size_t>(1, polygons.size() / kCandidates);
    std::vector<std::size_t> candidates;
    for (std::size_t c = 0; c < polygons.size() && c / step < kCandidates; c += step) {
      candidates.push_back(c);
    }
    if (const auto big = largest(sampled, polygons)) candidates.push_back(*big);
    std::optional<FacePlane> best;
    const auto consider = [&](const Plane& plane, std::uint32_t polygon) {
      const PlaneScore s = score(polygons, plane, eps_);
      if (polygon == kNoPolygon && s.front == 0) return;
      if (!best || s.cost() < best->cost) best = FacePlane{plane, polygon, s.cost()};
    };
    for (const std::size_t c : candidates) {
      if (!is_solid(sampled[c])) {
        consider(scene_.face_plane(polygons[c]->face), sampled[c]);
        continue;
      }
      for (const std::uint32_t id : faces_of(sampled[c])) {
        consider(scene_.face_plane(polygon(id).face), kNoPolygon);
      }
    }
    return best;
  }

  // The largest polygon of the sample that is not a solid, if any.
  std::optional<std::size_t> largest(const Ids& sampled, const Sample& polygons) const {
    std::optional<std::size_t> best;
    double best_area = -1;
    for (std::size_t i = 0; i < polygons.size(); ++i) {
      if (is_solid(sampled[i])) continue;
      const double a = area(*polygons[i]);
      if (a > best_area) best = i, best_area = a;
    }
    return best;
  }

  // Pieces in the plane stay at the node, the others go front or back, split if need be;
  // a solid the plane crosses goes on as its faces.
  void partition(Ids ids, std::uint32_t best, Draft& draft, Ids& front, Ids& back) {
    ConvexPolygon neg, pos;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const std::uint32_t id = ids[i];
      const PlaneSides sides = classify(shape(id), draft.plane, eps_);
      if (is_solid(id)) {
        if (sides.spanning()) {
          ids.insert(ids.end(), faces_of(id).begin(), faces_of(id).end());
        } else {
          (sides.positive ? front : back).push_back(id);
        }
      } else if (id == best || sides.on() || in_plane(polygon(id), draft.plane)) {
        draft.here.push_back(id);
      } else if (!sides.spanning()) {
        (sides.positive ? front : back).push_back(id);
      } else {
        split_polygon(polygon(id), draft.plane, eps_, std::nullopt, neg, pos);
        back.push_back(add(std::move(neg)));
        front.push_back(add(std::move(pos)));
      }
    }
  }

  // Whether piece \p p's face lies in \p plane: its plane is that plane, either way round. The
  // corners of a face that is planar only within the scene's tolerance lie off its own plane,
  // and a coincident copy of it would otherwise be cut by it and shadowed by it.
  bool in_plane(const ConvexPolygon& p, const Plane& plane) const {
    // Most pieces lie far from the plane: their corners tell without the face's plane.
    for (const Vec3& v : p.vertices) {
      if (std::abs(plane.distance(v)) > planar_reach_) return false;
    }
    return same_plane(scene_.face_plane(p.face), plane);
  }

  std::uint32_t add(ConvexPolygon&& p) {
    return std::uint32_t(inputs_.size() + std::size_t(cut_.push_back(std::move(p)) - cut_.begin()));
  }

  const Scene& scene_;
  double eps_;
  double planar_reach_;  ///< how far a face's corners may lie off its plane (kPlanarTolerance)
  bool clusters_;
  std::vector<ConvexPolygon> inputs_;
  tbb::concurrent_vector<ConvexPolygon> cut_;  ///< pieces of splits, ids from inputs_.size()
  std::vector<Solid> solids_;
  Ids items_;
};

SceneBsp SceneBsp::build(const Scene& scene, const ConvexSolids* solids, bool clusters) {
  SceneBsp bsp;
  bsp.eps_ = kRelativeTolerance * std::max(1.0, scene.bounds().diagonal());
  Builder builder(scene, bsp.eps_, convex_faces(scene), solids, clusters);
  const std::size_t inputs = builder.size();
  const std::unique_ptr<Draft> root = builder.build(builder.items());
  // The pieces in the order the nodes are laid out, then moved there in parallel.
  std::vector<std::uint32_t> order;
  order.reserve(builder.size());
  if (root) bsp.root_ = bsp.lay_out(*root, order, 1);
  bsp.pieces_.resize(order.size());
  tbb::parallel_for(std::size_t(0), order.size(),
                    [&](std::size_t k) { bsp.pieces_[k] = std::move(builder.polygon(order[k])); });
  bsp.splits_ = bsp.pieces_.size() - inputs;
  return bsp;
}

std::int32_t SceneBsp::lay_out(const Draft& draft, std::vector<std::uint32_t>& order,
                               std::size_t depth) {
  depth_ = std::max(depth_, depth);
  const std::int32_t index = std::int32_t(nodes_.size());
  const std::int32_t cluster = draft.cluster.empty() ? -1 : std::int32_t(cluster_planes_.size());
  nodes_.push_back({draft.plane, std::uint32_t(order.size()), std::uint32_t(draft.here.size()), -1,
                    -1, draft.solid, cluster});
  cluster_planes_.insert(cluster_planes_.end(), draft.cluster.begin(), draft.cluster.end());
  order.insert(order.end(), draft.here.begin(), draft.here.end());
  solids_ += draft.solid >= 0;
  if (draft.front) nodes_[index].front = lay_out(*draft.front, order, depth + 1);
  if (draft.back) nodes_[index].back = lay_out(*draft.back, order, depth + 1);
  return index;
}

void SceneBsp::front_to_back(const Light& light, const std::function<void(NodePieces)>& fn) const {
  visit(root_, light, fn);
}

void SceneBsp::visit(std::int32_t node, const Light& light,
                     const std::function<void(NodePieces)>& fn) const {
  if (node < 0) return;
  const Node& n = nodes_[node];
  const std::span<const ConvexPolygon> pieces(pieces_.data() + n.first, n.count);
  if (n.solid >= 0) {  // a leaf
    fn({pieces, n.solid});
    return;
  }
  if (n.cluster >= 0) return visit_cluster(n, light, fn);
  // The light's half-space first: nothing behind the plane can hide what is in front of it.
  const double side = light_side(n.plane, light);
  const std::int32_t near = side >= 0 ? n.front : n.back;
  const std::int32_t far = side >= 0 ? n.back : n.front;
  visit(near, light, fn);
  fn({pieces});
  visit(far, light, fn);
}

void SceneBsp::visit_cluster(const Node& n, const Light& light,
                             const std::function<void(NodePieces)>& fn) const {
  // For a piece to hide another in a cluster, the light must be behind the hidden one's
  // plane: the pieces whose plane the light is in front of hide nothing of one another and
  // come first; behind the planes of two, neither hides the other, since the ray would
  // leave the first plane's back to meet the second behind it.
  const std::span<const Plane> planes(cluster_planes_.data() + n.cluster, n.count);
  for (const bool turned_to_light : {true, false}) {
    for (std::uint32_t k = 0; k < n.count; ++k) {
      if ((light_side(planes[k], light) > 0) == turned_to_light) {
        fn({{&pieces_[n.first + k], 1}});
      }
    }
  }
}

std::size_t SceneBsp::memory_bytes() const {
  std::size_t bytes = nodes_.capacity() * sizeof(Node) + cluster_planes_.capacity() * sizeof(Plane);
  for (const ConvexPolygon& p : pieces_) {
    bytes += sizeof(p) + heap_bytes(p);
  }
  return bytes;
}

}  // namespace shadowkit::svbsp
