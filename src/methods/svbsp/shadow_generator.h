#pragma once
// shadowGenerator of Fig. 3: one light's SVBSP tree and the fragments of every scene piece.
#include <vector>

#include "scene_bsp.h"
#include "svbsp_tree.h"

namespace shadowkit::svbsp {

/// \brief One light's result: every scene piece as lit and shadowed fragments, and the
/// statistics of Table 1.
struct LightFragments {
  std::vector<Fragment> fragments;
  std::size_t light_facing = 0;  ///< pieces filtered (the light is off their plane)
  std::size_t svbsp_nodes = 0;
  std::size_t svbsp_bytes = 0;
};

/// Filters the pieces of \p bsp in front-to-back order from \p light down a new SVBSP tree.
/// Surfaces are two-sided: a piece faces the light from whichever side the light is; a
/// piece whose plane holds the light is shadowed and casts nothing. Where all fragments of
/// a piece agree, the piece itself replaces them (§6).
LightFragments generate_shadows(const SceneBsp& bsp, const Scene& scene, const Light& light);

}  // namespace shadowkit::svbsp
