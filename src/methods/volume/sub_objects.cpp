#include "sub_objects.h"

#include <limits>
#include <numeric>

namespace shadowkit {
namespace {

constexpr std::uint32_t kUnnumbered = std::numeric_limits<std::uint32_t>::max();

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
      if (part == kUnnumbered) part = std::uint32_t(s.bounds.size()), s.bounds.emplace_back();
      s.of_face[object.first_face + f] = part;
      for (std::uint32_t k = 0; k < mesh.face_size(f); ++k) {
        s.bounds[part].add(mesh.vertices[mesh.face_vertex(f, k)]);
      }
    }
  }
  return s;
}

}  // namespace shadowkit
