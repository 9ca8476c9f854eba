#include "shadowkit/scene/mesh.h"

#include <absl/container/flat_hash_map.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <utility>

#include "shadowkit/core/error.h"
#include "shadowkit/scene/triangulate.h"

namespace shadowkit {

void PolygonSoup::add_face(std::initializer_list<std::uint32_t> face) {
  indices.insert(indices.end(), face.begin(), face.end());
  face_start.push_back(std::uint32_t(indices.size()));
}

void PolygonSoup::add_face(const std::vector<std::uint32_t>& face) {
  indices.insert(indices.end(), face.begin(), face.end());
  face_start.push_back(std::uint32_t(indices.size()));
}

void PolygonSoup::append(const PolygonSoup& other) {
  const auto base = std::uint32_t(positions.size());
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  for (std::size_t f = 0; f < other.face_count(); ++f) {
    for (std::uint32_t k = other.face_start[f]; k < other.face_start[f + 1]; ++k) {
      indices.push_back(base + other.indices[k]);
    }
    face_start.push_back(std::uint32_t(indices.size()));
  }
}

namespace {

// Tolerances are relative to the mesh's size so that tiny and huge models behave alike.
constexpr double kWeldTolerance = 1e-9;    // of the bounding-box diagonal
constexpr double kDegenerateArea = 1e-14;  // of the face's squared diameter

struct CellKey {
  std::int64_t x, y, z;
  bool operator==(const CellKey&) const = default;
  template <typename H>
  friend H AbslHashValue(H h, const CellKey& k) {
    return H::combine(std::move(h), k.x, k.y, k.z);
  }
};

// Merges positions closer than `tolerance` (in every coordinate) on a hash grid whose cells
// are twice the tolerance wide. Only cells the point's tolerance box reaches can hold a match:
// two per axis, searched in the same order as the 27 around it would be. Cells count from the
// box's low corner: keys stay below diagonal / cell = 5e8 wherever the mesh sits.
std::vector<std::uint32_t> weld(std::span<const Vec3> positions, const Bounds3& box,
                                double tolerance, std::vector<Vec3>& welded) {
  constexpr std::uint32_t kNone = std::uint32_t(-1);
  const double cell = tolerance > 0 ? 2 * tolerance : 1.0;    // one point: any cell will do
  absl::flat_hash_map<CellKey, std::uint32_t> first_in_cell;  // the cell's latest welded vertex
  first_in_cell.reserve(positions.size());
  std::vector<std::uint32_t> next_in_cell;  // per welded vertex: the one before it in its cell
  std::vector<std::uint32_t> remap(positions.size());
  auto key_of = [&](Vec3 p) {
    const Vec3 q = (p - box.lo) / cell;
    return CellKey{std::int64_t(q.x), std::int64_t(q.y), std::int64_t(q.z)};
  };
  // The earliest welded vertex of a cell within tolerance of p, as the cell's list kept it.
  auto match_in = [&](const CellKey& k, Vec3 p) {
    const auto it = first_in_cell.find(k);
    std::uint32_t found = kNone;
    for (std::uint32_t w = it == first_in_cell.end() ? kNone : it->second; w != kNone;
         w = next_in_cell[w]) {
      if (max_abs_component(welded[w] - p) <= tolerance) found = w;
    }
    return found;
  };
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec3 p = positions[i];
    const CellKey lo = key_of(p - Vec3{tolerance, tolerance, tolerance});
    const CellKey hi = key_of(p + Vec3{tolerance, tolerance, tolerance});
    std::uint32_t found = kNone;
    for (std::int64_t x = lo.x; x <= hi.x && found == kNone; ++x)
      for (std::int64_t y = lo.y; y <= hi.y && found == kNone; ++y)
        for (std::int64_t z = lo.z; z <= hi.z && found == kNone; ++z)
          found = match_in({x, y, z}, p);
    if (found == kNone) {
      found = std::uint32_t(welded.size());
      welded.push_back(p);
      auto [it, inserted] = first_in_cell.try_emplace(key_of(p), found);
      next_in_cell.push_back(inserted ? kNone : std::exchange(it->second, found));
    }
    remap[i] = found;
  }
  return remap;
}

// Removes repeated consecutive vertices (including the wrap-around) left by welding.
void remove_repeats(std::vector<std::uint32_t>& loop) {
  loop.erase(std::unique(loop.begin(), loop.end()), loop.end());
  while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
}

double diameter(std::span<const Vec3> p, std::span<const std::uint32_t> loop) {
  Bounds3 b;
  for (std::uint32_t v : loop) b.add(p[v]);
  return b.diagonal();
}

bool is_planar(std::span<const Vec3> p, std::span<const std::uint32_t> loop, const Plane& plane,
               double size) {
  return std::all_of(loop.begin(), loop.end(), [&](std::uint32_t v) {
    return std::abs(plane.distance(p[v])) <= kPlanarTolerance * size;
  });
}

Plane plane_of(std::span<const Vec3> p, std::span<const std::uint32_t> loop, Vec3 newell) {
  Vec3 centroid;
  for (std::uint32_t v : loop) centroid += p[v];
  centroid = centroid / double(loop.size());
  const Vec3 n = normalize(newell);
  return {n, -dot(n, centroid)};
}

// The polygon turns the same way about \p normal at every corner.
bool turns_one_way(std::span<const Vec3> positions, std::span<const std::uint32_t> loop,
                   Vec3 normal) {
  const std::size_t n = loop.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 a = positions[loop[k]], b = positions[loop[(k + 1) % n]];
    const Vec3 c = positions[loop[(k + 2) % n]];
    if (dot(cross(b - a, c - b), normal) < 0) return false;
  }
  return true;
}

}  // namespace

