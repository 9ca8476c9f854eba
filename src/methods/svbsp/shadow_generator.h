#pragma once
// shadowGenerator of Fig. 3: one light's SVBSP tree and the fragments of every scene piece.
#include <functional>
#include <span>
#include <vector>

#include "convex_solids.h"
#include "scene_bsp.h"
#include "shadowkit/scene/outward_solids.h"
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

/// \brief How shadowGenerator runs: Figs. 3 and 4 as the paper writes them, and each of §6's
/// refinements that keep the result exact as a switch (docs/papers/chin-feiner-1989.md).
/// All false is the paper's own algorithm.
struct GeneratorSettings {
  /// Surfaces are two-sided (the contract): a piece is filtered from whichever side the
  /// light sees. Off, only pieces whose front faces the light are filtered; the others are
  /// shadowed and cast nothing (Fig. 3).
  bool two_sided = true;
  /// §6: an edge lying in a plane that already bounds the cell gets no plane of its own.
  bool skip_edges_in_tree = true;
  /// §6, after Thibault and Naylor: sibling fragments in the same state are merged.
  bool merge_siblings = true;
  /// §6: a piece whose fragments are all lit or all shadowed is kept whole.
  bool whole_pieces = true;
  /// §6: the SVBSP tree is kept balanced: on a scene of many pieces it starts cut into cells
  /// by planes through the light (ShadowGenerator::divide).
  bool balance = true;
  /// With balance, the cells filled in parallel (ShadowGenerator::process_in_cells); off, in
  /// one tree one piece after another. The fragments are the same.
  bool cells_in_parallel = true;
};

/// Whether a global face is known to lie in shadow whole: its pieces are shadowed without
/// filtering and cast nothing new. Empty: every piece is filtered.
using ShadowedWhole = std::function<bool(std::uint32_t face)>;

/// The far sides of the scene's outward solids from \p light, which their near sides
/// shadow.
ShadowedWhole far_side_of(const Scene& scene, const Light& light);

/// \brief The body of Fig. 3 for one light: fed the scene pieces one BSP node at a time in
/// front-to-back order, it grows the light's SVBSP tree and gives each piece's fragments.
class ShadowGenerator {
 public:
  /// §6's balance: a cell's share of the pieces. A polygon crosses the volumes of the
  /// pieces before it in its cell, about the square root of a cell's share in a sweep over
  /// a surface, and the cells' planes, one per halving.
  static constexpr std::size_t kPiecesPerCell = 1024;

  /// \p solids: the convex solids of the scene BSP tree's solid leaves (§6, contour edges);
  /// null when it has none. \p split: the polygons that do not shadow themselves
  /// (SplitPolygons), kept by the caller while the generator lives; null for none.
  ShadowGenerator(const Scene& scene, const Light& light, const GeneratorSettings& settings = {},
                  ShadowedWhole shadowed_whole = {}, const ConvexSolids* solids = nullptr,
                  const SplitPolygons* split = nullptr);

  /// Whether the light lies in the plane of \p piece's face: the piece is shadowed and
  /// casts nothing (Fig. 3).
  bool in_light_plane(const ConvexPolygon& piece) const;
  /// Whether \p piece is known to lie in shadow whole (ShadowedWhole).
  bool shadowed_whole(const ConvexPolygon& piece) const {
    return shadowed_whole_ && shadowed_whole_(piece.face);
  }
  /// With the balance setting, before any piece: cuts the tree into cells of about
  /// kPiecesPerCell of \p pieces (all the generator will be fed) each, placed by where the
  /// light sees them (SvbspTree::divide). Nothing on scenes of fewer than two cells' pieces,
  /// or with a point light inside the scene's box.
  void divide(std::span<const ConvexPolygon> pieces);
  /// Processes the pieces of one BSP node: appends their fragments to \p out and unions the
  /// shadow volumes of the lit ones into the tree. Far-side pieces are appended shadowed and
  /// whole.
  void process(NodePieces node, std::vector<Fragment>& out);
  /// The verdicts of the tree as it stands, without enlarging it: used for fragments of
  /// earlier lights (§5), which must not add planes of their own.
  void classify(const ConvexPolygon& p, std::vector<Fragment>& out) { tree_.classify(p, out); }

  /// Fig. 3 over every node of \p bsp in front-to-back order, as process() would, with each
  /// of divide()'s cells filled by a thread of its own: the volumes in one cell never reach
  /// another, so each piece is taken down the cells' planes first and its part in a cell
  /// filtered down that cell's own tree; the fragments are then put together in the order,
  /// and merged as, one tree would give. Needs cells, no convex solids and no split polygons.
  void process_in_cells(const SceneBsp& bsp, std::vector<Fragment>& out);

  std::size_t light_facing() const { return light_facing_; }
  const SvbspTree& tree() const { return tree_; }
  /// Nodes and bytes of the tree and of the cells' own trees.
  std::size_t svbsp_nodes() const;
  std::size_t svbsp_bytes() const;

 private:
  // Whether the light is in front of global face \p face, off its plane.
  bool turned_to_light(std::uint32_t face) const;
  // Whether \p piece is filtered: the light is off its plane, and with one-sided surfaces in
  // front of it (Fig. 3).
  bool facing(const ConvexPolygon& piece) const;
  // The pieces of one BSP node, in one plane: whether some are shadowed whole, and whether
  // they are classified together (Coplanar::together).
  struct Coplanar {
    bool any_whole;
    /// Pieces of one plane cannot shadow one another, but where two of them overlap, the
    /// first one's volume would hold the second: all are classified, then their volumes
    /// added.
    bool together;
  };
  Coplanar coplanar_pieces(std::span<const ConvexPolygon> coplanar) const;
  // Whether \p piece of \p coplanar is filtered: else it is shadowed whole and casts nothing.
  bool filtered(const ConvexPolygon& piece, const Coplanar& coplanar) const;
  void process_node(NodePieces node, std::vector<Fragment>& out);
  void process_coplanar(std::span<const ConvexPolygon> coplanar, std::vector<Fragment>& out);
  void process_solid(std::span<const ConvexPolygon> faces, std::size_t solid,
                     std::vector<Fragment>& out);
  // §6: the fragments of \p piece from \p first on give way to it when they all agree.
  void keep_whole_if_uniform(const ConvexPolygon& piece, std::size_t first,
                             std::vector<Fragment>& out) const;

  const Scene& scene_;
  Light light_;
  GeneratorSettings settings_;
  ShadowedWhole shadowed_whole_;
  const ConvexSolids* solids_;
  double in_plane_;
  SvbspTree tree_;
  std::vector<SvbspTree> cell_trees_;  ///< process_in_cells(): per cell
  std::size_t light_facing_ = 0;
};

/// Filters the pieces of \p bsp in front-to-back order from \p light down a new SVBSP tree.
/// Surfaces are two-sided unless \p settings says otherwise: a piece faces the light from
/// whichever side the light is; a piece whose plane holds the light is shadowed and casts
/// nothing. \p shadowed_whole: see ShadowedWhole. \p solids: see ShadowGenerator.
/// \p storage: an earlier light's fragments, whose room the new ones take.
LightFragments generate_shadows(const SceneBsp& bsp, const Scene& scene, const Light& light,
                                const GeneratorSettings& settings = {},
                                const ShadowedWhole& shadowed_whole = {},
                                const ConvexSolids* solids = nullptr,
                                std::vector<Fragment> storage = {});

}  // namespace shadowkit::svbsp
