// The lit area of every face for a sequence of directional lights (the sun study): one
// scene BSP tree (§3), one SVBSP tree per light (§4), areas summed as fragments come.
#include <algorithm>
#include <span>

#include "fragment_raster.h"
#include "scene_bsp.h"
#include "shadow_generator.h"
#include "shadowkit/methods/svbsp.h"

namespace shadowkit::svbsp {
namespace {

// SplitPolygons of \p scene as \p bsp cuts it into pieces; null when no polygon was split.
std::unique_ptr<const SplitPolygons> split_polygons(const Scene& scene, const SceneBsp& bsp) {
  if (std::ranges::none_of(scene.objects, [](const SceneObject& object) {
        return object.mesh.split_face_count() > 0;
      })) {
    return nullptr;
  }
  auto split = std::make_unique<SplitPolygons>();
  split->of_face.assign(scene.face_count(), -1);
  for (const SceneObject& object : scene.objects) {
    const std::vector<std::uint32_t>& input = object.mesh.input_faces;
    for (std::size_t f = 0, end = 0; f < input.size(); f = end) {
      for (end = f + 1; end < input.size() && input[end] == input[f];) ++end;
      if (end - f < 2) continue;
      std::fill(split->of_face.begin() + std::ptrdiff_t(object.first_face + f),
                split->of_face.begin() + std::ptrdiff_t(object.first_face + end),
                std::int32_t(object.first_face + f));
    }
  }
  split->pieces.assign(scene.face_count(), 0);
  for (const ConvexPolygon& piece : bsp.pieces()) {
    const std::int32_t polygon = split->of_face[piece.face];
    if (polygon >= 0) ++split->pieces[std::size_t(polygon)];
  }
  return split;
}

// Per global face: 1 when it bounds an outward solid (OutwardSolids): turned from the sun,
// it neither receives light nor casts a shadow that the solid does not. Not for a solid with
// a split polygon: its far side may see the sun through its own polygon's near side.
std::vector<char> outward_solid_faces(const Scene& scene, const SplitPolygons* split) {
  const OutwardSolids& solids = scene.outward_solids();
  std::vector<char> split_solid(solids.size());
  for (std::uint32_t f = 0; split && f < scene.face_count(); ++f) {
    if (split->of_face[f] >= 0 && solids.bounds_solid(f)) {
      split_solid[std::size_t(solids.solid_of(f))] = 1;
    }
  }
  std::vector<char> outward(scene.face_count());
  for (std::uint32_t f = 0; f < scene.face_count(); ++f) {
    outward[f] = solids.bounds_solid(f) && !split_solid[std::size_t(solids.solid_of(f))];
  }
  return outward;
}

}  // namespace

SunlitAreas::SunlitAreas(const Scene& scene)
    : scene_(scene),
      bsp_(std::make_unique<const SceneBsp>(SceneBsp::build(scene))),
      split_(split_polygons(scene, *bsp_)),
      outward_solid_faces_(outward_solid_faces(scene, split_.get())) {}

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
  // The sun is outside every solid: a face of one is on its far side when turned away.
  const auto far_side = [&](std::uint32_t face) {
    return outward_solid_faces_[face] && dot(scene_.face_plane(face).normal, toward_light) < 0;
  };
  ShadowGenerator generator(scene_, light, {}, far_side, nullptr, split_.get());
  generator.divide(bsp_->pieces());
  // Fragments are summed node by node and dropped: only the tree must grow (§4), not the
  // list of every fragment the fragments command keeps.
  std::vector<Fragment> fragments;
  bsp_->front_to_back(light, [&](NodePieces node) {
    fragments.clear();
    generator.process(node, fragments);
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