PolygonSoup welded_soup(const PolygonSoup& soup) {
  Bounds3 box;
  for (const Vec3& p : soup.positions) box.add(p);
  std::vector<Vec3> merged;
  const std::vector<std::uint32_t> remap =
      weld(soup.positions, box, kWeldTolerance * box.diagonal(), merged);
  PolygonSoup out;
  std::vector<std::vector<std::uint32_t>> loops;
  std::vector<bool> used(merged.size(), false);
  for (std::size_t f = 0; f < soup.face_count(); ++f) {
    std::vector<std::uint32_t> loop;
    for (std::uint32_t k = soup.face_start[f]; k < soup.face_start[f + 1]; ++k) {
      loop.push_back(remap[soup.indices[k]]);
      used[loop.back()] = true;
    }
    remove_repeats(loop);
    loops.push_back(std::move(loop));
  }
  // Used positions keep their order: a soup without duplicates keeps its numbering.
  std::vector<std::uint32_t> compact(merged.size());
  for (std::size_t v = 0; v < merged.size(); ++v) {
    compact[v] = std::uint32_t(out.positions.size());
    if (used[v]) out.positions.push_back(merged[v]);
  }
  for (std::vector<std::uint32_t>& loop : loops) {
    for (std::uint32_t& v : loop) v = compact[v];
    out.add_face(loop);
  }
  return out;
}

Mesh Mesh::build(const PolygonSoup& soup, const std::string& name, const Context& ctx) {
  Bounds3 box;
  for (const Vec3& p : soup.positions) box.add(p);
  Mesh mesh;
  const std::vector<std::uint32_t> remap =
      weld(soup.positions, box, kWeldTolerance * box.diagonal(), mesh.vertices);

  std::size_t degenerate = 0, split = 0;
  mesh.face_vertices.reserve(soup.indices.size());
  mesh.face_start.reserve(soup.face_start.size());
  mesh.planes.reserve(soup.face_count());
  mesh.areas.reserve(soup.face_count());
  mesh.convex.reserve(soup.face_count());
  mesh.input_faces.reserve(soup.face_count());
  std::vector<std::uint32_t> loop;
  auto add_face = [&mesh](std::span<const std::uint32_t> face, const Plane& plane, double area) {
    mesh.face_vertices.insert(mesh.face_vertices.end(), face.begin(), face.end());
    mesh.face_start.push_back(std::uint32_t(mesh.face_vertices.size()));
    mesh.planes.push_back(plane);
    mesh.areas.push_back(area);
    mesh.convex.push_back(turns_one_way(mesh.vertices, face, plane.normal));
  };
  for (std::size_t f = 0; f < soup.face_count(); ++f) {
    loop.clear();
    for (std::uint32_t k = soup.face_start[f]; k < soup.face_start[f + 1]; ++k) {
      loop.push_back(remap[soup.indices[k]]);
    }
    remove_repeats(loop);
    const double size = loop.size() >= 3 ? diameter(mesh.vertices, loop) : 0.0;
    const Vec3 newell = loop.size() >= 3 ? newell_normal(mesh.vertices, loop) : Vec3{};
    const double area = 0.5 * length(newell);
    if (loop.size() < 3 || !(area > kDegenerateArea * size * size)) {
      ++degenerate;
      continue;
    }
    const Plane plane = plane_of(mesh.vertices, loop, newell);
    if (is_planar(mesh.vertices, loop, plane, size)) {
      add_face(loop, plane, area);
      mesh.input_faces.push_back(std::uint32_t(f));
      continue;
    }
    // A warped polygon has no single plane: keep its surface as triangles.
    ++split;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    triangulate_polygon(mesh.vertices, loop, plane.normal, triangles);
    for (const auto& t : triangles) {
      const Vec3 tn = newell_normal(mesh.vertices, t);
      const double tsize = diameter(mesh.vertices, t);
      if (0.5 * length(tn) > kDegenerateArea * tsize * tsize) {
        add_face(t, plane_of(mesh.vertices, t, tn), 0.5 * length(tn));
        mesh.input_faces.push_back(std::uint32_t(f));
      }
    }
  }
  if (degenerate > 0) {
    ctx.warning(name + ": dropped " + std::to_string(degenerate) +
                " degenerate face(s) (fewer than 3 distinct vertices or zero area)");
  }
  mesh.split_faces_ = split;
  mesh.dropped_faces_ = degenerate;
  mesh.input_face_count_ = soup.face_count();
  mesh.build_adjacency();
  return mesh;
}

