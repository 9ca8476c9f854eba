#pragma once
// Shared by the svbsp tests: one light's fragments and their areas per face.
#include <map>

#include "shadow_generator.h"

namespace shadowkit::testing {

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

}  // namespace shadowkit::testing
