#pragma once
// The shadow volume BSP tree of one light (§4): internal nodes are shadow planes, leaves are
// IN (inside the merged shadow volume) and OUT cells, and for polygons that must not shadow
// themselves, cells in the shadow of one such polygon alone.
#include <cstdint>
#include <span>
#include <vector>

#include "convex_polygon.h"
#include "light_view.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::svbsp {

/// \brief A polygon piece with its verdict for one light.
struct Fragment {
  ConvexPolygon polygon;
  bool lit = false;
};

/// \brief The plane through the light and a polygon edge (for a directional light, through
/// the edge along the light's direction); the polygon's shadow volume is on its positive
/// side.
struct ShadowPlane {
  Plane plane;
};

/// \brief The input polygons that became several faces (Mesh::build keeps a warped polygon as
/// triangles). Such a polygon never shadows itself (sun-study.md): its faces see past one
/// another, and the tree keeps, apart from IN, the cells in the shadow of one of them alone.
struct SplitPolygons {
  /// Per global face: the id of its polygon (the polygon's first face), -1 when its polygon
  /// is that face alone.
  std::vector<std::int32_t> of_face;
  /// Per polygon id: the scene pieces of its faces. Once the last of them is filtered, the
  /// cells in its shadow alone are as IN for every piece after.
  std::vector<std::uint32_t> pieces;
};

/// \brief A lit fragment and the OUT leaf it reached, named by its parent node (-1: the root)
/// and side, as they stood before any volume replaced a leaf.
struct Landing {
  std::int32_t parent = -1;
  bool positive = false;
  ConvexPolygon fragment;
};

/// The shadow plane of edge \p a -> \p b of a polygon whose interior holds \p inside, or
/// nothing when the edge points at the light (the plane is undefined).
bool make_shadow_plane(const Light& light, Vec3 a, Vec3 b, Vec3 inside, ShadowPlane& out);

/// \brief The SVBSP tree: starts as one OUT cell and grows by the shadow volumes of the lit
/// fragments filtered into it, polygons arriving in front-to-back order from the light.
class SvbspTree {
 public:
  /// \p eps: the distance within which a point counts as on a shadow plane.
  /// \p merge_siblings (§6, after Thibault and Naylor): where a node splits a polygon and
  /// each side yields one fragment with the same verdict, the two give way to the unsplit
  /// polygon (convex, and their union: they share the cut edge).
  /// \p skip_edges_in_tree (§6): an edge lying in a plane that already bounds the cell gets
  /// no plane of its own.
  /// \p split: see SplitPolygons, kept by the caller while the tree lives; null, every face
  /// may shadow every other.
  SvbspTree(const Light& light, double eps, bool merge_siblings = true,
            bool skip_edges_in_tree = true, const SplitPolygons* split = nullptr)
      : light_(light),
        eps_(eps),
        merge_siblings_(merge_siblings),
        skip_edges_in_tree_(skip_edges_in_tree),
        split_(split),
        pending_pieces_(split ? split->pieces : std::vector<std::uint32_t>{}) {}

  /// determineShadow of Fig. 4: filters \p p down the tree, appends its shadowed (IN) and
  /// lit (OUT) fragments to \p out, and replaces each OUT cell reached by the shadow volume
  /// of the fragment that reached it.
  void determine_shadow(const ConvexPolygon& p, std::vector<Fragment>& out) {
    descend(p, -1, false, {&out, true, nullptr});
  }
  /// Fig. 4 without enlarging the tree: the verdicts only; with \p landings, where each lit
  /// fragment landed, for enlarge_by_contour().
  void classify(const ConvexPolygon& p, std::vector<Fragment>& out,
                std::vector<Landing>* landings = nullptr) {
    descend(p, -1, false, {&out, false, landings});
  }
  /// §6, "keep an SVBSP tree well-balanced, even at the expense of increased size": cuts the
  /// empty tree's one OUT cell into up to 2^\p levels OUT cells, a kd tree of planes through
  /// the light at the medians of \p points (reordered) as \p view sees them. Volumes then grow
  /// in a cell each, and a polygon passes \p levels planes to reach its cell instead of the
  /// volumes of every polygon before it. The planes bound no volume: a polygon they split
  /// gets the verdicts of its whole, and its edges in them no plane (skip_edges_in_tree).
  void divide(const LightView& view, std::span<LightView::Coordinates> points, std::size_t levels);
  /// Scene piece \p piece is done with: filtered, or left out as shadowed.
  void piece_done(const ConvexPolygon& piece) {
    if (split_ && split_->of_face[piece.face] >= 0) --pending_pieces_[split_->of_face[piece.face]];
  }
  /// Enlarging only: unions the shadow volume of \p p into the tree.
  void enlarge(const ConvexPolygon& p) { descend(p, -1, false, {nullptr, true, nullptr}); }
  /// §6, contour edges only: replaces the OUT leaf of each landing by the volume bounded by
  /// those of \p contour that hold an edge of a fragment landed there. Exact when the
  /// landings are those of the faces of one convex solid turned to the light, classified
  /// before any of them enlarged the tree (ConvexSolids): in each leaf their fragments' union
  /// is the leaf's share of the solid's silhouette cone, and the contour planes along its
  /// edges are the only walls it adds.
  void enlarge_by_contour(std::vector<Landing> landings, std::span<const ShadowPlane> contour);