// Edges are numbered in the order of their first corner. Corners are grouped by their edge's
// lower vertex (a counting sort) and each group sorted by the upper one: the corners of an edge
// then lie together, the first of them leading, whatever a vertex's degree.
void Mesh::build_adjacency() {
  const std::size_t corners = face_vertices.size();
  std::vector<std::uint32_t> lower(corners), upper(corners);
  std::vector<std::uint32_t> group_start(vertices.size() + 1, 0);
  for (std::size_t f = 0; f < face_count(); ++f) {
    const std::uint32_t n = face_size(f);
    for (std::uint32_t k = 0; k < n; ++k) {
      const std::uint32_t a = face_vertex(f, k), b = face_vertex(f, (k + 1) % n);
      lower[face_start[f] + k] = std::min(a, b);
      upper[face_start[f] + k] = std::max(a, b);
      ++group_start[std::min(a, b) + 1];
    }
  }
  for (std::size_t v = 0; v < vertices.size(); ++v) group_start[v + 1] += group_start[v];
  std::vector<std::uint64_t> grouped(corners);  // (upper << 32 | corner) per lower vertex
  {
    std::vector<std::uint32_t> fill(group_start.begin(), group_start.end() - 1);
    for (std::size_t c = 0; c < corners; ++c) {
      grouped[fill[lower[c]]++] = std::uint64_t(upper[c]) << 32 | c;
    }
  }
  std::vector<std::uint32_t> leader(corners);  // the first corner on each corner's edge
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    const auto begin = grouped.begin() + group_start[v], end = grouped.begin() + group_start[v + 1];
    std::sort(begin, end);
    std::uint32_t first = 0;
    for (auto it = begin; it != end; ++it) {
      if (it == begin || (*it >> 32) != (*(it - 1) >> 32)) first = std::uint32_t(*it);
      leader[std::uint32_t(*it)] = first;
    }
  }
  corner_edge.resize(corners);
  std::vector<std::uint32_t> uses_per_edge;
  for (std::size_t c = 0; c < corners; ++c) {
    if (leader[c] == c) {
      corner_edge[c] = std::uint32_t(edges.size());
      edges.push_back({lower[c], upper[c], 0, 0});
      uses_per_edge.push_back(0);
    } else {
      corner_edge[c] = corner_edge[leader[c]];
    }
    ++uses_per_edge[corner_edge[c]];
  }
  std::uint32_t offset = 0;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    edges[e].first_use = offset;
    offset += uses_per_edge[e];
  }
  edge_uses.resize(offset);
  for (std::size_t f = 0; f < face_count(); ++f) {
    const std::uint32_t n = face_size(f);
    for (std::uint32_t k = 0; k < n; ++k) {
      MeshEdge& e = edges[corner_edge[face_start[f] + k]];
      edge_uses[e.first_use + e.use_count++] = {std::uint32_t(f), face_vertex(f, k) == e.v0};
    }
  }
  for (const MeshEdge& e : edges) {
    if (e.use_count == 1) ++boundary_edges_;
    if (e.use_count > 2) ++nonmanifold_edges_;
    if (e.use_count == 2 && edge_uses[e.first_use].forward == edge_uses[e.first_use + 1].forward) {
      consistently_oriented_ = false;
    }
  }
}

Bounds3 Mesh::bounds() const {
  Bounds3 b;
  for (const Vec3& p : vertices) b.add(p);
  return b;
}

}  // namespace shadowkit
