#include "contour_edges.h"

#include <algorithm>

#include "shadowkit/core/parallel_runs.h"

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

// Sorts \p ids and drops repeats: marked over the span of their values where it is not much
// longer than their count (a part of a mesh numbered together: the knot's 1.7M corners),
// sorted where it is (a few edges scattered over a large mesh).
void sort_unique(std::vector<std::uint32_t>& ids) {
  if (ids.empty()) return;
  const auto [lo, hi] = std::minmax_element(ids.begin(), ids.end());
  const std::uint32_t first = *lo, span = *hi - *lo + 1;
  if (span > 8 * ids.size() + 64) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return;
  }
  std::vector<char> used(span, 0);
  for (const std::uint32_t id : ids) used[id - first] = 1;
  ids.clear();
  for (std::uint32_t i = 0; i < span; ++i) {
    if (used[i]) ids.push_back(first + i);
  }
}

}  // namespace

std::vector<ContourEdge> find_contour_edges(const Mesh& mesh, const Light& light) {
  std::vector<ContourEdge> contour;
  for (std::uint32_t e = 0; e < mesh.edges.size(); ++e) add_if_contour(mesh, e, light, contour);
  return contour;
}

void find_contour_edges(const Mesh& mesh, std::span<const std::uint32_t> faces, const Light& light,
                        std::vector<ContourEdge>& out) {
  thread_local std::vector<std::uint32_t> buffer;
  // A reference, so that the tasks below read this thread's buffer, not their own.
  std::vector<std::uint32_t>& edges = buffer;
  edges.clear();
  for (std::uint32_t f : faces) {
    for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
      edges.push_back(mesh.corner_edge[c]);
    }
  }
  sort_unique(edges);
  out.clear();
  // In parallel on a large part (the knot is one).
  append_in_runs(edges.size(), std::size_t(1) << 15, out,
                 [&](std::size_t i, std::vector<ContourEdge>& list) {
                   add_if_contour(mesh, edges[i], light, list);
                 });
}

std::vector<ContourLoop> chain_contour_loops(std::span<const ContourEdge> edges) {
  return chain_edge_loops(edges);
}

}  // namespace shadowkit::volume
