// The control mesh as OpenSubdiv topology, its checks, and Lai & Cheng's one-step rule (§3).
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <algorithm>
#include <cstdio>
#include <unordered_set>

#include "shadowkit/core/error.h"
#include "subdivision_impl.h"

namespace shadowkit::subdivision {
namespace {

std::string point_text(Vec3 p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.9g, %.9g, %.9g)", p.x, p.y, p.z);
  return text;
}

// OpenSubdiv flags rather than rejects what it cannot subdivide: edges with more than two
// faces, or two faces that walk an edge the same way, and vertices whose faces form no
// single fan.
void check_manifold(const Far::TopologyLevel& level, std::span<const Vec3> positions,
                    const std::string& name) {
  for (int e = 0; e < level.GetNumEdges(); ++e) {
    if (!level.IsEdgeNonManifold(e)) continue;
    const Far::ConstIndexArray ends = level.GetEdgeVertices(e);
    throw InputError(name, "the control mesh is not manifold at the edge from " +
                               point_text(positions[ends[0]]) + " to " +
                               point_text(positions[ends[1]]) +
                               " (more than two faces, or faces of opposite orientation)");
  }
  for (int v = 0; v < level.GetNumVertices(); ++v) {
    if (level.IsVertexNonManifold(v)) {
      throw InputError(name, "the control mesh is not manifold at the vertex " +
                                 point_text(positions[v]) + " (its faces form no single fan)");
    }
  }
}

bool has_repeated_edge(const Far::TopologyLevel& level) {
  std::unordered_set<std::uint64_t> ends;
  for (int e = 0; e < level.GetNumEdges(); ++e) {
    const Far::ConstIndexArray v = level.GetEdgeVertices(e);
    const auto lo = std::uint64_t(std::min(v[0], v[1])), hi = std::uint64_t(std::max(v[0], v[1]));
    if (!ends.insert(lo << 32 | hi).second) return true;
  }
  return false;
}

// §3: every face a quad with at most one extraordinary vertex (OpenSubdiv's sense: not of
// regular valence; a sharp corner on one face is regular). A repeated edge (two edges with
// the same ends, as in a 2 x 2 torus) also asks for the step, so that corner ids identify
// a patch edge; one Catmull-Clark step always gives such a mesh.
bool needs_one_step(const Far::TopologyLevel& level) {
  for (int f = 0; f < level.GetNumFaces(); ++f) {
    const Far::ConstIndexArray corners = level.GetFaceVertices(f);
    if (corners.size() != 4) return true;
    const auto irregular = std::count_if(corners.begin(), corners.end(),
                                         [&](int v) { return !level.IsVertexValenceRegular(v); });
    if (irregular > 1) return true;
  }
  return has_repeated_edge(level);
}

QuadMesh quads_of(const Far::TopologyLevel& level, std::vector<Vec3> positions) {
  QuadMesh mesh{std::move(positions), {}};
  for (int f = 0; f < level.GetNumFaces(); ++f) {
    const Far::ConstIndexArray v = level.GetFaceVertices(f);
    SHADOWKIT_CHECK(v.size() == 4);
    mesh.quads.push_back(
        {std::uint32_t(v[0]), std::uint32_t(v[1]), std::uint32_t(v[2]), std::uint32_t(v[3])});
  }
  return mesh;
}

void check_faces(const PolygonSoup& control, const std::string& name) {
  if (control.face_count() == 0) throw InputError(name, "the control mesh has no faces");
  for (std::size_t f = 0; f < control.face_count(); ++f) {
    std::vector<std::uint32_t> loop(control.indices.begin() + control.face_start[f],
                                    control.indices.begin() + control.face_start[f + 1]);
    std::sort(loop.begin(), loop.end());
    if (loop.size() < 3 || std::adjacent_find(loop.begin(), loop.end()) != loop.end()) {
      throw InputError(name, "control face " + std::to_string(f + 1) +
                                 " is degenerate (fewer than three distinct vertices, or a "
                                 "vertex used twice)");
    }
  }
}

}  // namespace

std::unique_ptr<Far::TopologyRefiner> make_refiner(int vertex_count,
                                                   std::span<const int> face_sizes,
                                                   std::span<const int> face_vertices) {
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  OpenSubdiv::Sdc::Options rules;
  rules.SetVtxBoundaryInterpolation(OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  Far::TopologyDescriptor descriptor;
  descriptor.numVertices = vertex_count;
  descriptor.numFaces = int(face_sizes.size());
  descriptor.numVertsPerFace = face_sizes.data();
  descriptor.vertIndicesPerFace = face_vertices.data();
  return std::unique_ptr<Far::TopologyRefiner>(
      Factory::Create(descriptor, Factory::Options(OpenSubdiv::Sdc::SCHEME_CATMARK, rules)));
}

QuadMesh quad_base(const PolygonSoup& control, const std::string& name) {
  check_faces(control, name);
  std::vector<int> sizes, vertices(control.indices.begin(), control.indices.end());
  for (std::size_t f = 0; f < control.face_count(); ++f) {
    sizes.push_back(int(control.face_start[f + 1] - control.face_start[f]));
  }
  const std::unique_ptr<Far::TopologyRefiner> refiner =
      make_refiner(int(control.positions.size()), sizes, vertices);
  if (!refiner) throw InputError(name, "OpenSubdiv rejects the control mesh's topology");
  check_manifold(refiner->GetLevel(0), control.positions, name);
  if (!needs_one_step(refiner->GetLevel(0)))
    return quads_of(refiner->GetLevel(0), control.positions);

  refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(1));
  std::vector<Point> coarse, fine(std::size_t(refiner->GetLevel(1).GetNumVertices()));
  for (const Vec3& p : control.positions) coarse.push_back({p});
  const Point* src = coarse.data();
  Point* dst = fine.data();
  Far::PrimvarRefinerReal<double>(*refiner).Interpolate(1, src, dst);
  std::vector<Vec3> positions;
  for (const Point& p : fine) positions.push_back(p.p);
  return quads_of(refiner->GetLevel(1), std::move(positions));
}

}  // namespace shadowkit::subdivision
