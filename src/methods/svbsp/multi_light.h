#pragma once
// §5: several lights, the fragments of one light's SVBSP tree pipelined into the next.
#include <cstdint>
#include <vector>

#include "scene_bsp.h"
#include "shadow_generator.h"

namespace shadowkit::svbsp {

/// At most this many lights: one bit each in a fragment's mask (§7: "a bit mask is used to
/// keep track of which light sources illuminate each polygon fragment").
inline constexpr std::size_t kMaxLights = 64;

/// \brief A fragment of the multi-light pipeline: bit l of lit_mask set when light l
/// (index into scene.lights) illuminates it.
struct MaskedFragment {
  ConvexPolygon polygon;
  std::uint64_t lit_mask = 0;
};

/// \brief Statistics of one light's pass, as Table 1 lists them.
struct LightPass {
  std::size_t light = 0;  ///< index into scene.lights
  FrontFacing front_facing;
  std::size_t svbsp_nodes = 0;
  std::size_t fragments = 0;  ///< fragments leaving this light's tree
};

/// \brief Every scene piece split by every light's shadow volumes.
struct MultiLightFragments {
  std::vector<MaskedFragment> fragments;
  std::vector<LightPass> passes;  ///< in processing order
};

/// §6's heuristic: lights in increasing order of the number of polygons facing them, so the
/// lights that split most come last and fragment the fewest pieces.
std::vector<std::size_t> light_order(const Scene& scene);

/// Runs every light of \p scene (at most kMaxLights, InputError otherwise) in light_order().
/// Each light's tree grows exactly as in generate_shadows() (from the original pieces: §6's
/// "more coherent" fragments), so its lit region is the one of the single-light run; the
/// fragments of the earlier lights are only classified by it.
/// \p merge_siblings: see SvbspTree.
MultiLightFragments generate_multi_light_shadows(const SceneBsp& bsp, const Scene& scene,
                                                 bool merge_siblings = true);

}  // namespace shadowkit::svbsp
