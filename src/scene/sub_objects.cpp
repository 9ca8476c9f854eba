#include "shadowkit/scene/sub_objects.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

namespace shadowkit {
namespace {

constexpr std::uint32_t kUnnumbered = std::numeric_limits<std::uint32_t>::max();

// Whether every face's plane of sub-object \p k has all of \p points (its vertices) on one
// side. Hazard: a relative tolerance, far above the rounding of the planes.
bool faces_support(const Scene& scene, const SubObjects& s, std::size_t k,
                   std::span<const Vec3> points) {
  const Bounds3& b = s.bounds[k];
  const double tolerance = 1e-9 * std::max({b.diagonal(), length(b.lo), length(b.hi)}) + 1e-300;
  return std::all_of(s.faces(k).begin(), s.faces(k).end(), [&](std::uint32_t f) {
    const Plane& plane = scene.face_plane(f);
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec3& p : points) {
      const double d = plane.distance(p);
      lo = std::min(lo, d), hi = std::max(hi, d);
    }
    return lo >= -tolerance || hi <= tolerance;
  });
}

// Union-find over the faces of one mesh.
struct FaceSets {
  std::vector<std::uint32_t> parent;
  explicit FaceSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t f) {
    while (parent[f] != f) f = parent[f] = parent[parent[f]];
    return f;
  }
  void join(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

}  // namespace

SubObjects SubObjects::of(const Scene& scene) {
  SubObjects s;
  s.of_face.resize(scene.face_count());
  std::vector<char> closed;
  for (const SceneObject& object : scene.objects) {
    const Mesh& mesh = object.mesh;
    FaceSets sets(mesh.face_count());
    for (const MeshEdge& edge : mesh.edges) {
      for (std::uint32_t u = edge.first_use + 1; u < edge.first_use + edge.use_count; ++u) {
        sets.join(mesh.edge_uses[edge.first_use].face, mesh.edge_uses[u].face);
      }
    }
    // Number the parts in order of their first face.
    std::vector<std::uint32_t> id(mesh.face_count(), kUnnumbered);
    for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
      std::uint32_t& part = id[sets.find(f)];
      if (part == kUnnumbered) {
        part = std::uint32_t(s.bounds.size());
        s.bounds.emplace_back();
        closed.push_back(1);
      }
      s.of_face[object.first_face + f] = part;
      for (std::uint32_t k = 0; k < mesh.face_size(f); ++k) {
        s.bounds[part].add(mesh.vertices[mesh.face_vertex(f, k)]);
      }
    }
    for (const MeshEdge& edge : mesh.edges) {
      if (edge.use_count != 2) closed[id[sets.find(mesh.edge_uses[edge.first_use].face)]] = 0;
    }
  }
  // Faces per sub-object, by counting sort.
  s.face_start_.assign(s.size() + 1, 0);
  for (std::uint32_t k : s.of_face) ++s.face_start_[k + 1];
  std::partial_sum(s.face_start_.begin(), s.face_start_.end(), s.face_start_.begin());
  s.face_ids_.resize(s.of_face.size());
  std::vector<std::uint32_t> next(s.face_start_.begin(), s.face_start_.end() - 1);
  for (std::uint32_t f = 0; f < s.of_face.size(); ++f) s.face_ids_[next[s.of_face[f]]++] = f;
  // Corners: the distinct vertices of small sub-objects, the box of large ones.
  s.corner_start_.push_back(0);
  s.convex.assign(s.size(), 0);
  std::vector<Vec3> points;
  for (std::size_t k = 0; k < s.size(); ++k) {
    points.clear();
    bool large = false;  // too many vertices to list: the box stands for them
    for (std::uint32_t f : s.faces(k)) {
      const Mesh& mesh = scene.objects[scene.object_of_face(f)].mesh;
      const std::uint32_t local = scene.local_face(f);
      for (std::uint32_t c = 0; c < mesh.face_size(local); ++c) {
        points.push_back(mesh.vertices[mesh.face_vertex(local, c)]);
      }
      if (points.size() > 4 * kMaxCorners) {
        large = true;
        break;
      }
    }
    std::sort(points.begin(), points.end(),
              [](Vec3 a, Vec3 b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); });
    points.erase(std::unique(points.begin(), points.end(),
                             [](Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }),
                 points.end());
    if (large || points.size() > kMaxCorners) {
      points.clear();
      const Bounds3& b = s.bounds[k];
      for (int c = 0; c < 8; ++c) points.push_back(b.corner(c));
    } else {
      s.convex[k] = closed[k] && faces_support(scene, s, k, points);
    }
    s.corners_.insert(s.corners_.end(), points.begin(), points.end());
    s.corner_start_.push_back(std::uint32_t(s.corners_.size()));
  }
  return s;
}

}  // namespace shadowkit
