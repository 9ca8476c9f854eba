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

namespace {

// Edge \p e as a contour edge, into \p out if it is one. Crow: each face faces the light or
// not; a face in the light's plane casts no volume at all.
void add_if_contour(const Mesh& mesh, std::uint32_t e, const Light& light,
                    std::vector<ContourEdge>& out) {
  const MeshEdge& edge = mesh.edges[e];
  const Vec3 a = mesh.vertices[edge.v0], b = mesh.vertices[edge.v1];
  const Vec3 normal = cross(b - a, away_from_light(a, light));
  int weight = 0;
  for (std::uint32_t u = edge.first_use; u < edge.first_use + edge.use_count; ++u) {
    const EdgeUse& use = mesh.edge_uses[u];
    if (light_side(mesh.planes[use.face], light) != 0) weight += face_side(mesh, edge, use, normal);
  }
  if (weight > 0) out.push_back({e, edge.v0, edge.v1, weight});
  if (weight < 0) out.push_back({e, edge.v1, edge.v0, -weight});
}

}  // namespace

std::vector<ContourEdge> find_contour_edges(const Mesh& mesh, const Light& light) {
  std::vector<ContourEdge> contour;
  for (std::uint32_t e = 0; e < mesh.edges.size(); ++e) add_if_contour(mesh, e, light, contour);
  return contour;
}

void find_contour_edges(const Mesh& mesh, std::span<const std::uint32_t> faces, const Light& light,
                        std::vector<ContourEdge>& out) {
  thread_local std::vector<std::uint32_t> edges;
  edges.clear();
  for (std::uint32_t f : faces) {
    for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
      edges.push_back(mesh.corner_edge[c]);
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  out.clear();
  for (std::uint32_t e : edges) add_if_contour(mesh, e, light, out);
}

std::vector<ContourLoop> chain_contour_loops(std::span<const ContourEdge> edges) {
  return chain_edge_loops(edges);
}

}  // namespace shadowkit::volume