  std::size_t node_count() const { return nodes_.size(); }
  std::size_t memory_bytes() const { return nodes_.capacity() * sizeof(Node); }

  /// A tree with nothing in it and this one's light and settings: one cell's own.
  SvbspTree empty_like() const {
    return SvbspTree(light_, eps_, merge_siblings_, skip_edges_in_tree_, nullptr);
  }
  /// The OUT cells divide() made; 0 before it, or when it made none.
  std::size_t cell_count() const { return cell_count_; }
  /// \brief One step of a polygon's way down the planes of divide()'s cells (route()), in
  /// preorder: a split keeps the polygon it cut, and its negative side's steps and then its
  /// positive side's follow; a leaf names the cell its part reached.
  struct RouteStep {
    std::int32_t cell = -1;  ///< -1: a split
    ConvexPolygon polygon;   ///< a split: the polygon before it; a leaf: the part
  };
  /// Takes \p p down the cells' planes as descend() would, before the cells hold anything,
  /// appending its steps to \p steps. Each cell's part may then be filtered down a tree of its
  /// own: the cells' volumes never meet.
  void route(ConvexPolygon p, std::vector<RouteStep>& steps) const {
    route(std::move(p), -1, false, steps);
  }

 private:
  // Leaves: IN, OUT, and below kOut the cells in the shadow of split polygon `kOut - 1 - leaf`
  // alone, IN for every other polygon and OUT for that one.
  static constexpr std::int32_t kIn = -1, kOut = -2;
  static constexpr std::int32_t shadow_of(std::int32_t polygon) { return kOut - 1 - polygon; }
  struct Node {
    ShadowPlane shadow_plane;
    std::int32_t negative = kOut, positive = kOut;
  };
  // Where a filtered polygon's fragments go: the verdicts, the tree grown by each lit
  // fragment's volume, the lit fragments' leaves.
  struct Sinks {
    std::vector<Fragment>* out;
    bool enlarge;
    std::vector<Landing>* landings;
  };
  // Filters \p p from the slot (parent node, side; parent -1: the root) down to the leaves.
  void descend(ConvexPolygon p, std::int32_t parent, bool positive, const Sinks& sinks);
  // Takes \p p down from the slot (\p parent, \p positive) while it lies on one side of each
  // plane, its edges along a plane it touches marked (§6). Returns the node whose plane it
  // spans, its halves in \p negative_part and \p positive_part; or the leaf it reached, the
  // slot left in (\p parent, \p positive).
  std::int32_t down_to_split(ConvexPolygon& p, std::int32_t& parent, bool& positive,
                             ConvexPolygon& negative_part, ConvexPolygon& positive_part) const;
  void route(ConvexPolygon p, std::int32_t parent, bool positive,
             std::vector<RouteStep>& steps) const;
  std::int32_t& slot(std::int32_t parent, bool positive);
  std::int32_t slot(std::int32_t parent, bool positive) const;
  // The cells of divide() over \p points: a subtree of OUT leaves.
  std::int32_t cells(const LightView& view, std::span<LightView::Coordinates> points,
                     std::size_t levels);
  // Where fragment \p p reached \p leaf: whether it is lit, and the leaf after its volume.
  struct Verdict {
    bool lit;
    std::int32_t inside;  ///< the leaf inside p's volume; \p leaf itself when it adds nothing
  };
  Verdict verdict(const ConvexPolygon& p, std::int32_t leaf) const;
  // The volume of \p p in a cell that was leaf \p outside, with leaf \p inside within it.
  std::int32_t shadow_volume(const ConvexPolygon& p, std::int32_t outside, std::int32_t inside);
  // Links \p planes into one volume: outside any of them \p outside, inside all \p inside.
  std::int32_t chain(std::span<const ShadowPlane> planes, std::int32_t outside = kOut,
                     std::int32_t inside = kIn);

  Light light_;
  double eps_;
  bool merge_siblings_;
  bool skip_edges_in_tree_;
  const SplitPolygons* split_;
  std::vector<std::uint32_t> pending_pieces_;  ///< per split polygon: its pieces still to come
  std::int32_t root_ = kOut;
  std::vector<Node> nodes_;
  // divide()'s cells: per slot of its nodes (node * 2 + side), the cell there, or -1.
  std::vector<std::int32_t> cell_of_slot_;
  std::size_t cell_count_ = 0;
};

}  // namespace shadowkit::svbsp
