#pragma once
// shadowGenerator of Fig. 3: one light's SVBSP tree and the fragments of every scene piece.
#include <functional>
#include <span>
#include <vector>

#include "outward_solids.h"
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

/// \brief Table 1's "front-facing polygons" and "front-facing edges": the scene faces whose
/// front (the side their normal points to) sees the light, and their edges, each face
/// counting its own (the paper processes polygons individually, §7).
struct FrontFacing {
  std::size_t polygons = 0, edges = 0;
};
FrontFacing front_facing(const Scene& scene, const Light& light);

/// Whether a global face is on the far side of its solid from the light (OutwardSolids); its
/// pieces are shadowed without filtering. Empty: every piece is filtered.
using FarSide = std::function<bool(std::uint32_t face)>;

/// The far-side test of \p solids for \p light.
FarSide far_side_of(const OutwardSolids& solids, const Scene& scene, const Light& light);

/// \brief The body of Fig. 3 for one light: fed the scene pieces one BSP node at a time in
/// front-to-back order, it grows the light's SVBSP tree and gives each piece's fragments.
class ShadowGenerator {
 public:
  /// \p merge_siblings: see SvbspTree.
  ShadowGenerator(const Scene& scene, const Light& light, bool merge_siblings = true,
                  FarSide far_side = {});

  /// Whether the light lies in the plane of \p piece's face: the piece is shadowed and
  /// casts nothing (Fig. 3).
  bool in_light_plane(const ConvexPolygon& piece) const;
  /// Whether \p piece is on the far side of its solid (FarSide).
  bool far_side(const ConvexPolygon& piece) const { return far_side_ && far_side_(piece.face); }
  /// Processes the coplanar pieces of one BSP node: appends their fragments to \p out and
  /// unions the shadow volumes of the lit ones into the tree. Far-side pieces are appended
  /// shadowed and whole.
  void process(std::span<const ConvexPolygon> coplanar, std::vector<Fragment>& out);
  /// The verdicts of the tree as it stands, without enlarging it: used for fragments of
  /// earlier lights (§5), which must not add planes of their own.
  void classify(const ConvexPolygon& p, std::vector<Fragment>& out) { tree_.classify(p, out); }

  std::size_t light_facing() const { return light_facing_; }
  const SvbspTree& tree() const { return tree_; }

 private:
  const Scene& scene_;
  Light light_;
  FarSide far_side_;
  double in_plane_;
  SvbspTree tree_;
  std::size_t light_facing_ = 0;
};

/// Filters the pieces of \p bsp in front-to-back order from \p light down a new SVBSP tree.
/// Surfaces are two-sided: a piece faces the light from whichever side the light is; a
/// piece whose plane holds the light is shadowed and casts nothing. Where all fragments of
/// a piece agree, the piece itself replaces them (§6).
/// \p merge_siblings: fragments split by a node but in the same state are merged back (§6).
/// \p far_side: see FarSide.
LightFragments generate_shadows(const SceneBsp& bsp, const Scene& scene, const Light& light,
                                bool merge_siblings = true, const FarSide& far_side = {});

}  // namespace shadowkit::svbsp
