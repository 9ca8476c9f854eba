#include "ridge_edges.h"

#include <algorithm>
#include <unordered_set>

#include "shadowkit/core/parallel_runs.h"
#include "shadowkit/methods/shadow_method.h"

namespace shadowkit::angular {
namespace {

// HRE when a vertex of the hidden face \p h off the edge lies on the light's side of the
// visible face \p v's plane: the hidden face is then nearer the light.
bool is_hidden_ridge(const Mesh& mesh, const MeshEdge& edge, std::uint32_t v, std::uint32_t h) {
  for (std::uint32_t k = 0; k < mesh.face_size(h); ++k) {
    const std::uint32_t p = mesh.face_vertex(h, k);
    if (p == edge.v0 || p == edge.v1) continue;
    return mesh.planes[v].distance(mesh.vertices[p]) > 0;
  }
  return false;
}

// Whether a ridge edge between a visible and a hidden face is an HRE; false elsewhere.
bool hidden_ridge(const Mesh& mesh, const FarSheets& sheets, const MeshEdge& edge) {
  if (edge.use_count != 2) return false;
  const std::uint32_t a = mesh.edge_uses[edge.first_use].face;
  const std::uint32_t b = mesh.edge_uses[edge.first_use + 1].face;
  if (sheets.side[a] * sheets.side[b] >= 0) return false;
  return sheets.side[a] > 0 ? is_hidden_ridge(mesh, edge, a, b) : is_hidden_ridge(mesh, edge, b, a);
}

}  // namespace

FarSheets far_sheets(const Mesh& mesh, const Light& light, bool solid) {
  FarSheets s;
  s.solid = solid;
  s.side.reserve(mesh.face_count());
  for (const Plane& plane : mesh.planes) {
    const double d = light_side(plane, light);
    s.side.push_back(static_cast<signed char>(d > 0 ? 1 : d < 0 ? -1 : 0));
  }
  return s;
}

std::int64_t sheet_neighbour(const Mesh& mesh, const FarSheets& sheets, std::uint32_t f,
                             std::uint32_t e) {
  const MeshEdge& edge = mesh.edges[e];
  if (edge.use_count != 2) return -1;
  const EdgeUse& a = mesh.edge_uses[edge.first_use];
  const EdgeUse& b = mesh.edge_uses[edge.first_use + 1];
  if (!sheets.occludes(a.face) || !sheets.occludes(b.face)) return -1;
  const int weight =
      (a.forward ? 1 : -1) * sheets.side[a.face] + (b.forward ? 1 : -1) * sheets.side[b.face];
  if (weight != 0) return -1;
  return a.face == f ? b.face : a.face;
}

bool one_solid(const Mesh& mesh) {
  return mesh.closed() && mesh.consistently_oriented();
}

std::vector<RidgeEdge> find_ridge_edges(const Mesh& mesh, const FarSheets& sheets) {
  // In parallel over the faces of a large object.
  std::vector<RidgeEdge> ridges;
  append_in_runs(mesh.face_count(), 4096, ridges, [&](std::size_t i, std::vector<RidgeEdge>& list) {
    const auto f = std::uint32_t(i);
    if (!sheets.occludes(f)) return;
    const std::uint32_t n = mesh.face_size(f);
    for (std::uint32_t k = 0; k < n; ++k) {
      // The corner's edge bounds the face's far sheet.
      const std::uint32_t e = mesh.corner_edge[mesh.face_start[f] + k];
      if (sheet_neighbour(mesh, sheets, f, e) >= 0) continue;
      // The face walks its corners counter-clockwise about its normal; the far sheet's
      // normal is the face's when the light is behind it.
      std::uint32_t a = mesh.face_vertex(f, k), b = mesh.face_vertex(f, (k + 1) % n);
      if (sheets.side[f] > 0) std::swap(a, b);
      list.push_back({e, a, b, f, hidden_ridge(mesh, sheets, mesh.edges[e])});
    }
  });
  return ridges;
}

std::vector<RidgeEdgeLoop> chain_ridge_edge_loops(std::span<const RidgeEdge> edges) {
  return chain_edge_loops(edges);
}

std::vector<std::uint32_t> hidden_edges_at_loops(const Mesh& mesh, const FarSheets& sheets,
                                                 std::span<const RidgeEdge> edges) {
  std::unordered_set<std::uint32_t> on_loop;
  for (const RidgeEdge& re : edges) on_loop.insert(re.from), on_loop.insert(re.to);
  std::vector<std::uint32_t> hidden;
  for (std::uint32_t e = 0; e < mesh.edges.size(); ++e) {
    const MeshEdge& edge = mesh.edges[e];
    if (!on_loop.count(edge.v0) && !on_loop.count(edge.v1)) continue;
    const std::uint32_t f = mesh.edge_uses[edge.first_use].face;
    if (sheets.occludes(f) && sheet_neighbour(mesh, sheets, f, e) >= 0) hidden.push_back(e);
  }
  return hidden;
}

}  // namespace shadowkit::angular
