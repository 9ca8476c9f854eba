#pragma once
// svbsp: Chin & Feiner 1989 shadow volume BSP trees, shadows as object-space fragments.
#include <optional>
#include <vector>

#include "convex_solids.h"
#include "scene_bsp.h"
#include "shadow_generator.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/scene/sub_objects.h"

namespace shadowkit::svbsp {

/// \brief Chin & Feiner 1989: a scene BSP tree built once (prepare), per light an SVBSP
/// tree grown from the light-facing pieces in front-to-back order, which splits every piece
/// into lit and shadowed fragments (build); the mask renders the lit fragments with the
/// shared scan converter (shade). Settings (docs/methods/svbsp.md): paper=1 runs Figs. 3
/// and 4 as written, one-sided and with none of §6's refinements; each refinement has its
/// own switch: far_side (pieces on the far side of their solid shadowed whole,
/// OutwardSolids), footprints (the pieces of sub-objects wholly in the shadow of nearer
/// ones shadowed whole, shadowed_sub_objects), balance (the SVBSP tree cut into cells),
/// contour_planes (convex solids filtered as units, ConvexSolids),
/// skip_edges_in_tree, merge_siblings, whole_pieces, and shadowed_only (keep only the
/// shadowed fragments and draw them over the lit faces; the same mask but at a rare pixel on
/// a face's outline, see shade_fragments; less memory).
class SvbspMethod final : public ShadowMethod {
 public:
  explicit SvbspMethod(const MethodOptions& options);
  std::string_view name() const override { return "svbsp"; }
  void prepare(const Scene& scene, const Context& ctx) override;
  void build(const Scene& scene, std::size_t light, const Context& ctx) override;
  void shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces, ShadowMask& mask,
             const Context& ctx) override;
  std::size_t memory_bytes() const override;
  MethodCounters counters() const override;

  /// The fragments of the last build() (shadowed ones only with shadowed_only), each tied to
  /// its original face.
  const std::vector<svbsp::Fragment>& fragments() const { return result_.fragments; }

 private:
  svbsp::GeneratorSettings generator_;
  // Pieces shadowed without filtering, for the current light (far_side_, footprints_).
  ShadowedWhole shadowed_whole(const Scene& scene);

  bool far_side_ = true;
  bool footprints_ = true;
  bool contour_planes_ = false;
  bool shadowed_only_ = false;
  bool clusters_ = true;  ///< scene BSP cluster leaves; paper=1: none (§3's tree)
  std::optional<svbsp::SceneBsp> bsp_;
  std::optional<svbsp::ConvexSolids> convex_solids_;  ///< with contour_planes only
  SubObjects parts_;                                  ///< with footprints only
  std::vector<char> shadowed_parts_;                  ///< per sub-object, for the current light
  Light light_;
  svbsp::LightFragments result_;
  // Table 1's columns for the last light.
  std::size_t input_polygons_ = 0;
  svbsp::FrontFacing front_facing_;
};

}  // namespace shadowkit::svbsp
