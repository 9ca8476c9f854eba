#include "shadow_generator.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "shadowkit/methods/shadow_method.h"

namespace shadowkit::svbsp {
namespace {

// The distance within which a point counts as on a shadow plane, relative to how far the
// planes reach across the scene.
double plane_tolerance(const Scene& scene, const Light& light) {
  const double size = std::max(1.0, scene.bounds().diagonal());
  const double reach = light.type == Light::Type::point
                           ? size + length(light.position - scene.bounds().center())
                           : size;
  return SceneBsp::kRelativeTolerance * reach;
}

// Hazard: one tolerance for "the light is in the face's plane", as for every plane test.
double in_plane_tolerance(const Scene& scene, const Light& light) {
  return light.type == Light::Type::point ? plane_tolerance(scene, light)
                                          : SceneBsp::kRelativeTolerance;
}

// §6: a piece whose fragments are all lit or all shadowed is kept whole.
void merge_if_uniform(const ConvexPolygon& piece, std::size_t first, std::vector<Fragment>& out) {
  if (out.size() - first < 2) return;
  const bool lit = out[first].lit;
  const bool uniform = std::all_of(out.begin() + std::ptrdiff_t(first), out.end(),
                                   [lit](const Fragment& f) { return f.lit == lit; });
  if (!uniform) return;
  out.resize(first);
  out.push_back({piece, lit});
}

}  // namespace

FarSide far_side_of(const OutwardSolids& solids, const Scene& scene, const Light& light) {
  return
      [&solids, &scene, light](std::uint32_t face) { return solids.far_side(scene, face, light); };
}

FrontFacing front_facing(const Scene& scene, const Light& light) {
  const double in_plane = in_plane_tolerance(scene, light);
  FrontFacing count;
  for (const SceneObject& object : scene.objects) {
    for (std::size_t f = 0; f < object.mesh.face_count(); ++f) {
      if (light_side(object.mesh.planes[f], light) <= in_plane) continue;
      ++count.polygons;
      count.edges += object.mesh.face_size(f);
    }
  }
  return count;
}

ShadowGenerator::ShadowGenerator(const Scene& scene, const Light& light, bool merge_siblings,
                                 FarSide far_side)
    : scene_(scene),
      light_(light),
      far_side_(std::move(far_side)),
      in_plane_(in_plane_tolerance(scene, light)),
      tree_(light, plane_tolerance(scene, light), merge_siblings) {}

bool ShadowGenerator::in_light_plane(const ConvexPolygon& piece) const {
  return std::abs(light_side(scene_.face_plane(piece.face), light_)) <= in_plane_;
}

void ShadowGenerator::process(std::span<const ConvexPolygon> coplanar, std::vector<Fragment>& out) {
  // Pieces of one plane cannot shadow one another, but where two of them overlap, the
  // first one's volume would hold the second: classify all, then enlarge.
  const auto far = std::count_if(coplanar.begin(), coplanar.end(),
                                 [this](const ConvexPolygon& p) { return far_side(p); });
  const bool together = std::ssize(coplanar) - far > 1;
  const std::size_t group = out.size();
  for (const ConvexPolygon& piece : coplanar) {
    const std::size_t first = out.size();
    if ((far > 0 && far_side(piece)) || in_light_plane(piece)) {
      out.push_back({piece, false});  // Fig. 3: the light is in its plane, or the far side
      continue;
    }
    ++light_facing_;
    if (together)
      tree_.classify(piece, out);
    else
      tree_.determine_shadow(piece, out);
    merge_if_uniform(piece, first, out);
  }
  if (!together) return;
  for (std::size_t i = group; i < out.size(); ++i) {
    if (out[i].lit) tree_.enlarge(out[i].polygon);
  }
}

LightFragments generate_shadows(const SceneBsp& bsp, const Scene& scene, const Light& light,
                                bool merge_siblings, const FarSide& far_side) {
  ShadowGenerator generator(scene, light, merge_siblings, far_side);
  LightFragments result;
  bsp.front_to_back(light, [&](std::span<const ConvexPolygon> coplanar) {
    generator.process(coplanar, result.fragments);
  });
  result.light_facing = generator.light_facing();
  result.svbsp_nodes = generator.tree().node_count();
  result.svbsp_bytes = generator.tree().memory_bytes();
  return result;
}

}  // namespace shadowkit::svbsp
