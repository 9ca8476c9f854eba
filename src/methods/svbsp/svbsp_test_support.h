#pragma once
// Shared by the svbsp tests: one light's fragments and their areas per face.
#include <map>

#include "multi_light.h"
#include "shadow_generator.h"

namespace shadowkit::svbsp {

/// Lit and shadowed area of one face.
struct FaceAreas {
  double lit = 0, shadowed = 0;
};

/// The fragments of light \p light of \p scene.
inline svbsp::LightFragments light_fragments(const Scene& scene, std::size_t light) {
  const svbsp::SceneBsp bsp = svbsp::SceneBsp::build(scene);
  return svbsp::generate_shadows(bsp, scene, scene.lights[light]);
}

/// Lit and shadowed area per global face id.
inline std::map<std::uint32_t, FaceAreas> face_areas(
    const std::vector<svbsp::Fragment>& fragments) {
  std::map<std::uint32_t, FaceAreas> areas;
  for (const svbsp::Fragment& f : fragments) {
    (f.lit ? areas[f.polygon.face].lit : areas[f.polygon.face].shadowed) += area(f.polygon);
  }
  return areas;
}

/// Lit and shadowed area per global face id for light \p light of a multi-light result.
inline std::map<std::uint32_t, FaceAreas> face_areas(
    const std::vector<svbsp::MaskedFragment>& fragments, std::size_t light) {
  std::map<std::uint32_t, FaceAreas> areas;
  for (const svbsp::MaskedFragment& f : fragments) {
    FaceAreas& a = areas[f.polygon.face];
    ((f.lit_mask >> light) & 1 ? a.lit : a.shadowed) += area(f.polygon);
  }
  return areas;
}

/// Area of global face \p face of \p scene.
inline double face_area(const Scene& scene, std::uint32_t face) {
  return scene.objects[scene.object_of_face(face)].mesh.areas[scene.local_face(face)];
}

}  // namespace shadowkit::svbsp
