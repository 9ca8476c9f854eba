#include "shadowkit/scene/outward_solids.h"

#include <numeric>

#include "shadowkit/scene/scene.h"

namespace shadowkit {
namespace {

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t f) {
  while (parent[f] != f) f = parent[f] = parent[parent[f]];
  return f;
}

// Per local face of \p mesh, its connected part: faces sharing an edge are in one part.
std::vector<std::uint32_t> connected_parts(const Mesh& mesh) {
  std::vector<std::uint32_t> part(mesh.face_count());
  std::iota(part.begin(), part.end(), 0u);
  for (const MeshEdge& edge : mesh.edges) {
    const std::uint32_t a = find_root(part, mesh.edge_uses[edge.first_use].face);
    const std::uint32_t b = find_root(part, mesh.edge_uses[edge.first_use + 1].face);
    part[a] = b;
  }
  // Path halving leaves a face's parent short of the root: name the root itself.
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f) part[f] = find_root(part, f);
  return part;
}

}  // namespace

OutwardSolids::OutwardSolids(const Scene& scene) : solid_(scene.face_count(), -1) {
  for (const SceneObject& object : scene.objects) {
    const Mesh& mesh = object.mesh;
    if (!mesh.closed() || !mesh.consistently_oriented()) continue;
    const std::vector<std::uint32_t> part = connected_parts(mesh);
    // The divergence theorem: volume = sum of area * (normal . a point of the face) / 3.
    std::vector<double> volume(mesh.face_count(), 0.0);
    std::vector<Bounds3> box(mesh.face_count());
    for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
      const Vec3 corner = mesh.vertices[mesh.face_vertex(f, 0)];
      volume[part[f]] += mesh.areas[f] * dot(mesh.planes[f].normal, corner) / 3;
      for (std::uint32_t k = 0; k < mesh.face_size(f); ++k) {
        box[part[f]].add(mesh.vertices[mesh.face_vertex(f, k)]);
      }
    }
    std::vector<std::int32_t> solid_of_part(mesh.face_count(), -1);
    for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
      const std::uint32_t p = part[f];
      if (!(volume[p] > 0)) continue;
      if (solid_of_part[p] < 0) {
        solid_of_part[p] = std::int32_t(bounds_.size());
        bounds_.push_back(box[p]);
      }
      solid_[object.first_face + f] = solid_of_part[p];
    }
  }
}

bool OutwardSolids::far_side_from(const Scene& scene, std::uint32_t face, Vec3 point) const {
  const std::int32_t solid = solid_[face];
  return solid >= 0 && turned_from(scene.face_plane(face), point) &&
         outside(std::size_t(solid), point);
}

bool OutwardSolids::outside(std::size_t s, Vec3 point) const {
  const Bounds3& box = bounds_[s];
  return point.x < box.lo.x || point.y < box.lo.y || point.z < box.lo.z || point.x > box.hi.x ||
         point.y > box.hi.y || point.z > box.hi.z;
}

bool OutwardSolids::far_side_along(const Scene& scene, std::uint32_t face, Vec3 direction) const {
  return solid_[face] >= 0 && turned_along(scene.face_plane(face), direction);
}

}  // namespace shadowkit
