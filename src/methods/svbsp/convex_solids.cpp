#include "convex_solids.h"

#include <algorithm>
#include <map>

#include "scene_bsp.h"

namespace shadowkit::svbsp {
namespace {

/// \brief The faces and vertices (local ids) of one outward solid of a mesh.
struct Part {
  std::vector<std::uint32_t> faces, vertices;
};

// The outward solids of \p object, by their OutwardSolids id: faces and vertices.
std::map<std::int32_t, Part> parts_of(const SceneObject& object, const OutwardSolids& outward) {
  const Mesh& mesh = object.mesh;
  std::map<std::int32_t, Part> parts;
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
    const std::int32_t s = outward.solid_of(object.first_face + f);
    if (s < 0) continue;
    Part& part = parts[s];
    part.faces.push_back(f);
    for (std::uint32_t k = 0; k < mesh.face_size(f); ++k) {
      part.vertices.push_back(mesh.face_vertex(f, k));
    }
  }
  for (auto& [s, part] : parts) {
    std::sort(part.vertices.begin(), part.vertices.end());
    part.vertices.erase(std::unique(part.vertices.begin(), part.vertices.end()),
                        part.vertices.end());
  }
  return parts;
}

// Every vertex of \p part within \p eps of, or behind, every one of its face planes.
bool convex(const Mesh& mesh, const Part& part, double eps) {
  return std::all_of(part.faces.begin(), part.faces.end(), [&](std::uint32_t f) {
    return std::all_of(part.vertices.begin(), part.vertices.end(), [&](std::uint32_t v) {
      return mesh.planes[f].distance(mesh.vertices[v]) <= eps;
    });
  });
}

}  // namespace

ConvexSolids::ConvexSolids(const Scene& scene, const OutwardSolids& outward)
    : solid_(scene.face_count(), -1) {
  // Hazard: a solid flat within the plane tolerance passes as convex; its faces are then
  // within that tolerance of one another, as every plane test allows.
  const double eps = SceneBsp::kRelativeTolerance * std::max(1.0, scene.bounds().diagonal());
  for (const SceneObject& object : scene.objects) {
    const Mesh& mesh = object.mesh;
    for (const auto& [outward_id, part] : parts_of(object, outward)) {
      if (!convex(mesh, part, eps)) continue;
      Solid solid;
      for (const std::uint32_t v : part.vertices) solid.inside += mesh.vertices[v];
      solid.inside = solid.inside / double(part.vertices.size());
      for (const std::uint32_t f : part.faces) {
        solid_[object.first_face + f] = std::int32_t(solids_.size());
      }
      solids_.push_back(std::move(solid));
    }
    // A closed solid's edges each join two of its faces.
    for (const MeshEdge& edge : mesh.edges) {
      const std::uint32_t f0 = mesh.edge_uses[edge.first_use].face;
      const std::int32_t s = solid_[object.first_face + f0];
      if (s < 0) continue;
      const std::uint32_t f1 = mesh.edge_uses[edge.first_use + 1].face;
      solids_[std::size_t(s)].edges.push_back({mesh.vertices[edge.v0],
                                               mesh.vertices[edge.v1],
                                               {object.first_face + f0, object.first_face + f1}});
    }
  }
}

std::vector<ShadowPlane> ConvexSolids::contour_planes(
    std::size_t s, const Light& light, const std::function<bool(std::uint32_t)>& facing) const {
  const Solid& solid = solids_[s];
  std::vector<ShadowPlane> planes;
  for (const Edge& e : solid.edges) {
    if (facing(e.faces[0]) == facing(e.faces[1])) continue;
    ShadowPlane plane;
    if (make_shadow_plane(light, e.a, e.b, solid.inside, plane)) planes.push_back(plane);
  }
  return planes;
}

}  // namespace shadowkit::svbsp
