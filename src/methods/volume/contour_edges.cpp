#include "contour_edges.h"

#include <tbb/parallel_for.h>

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
  out.clear();
  if (edges.empty()) return;
  // Each edge once, in edge order: marked over the span of their ids where it is not much
  // longer than their count (a part of a mesh numbered together; the knot's 1.7M corners),
  // sorted where it is (a few edges scattered over a large mesh).
  const auto [lo, hi] = std::minmax_element(edges.begin(), edges.end());
  const std::uint32_t first = *lo, span = *hi - *lo + 1;
  if (span <= 8 * edges.size() + 64) {
    std::vector<char> used(span, 0);
    for (std::uint32_t e : edges) used[e - first] = 1;
    // Fixed runs of ids, in parallel on a large part (the knot is one), in run order.
    constexpr std::uint32_t kRun = 1 << 16;
    std::vector<std::vector<ContourEdge>> runs((span + kRun - 1) / kRun);
    const auto find_in_run = [&](std::size_t r) {
      for (std::uint32_t i = std::uint32_t(r) * kRun;
           i < std::min(span, std::uint32_t(r + 1) * kRun); ++i) {
        if (used[i]) add_if_contour(mesh, first + i, light, runs.size() == 1 ? out : runs[r]);
      }
    };
    if (runs.size() == 1) {
      find_in_run(0);
      return;
    }
    tbb::parallel_for(std::size_t(0), runs.size(), find_in_run);
    for (const std::vector<ContourEdge>& run : runs) out.insert(out.end(), run.begin(), run.end());
    return;
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (std::uint32_t e : edges) add_if_contour(mesh, e, light, out);
}

std::vector<ContourLoop> chain_contour_loops(std::span<const ContourEdge> edges) {
  return chain_edge_loops(edges);
}

}  // namespace shadowkit::volume
