#include "ridge_edges.h"

#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <cstdlib>
#include <unordered_set>

namespace shadowkit {
namespace {

// The thin-solid weight of an edge (see RidgeEdge).
int sheet_weight(const Mesh& mesh, const MeshEdge& edge, const std::vector<char>& visible) {
  int w = 0;
  for (std::uint32_t u = edge.first_use; u < edge.first_use + edge.use_count; ++u) {
    const EdgeUse& use = mesh.edge_uses[u];
    w += (use.forward ? 1 : -1) * (visible[use.face] ? 1 : -1);
  }
  return w;
}

// HRE when a vertex of the hidden face off the edge lies on the light's side of the visible
// face's plane: the hidden face is then nearer the light.
bool is_hidden_ridge(const Mesh& mesh, const MeshEdge& edge, const std::vector<char>& visible) {
  std::int64_t v = -1, h = -1;
  for (std::uint32_t u = edge.first_use; u < edge.first_use + edge.use_count; ++u) {
    const std::uint32_t f = mesh.edge_uses[u].face;
    (visible[f] ? v : h) = f;
  }
  if (v < 0 || h < 0) return false;  // a boundary edge: both sheets of one face
  for (std::uint32_t k = 0; k < mesh.face_size(h); ++k) {
    const std::uint32_t p = mesh.face_vertex(h, k);
    if (p == edge.v0 || p == edge.v1) continue;
    return mesh.planes[v].distance(mesh.vertices[p]) > 0;
  }
  return false;
}

}  // namespace

std::vector<char> visible_faces(const Mesh& mesh, const Light& light) {
  std::vector<char> visible(mesh.face_count());
  for (std::size_t f = 0; f < visible.size(); ++f)
    visible[f] = light_side(mesh.planes[f], light) > 0;
  return visible;
}

bool one_solid(const Mesh& mesh) {
  return mesh.closed() && mesh.consistently_oriented();
}

std::vector<RidgeEdge> find_ridge_edges(const Mesh& mesh, const Light& light) {
  const std::vector<char> visible = visible_faces(mesh, light);
  const int per_ridge = one_solid(mesh) ? 2 : 1;  // a solid's RE has weight 2: one RE
  std::vector<RidgeEdge> ridges;
  for (std::uint32_t e = 0; e < mesh.edges.size(); ++e) {
    const MeshEdge& edge = mesh.edges[e];
    const int w = sheet_weight(mesh, edge, visible);
    if (w == 0) continue;
    const RidgeEdge re{e, w > 0 ? edge.v0 : edge.v1, w > 0 ? edge.v1 : edge.v0,
                       is_hidden_ridge(mesh, edge, visible)};
    for (int i = 0; i < std::abs(w) / per_ridge; ++i) ridges.push_back(re);
  }
  return ridges;
}

std::vector<RidgeEdgeLoop> chain_ridge_edge_loops(std::span<const RidgeEdge> edges) {
  return chain_edge_loops(edges);
}

std::vector<std::uint32_t> hidden_edges_at_loops(const Mesh& mesh, const Light& light,
                                                 std::span<const RidgeEdge> edges) {
  const std::vector<char> visible = visible_faces(mesh, light);
  const bool solid = one_solid(mesh);
  std::unordered_set<std::uint32_t> on_loop;
  for (const RidgeEdge& re : edges) on_loop.insert(re.from), on_loop.insert(re.to);
  std::vector<std::uint32_t> hidden;
  for (std::uint32_t e = 0; e < mesh.edges.size(); ++e) {
    const MeshEdge& edge = mesh.edges[e];
    if (!on_loop.count(edge.v0) && !on_loop.count(edge.v1)) continue;
    bool all_hidden = true;
    for (std::uint32_t u = edge.first_use; u < edge.first_use + edge.use_count; ++u) {
      all_hidden = all_hidden && !visible[mesh.edge_uses[u].face];
    }
    const bool thin_hidden = edge.use_count >= 2 && sheet_weight(mesh, edge, visible) == 0;
    if (solid ? all_hidden : thin_hidden) hidden.push_back(e);
  }
  return hidden;
}

RidgeEdgeStats ridge_edge_stats(const Scene& scene, const Light& light) {
  tbb::combinable<RidgeEdgeStats> counts;
  tbb::parallel_for(std::size_t(0), scene.objects.size(), [&](std::size_t o) {
    const Mesh& mesh = scene.objects[o].mesh;
    const std::vector<RidgeEdge> ridges = find_ridge_edges(mesh, light);
    RidgeEdgeStats& c = counts.local();
    for (const RidgeEdgeLoop& loop : chain_ridge_edge_loops(ridges)) {
      c.loops += 1;
      c.open_loops += loop.closed ? 0 : 1;
    }
    c.ridge_edges += double(ridges.size());
    c.hidden_edges += double(hidden_edges_at_loops(mesh, light, ridges).size());
  });
  return counts.combine([](RidgeEdgeStats a, const RidgeEdgeStats& b) {
    a.ridge_edges += b.ridge_edges, a.loops += b.loops;
    a.open_loops += b.open_loops, a.hidden_edges += b.hidden_edges;
    return a;
  });
}

}  // namespace shadowkit
