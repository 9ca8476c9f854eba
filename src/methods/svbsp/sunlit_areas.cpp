// The lit area of every face for a sequence of directional lights (the sun study): one
// scene BSP tree (§3), one SVBSP tree per light (§4), areas summed as fragments come.
#include <numeric>
#include <span>

#include "fragment_raster.h"
#include "scene_bsp.h"
#include "shadow_generator.h"
#include "shadowkit/methods/svbsp.h"

namespace shadowkit::svbsp {
namespace {

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t f) {
  while (parent[f] != f) f = parent[f] = parent[parent[f]];
  return f;
}

// Per global face: 1 when the face bounds a solid and its normal points out of it, so that
// a face turned from the light is shadowed by the solid's own faces turned toward it (a ray
// entering the solid there leaves it through one of those). Such faces neither receive light
// nor cast a shadow that the solid does not, and the SVBSP tree need not see them. The
// solids: the connected parts of closed, consistently oriented meshes whose signed volume is
// positive (a part turned inside out, or a cavity's lining, keeps every face).
std::vector<char> outward_solid_faces(const Scene& scene) {
  std::vector<char> outward(scene.face_count(), 0);
  for (const SceneObject& object : scene.objects) {
    const Mesh& mesh = object.mesh;
    if (!mesh.closed() || !mesh.consistently_oriented()) continue;
    std::vector<std::uint32_t> part(mesh.face_count());
    std::iota(part.begin(), part.end(), 0u);
    for (const MeshEdge& edge : mesh.edges) {
      const std::uint32_t a = find_root(part, mesh.edge_uses[edge.first_use].face);
      const std::uint32_t b = find_root(part, mesh.edge_uses[edge.first_use + 1].face);
      part[a] = b;
    }
    // The divergence theorem: volume = sum of area * (normal . a point of the face) / 3.
    std::vector<double> volume(mesh.face_count(), 0.0);
    for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
      const Vec3 corner = mesh.vertices[mesh.face_vertex(f, 0)];
      volume[find_root(part, f)] += mesh.areas[f] * dot(mesh.planes[f].normal, corner) / 3;
    }
    for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
      outward[object.first_face + f] = volume[find_root(part, f)] > 0;
    }
  }
  return outward;
}

}  // namespace

SunlitAreas::SunlitAreas(const Scene& scene)
    : scene_(scene),
      bsp_(std::make_unique<const SceneBsp>(SceneBsp::build(scene))),
      outward_solid_faces_(outward_solid_faces(scene)) {}

SunlitAreas::~SunlitAreas() = default;

std::vector<double> SunlitAreas::lit_areas(Vec3 toward_light) const {
  return filter(toward_light, nullptr);
}

std::vector<double> SunlitAreas::lit_areas(Vec3 toward_light, const VisibleSurfaceBuffer& surfaces,
                                           ShadowMask& mask) const {
  std::vector<Fragment> lit_fragments;
  std::vector<double> areas = filter(toward_light, &lit_fragments);
  shade_fragments(scene_, Light::directional(-toward_light), lit_fragments, surfaces, false, mask);
  return areas;
}

std::vector<double> SunlitAreas::filter(Vec3 toward_light, std::vector<Fragment>* lit_out) const {
  const Light light = Light::directional(-toward_light);
  std::vector<double> lit(scene_.face_count(), 0.0);
  ShadowGenerator generator(scene_, light);
  const auto turned_away = [&](const ConvexPolygon& piece) {
    return outward_solid_faces_[piece.face] &&
           dot(scene_.face_plane(piece.face).normal, toward_light) < 0;
  };
  // Fragments are summed node by node and dropped: only the tree must grow (§4), not the
  // list of every fragment the fragments command keeps.
  std::vector<Fragment> fragments;
  std::vector<ConvexPolygon> kept;
  bsp_->front_to_back(light, [&](std::span<const ConvexPolygon> coplanar) {
    fragments.clear();
    // A node's pieces share a plane but may face either way along it.
    const auto away = std::count_if(coplanar.begin(), coplanar.end(), turned_away);
    if (away == std::ssize(coplanar)) return;
    if (away == 0) {
      generator.process(coplanar, fragments);
    } else {
      kept.clear();
      std::copy_if(coplanar.begin(), coplanar.end(), std::back_inserter(kept),
                   [&](const ConvexPolygon& p) { return !turned_away(p); });
      generator.process(kept, fragments);
    }
    for (Fragment& f : fragments) {
      if (!f.lit) continue;
      lit[f.polygon.face] += area(f.polygon);
      if (lit_out) lit_out->push_back(std::move(f));
    }
  });
  // The working frame is the world scaled by frame.scale (a power of two: exact).
  const double scale2 = scene_.frame.scale * scene_.frame.scale;
  for (double& a : lit) a *= scale2;
  return lit;
}

}  // namespace shadowkit::svbsp
