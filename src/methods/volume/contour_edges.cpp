#include "contour_edges.h"

#include <algorithm>

namespace shadowkit::volume {
namespace {

int sign(double v) {
  return (v > 0) - (v < 0);
}

}  // namespace

int face_side(const Mesh& mesh, const MeshEdge& edge, const EdgeUse& use, Vec3 polygon_normal) {
  // The face's inward direction in its own plane (left of the edge as the face walks it),
  // against the polygon's normal. Exact for non-convex faces too.
  const Vec3 walk = mesh.vertices[edge.v1] - mesh.vertices[edge.v0];
  const Vec3 inward = cross(mesh.planes[use.face].normal, use.forward ? walk : -walk);
  return sign(dot(polygon_normal, inward));
}

Vec3 away_from_light(Vec3 v, const Light& light) {
  return light.type == Light::Type::point ? v - light.position : light.direction;
}

std::vector<ContourEdge> find_contour_edges(const Mesh& mesh, const Light& light) {
  // Crow: mark each face as facing the light or not; a face in the light's plane casts no
  // volume at all.
  std::vector<char> casts(mesh.face_count());
  for (std::size_t f = 0; f < casts.size(); ++f) casts[f] = light_side(mesh.planes[f], light) != 0;

  std::vector<ContourEdge> contour;
  for (std::uint32_t e = 0; e < mesh.edges.size(); ++e) {
    const MeshEdge& edge = mesh.edges[e];
    const Vec3 a = mesh.vertices[edge.v0], b = mesh.vertices[edge.v1];
    const Vec3 normal = cross(b - a, away_from_light(a, light));
    int weight = 0;
    for (std::uint32_t u = edge.first_use; u < edge.first_use + edge.use_count; ++u) {
      const EdgeUse& use = mesh.edge_uses[u];
      if (casts[use.face]) weight += face_side(mesh, edge, use, normal);
    }
    if (weight > 0) contour.push_back({e, edge.v0, edge.v1, weight});
    if (weight < 0) contour.push_back({e, edge.v1, edge.v0, -weight});
  }
  return contour;
}

std::vector<ContourLoop> chain_contour_loops(std::span<const ContourEdge> edges) {
  return chain_edge_loops(edges);
}

}  // namespace shadowkit::volume
