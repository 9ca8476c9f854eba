#pragma once
// The shadow volume BSP tree of one light (§4): internal nodes are shadow planes, leaves are
// IN (inside the merged shadow volume) and OUT cells.
#include <cstdint>
#include <vector>

#include "convex_polygon.h"
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
  SvbspTree(const Light& light, double eps, bool merge_siblings = true)
      : light_(light), eps_(eps), merge_siblings_(merge_siblings) {}

  /// determineShadow of Fig. 4: filters \p p down the tree, appends its shadowed (IN) and
  /// lit (OUT) fragments to \p out, and replaces each OUT cell reached by the shadow volume
  /// of the fragment that reached it.
  void determine_shadow(const ConvexPolygon& p, std::vector<Fragment>& out) {
    filter(p, &out, true);
  }
  /// Fig. 4 without enlarging the tree: the verdicts only.
  void classify(const ConvexPolygon& p, std::vector<Fragment>& out) { filter(p, &out, false); }
  /// Enlarging only: unions the shadow volume of \p p into the tree.
  void enlarge(const ConvexPolygon& p) { filter(p, nullptr, true); }

  std::size_t node_count() const { return nodes_.size(); }
  std::size_t memory_bytes() const { return nodes_.capacity() * sizeof(Node); }

 private:
  static constexpr std::int32_t kIn = -1, kOut = -2;
  struct Node {
    ShadowPlane shadow_plane;
    std::int32_t negative = kOut, positive = kOut;
  };
  void filter(const ConvexPolygon& p, std::vector<Fragment>* out, bool enlarge);
  // Filters \p p from the slot (parent node, side; parent -1: the root) down to the leaves.
  void descend(ConvexPolygon p, std::int32_t parent, bool positive, std::vector<Fragment>* out,
               bool enlarge);
  std::int32_t shadow_volume(const ConvexPolygon& p);

  Light light_;
  double eps_;
  bool merge_siblings_;
  std::int32_t root_ = kOut;
  std::vector<Node> nodes_;
};

}  // namespace shadowkit::svbsp
