#include "shadow_generator.h"

#include <algorithm>
#include <cmath>

namespace shadowkit::svbsp {
namespace {

// Distance of the light from a face plane; for a directional light, the cosine.
double light_side(const Plane& plane, const Light& light) {
  return light.type == Light::Type::point ? plane.distance(light.position)
                                          : -dot(plane.normal, light.direction);
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

LightFragments generate_shadows(const SceneBsp& bsp, const Scene& scene, const Light& light) {
  const double size = std::max(1.0, scene.bounds().diagonal());
  const double reach = light.type == Light::Type::point
                           ? size + length(light.position - scene.bounds().center())
                           : size;
  const double eps = SceneBsp::kRelativeTolerance * reach;
  // Hazard: one tolerance for "the light is in the face's plane", as for every plane test.
  const double in_plane = light.type == Light::Type::point ? eps : SceneBsp::kRelativeTolerance;
  SvbspTree tree(light, eps);
  LightFragments result;
  std::vector<Fragment>& out = result.fragments;
  bsp.front_to_back(light, [&](std::span<const ConvexPolygon> coplanar) {
    // Pieces of one plane cannot shadow one another, but where two of them overlap, the
    // first one's volume would hold the second: classify all, then enlarge.
    const bool together = coplanar.size() > 1;
    const std::size_t group = out.size();
    for (const ConvexPolygon& piece : coplanar) {
      const std::size_t first = out.size();
      if (std::abs(light_side(scene.face_plane(piece.face), light)) <= in_plane) {
        out.push_back({piece, false});  // Fig. 3: the light is in its plane
        continue;
      }
      ++result.light_facing;
      if (together)
        tree.classify(piece, out);
      else
        tree.determine_shadow(piece, out);
      merge_if_uniform(piece, first, out);
    }
    if (!together) return;
    for (std::size_t i = group; i < out.size(); ++i) {
      if (out[i].lit) tree.enlarge(out[i].polygon);
    }
  });
  result.svbsp_nodes = tree.node_count();
  result.svbsp_bytes = tree.memory_bytes();
  return result;
}

}  // namespace shadowkit::svbsp
