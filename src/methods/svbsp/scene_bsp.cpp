#include "scene_bsp.h"

#include <algorithm>
#include <array>
#include <utility>

#include "shadowkit/scene/triangulate.h"

namespace shadowkit::svbsp {
namespace {

// Candidate planes tried per node: enough to avoid bad roots, few enough for O(n log n).
constexpr std::size_t kCandidates = 8;
// No polygon defines the splitter.
constexpr std::size_t kNoPolygon = ~std::size_t(0);

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

PlaneScore score(const std::vector<ConvexPolygon>& polygons, const Plane& plane, double eps) {
  PlaneScore s;
  for (const ConvexPolygon& p : polygons) {
    const PlaneSides sides = classify(p, plane, eps);
    s.splits += sides.spanning();
    s.front += sides.positive;
    s.back += sides.negative;
  }
  return s;
}

// The plane across the longest axis of the polygons' centroids, through their median: a
// splitter that holds no polygon but halves the set.
Plane median_plane(const std::vector<ConvexPolygon>& polygons) {
  std::vector<Vec3> centroids;
  Bounds3 box;
  for (const ConvexPolygon& p : polygons) {
    Vec3 c;
    for (const Vec3& v : p.vertices) c += v;
    centroids.push_back(c / double(p.vertices.size()));
    box.add(centroids.back());
  }
  const Vec3 e = box.extent();
  const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
  std::vector<double> coordinate;
  for (const Vec3& c : centroids) coordinate.push_back(c[axis]);
  const auto mid = coordinate.begin() + std::ptrdiff_t(coordinate.size() / 2);
  std::nth_element(coordinate.begin(), mid, coordinate.end());
  Plane plane;
  plane.normal[axis] = 1;
  plane.d = -*mid;
  return plane;
}

std::size_t largest(const std::vector<ConvexPolygon>& polygons) {
  std::size_t best = 0;
  double best_area = -1;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const double a = area(polygons[i]);
    if (a > best_area) best = i, best_area = a;
  }
  return best;
}

}  // namespace

std::vector<ConvexPolygon> convex_faces(const Scene& scene) {
  std::vector<ConvexPolygon> out;
  for (const SceneObject& object : scene.objects) {
    const Mesh& mesh = object.mesh;
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      const std::uint32_t face = object.first_face + std::uint32_t(f);
      const std::span<const std::uint32_t> loop(&mesh.face_vertices[mesh.face_start[f]],
                                                mesh.face_size(f));
      if (is_convex(mesh, f)) {
        ConvexPolygon::Corners v;
        for (std::uint32_t i : loop) v.push_back(mesh.vertices[i]);
        out.push_back(make_polygon(v, face));
        continue;
      }
      std::vector<std::array<std::uint32_t, 3>> triangles;
      triangulate_polygon(mesh.vertices, loop, mesh.planes[f].normal, triangles);
      for (const auto& t : triangles) {
        out.push_back(
            make_polygon({mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]}, face));
      }
    }
  }
  return out;
}

SceneBsp SceneBsp::build(const Scene& scene) {
  SceneBsp bsp;
  bsp.eps_ = kRelativeTolerance * std::max(1.0, scene.bounds().diagonal());
  std::vector<ConvexPolygon> polygons = convex_faces(scene);
  const std::size_t inputs = polygons.size();
  bsp.root_ = bsp.build_node(std::move(polygons), scene, 1);
  bsp.splits_ = bsp.pieces_.size() - inputs;
  return bsp;
}

std::pair<Plane, std::size_t> SceneBsp::choose_splitter(const std::vector<ConvexPolygon>& polygons,
                                                        const Scene& scene) const {
  // Candidates: face planes of a few polygons spread over the list and of the largest one
  // (the one most planes would split); past a few polygons also the median plane.
  const std::size_t step = std::max<std::size_t>(1, polygons.size() / kCandidates);
  std::vector<std::size_t> candidates;
  for (std::size_t c = 0; c < polygons.size() && c / step < kCandidates; c += step) {
    candidates.push_back(c);
  }
  candidates.push_back(largest(polygons));
  std::size_t best = candidates[0];
  Plane plane = scene.face_plane(polygons[best].face);
  std::size_t best_cost = score(polygons, plane, eps_).cost();
  for (std::size_t c : candidates) {
    const Plane candidate = scene.face_plane(polygons[c].face);
    const std::size_t cost = score(polygons, candidate, eps_).cost();
    if (cost < best_cost) best = c, plane = candidate, best_cost = cost;
  }
  if (polygons.size() > kCandidates) {
    const Plane median = median_plane(polygons);
    if (score(polygons, median, eps_).cost() < best_cost) return {median, kNoPolygon};
  }
  return {plane, best};
}

std::int32_t SceneBsp::build_node(std::vector<ConvexPolygon> polygons, const Scene& scene,
                                  std::size_t depth) {
  if (polygons.empty()) return -1;
  depth_ = std::max(depth_, depth);
  const auto [plane, best] = choose_splitter(polygons, scene);
  // Partition: pieces in the plane stay at the node, the others go front or back.
  std::vector<ConvexPolygon> front, back, here;
  ConvexPolygon neg, pos;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    ConvexPolygon& p = polygons[i];
    const PlaneSides sides = classify(p, plane, eps_);
    if (i == best || sides.on()) {
      here.push_back(std::move(p));
    } else if (!sides.spanning()) {
      (sides.positive ? front : back).push_back(std::move(p));
    } else {
      split_polygon(p, plane, eps_, false, neg, pos);
      back.push_back(std::move(neg));
      front.push_back(std::move(pos));
    }
  }
  polygons = {};
  const std::int32_t index = std::int32_t(nodes_.size());
  nodes_.push_back({plane, std::uint32_t(pieces_.size()), std::uint32_t(here.size()), -1, -1});
  for (ConvexPolygon& p : here) pieces_.push_back(std::move(p));
  const std::int32_t f = build_node(std::move(front), scene, depth + 1);
  const std::int32_t b = build_node(std::move(back), scene, depth + 1);
  nodes_[index].front = f;
  nodes_[index].back = b;
  return index;
}

void SceneBsp::front_to_back(const Light& light,
                             const std::function<void(std::span<const ConvexPolygon>)>& fn) const {
  visit(root_, light, fn);
}

void SceneBsp::visit(std::int32_t node, const Light& light,
                     const std::function<void(std::span<const ConvexPolygon>)>& fn) const {
  if (node < 0) return;
  const Node& n = nodes_[node];
  // The light's half-space first: nothing behind the plane can hide what is in front of it.
  const double side = light.type == Light::Type::point ? n.plane.distance(light.position)
                                                       : -dot(n.plane.normal, light.direction);
  const std::int32_t near = side >= 0 ? n.front : n.back;
  const std::int32_t far = side >= 0 ? n.back : n.front;
  visit(near, light, fn);
  fn({pieces_.data() + n.first, n.count});
  visit(far, light, fn);
}

std::size_t SceneBsp::memory_bytes() const {
  std::size_t bytes = nodes_.capacity() * sizeof(Node);
  for (const ConvexPolygon& p : pieces_) {
    bytes += sizeof(p) + heap_bytes(p);
  }
  return bytes;
}

}  // namespace shadowkit::svbsp
