#pragma once
// The scene BSP tree of Fuchs, Kedem and Naylor (§3): built once per scene, it gives the
// front-to-back order of the scene polygons from any light in linear time.
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "convex_polygon.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::svbsp {

class ConvexSolids;

/// \brief What front_to_back() hands over for one node: the coplanar pieces lying in its
/// plane, or (solid >= 0) every face of a convex solid that no splitting plane crossed.
struct NodePieces {
  std::span<const ConvexPolygon> pieces;
  std::int32_t solid = -1;  ///< into ConvexSolids
};

/// \brief A BSP tree over the convex pieces of every scene face. Each node holds the pieces
/// lying in its plane (the plane of an original face); pieces spanning a node's plane are
/// split by it.
class SceneBsp {
 public:
  /// Builds the tree from every face of \p scene (non-convex faces as triangles). Each node
  /// tries a few candidate planes on a sample of its polygons and keeps the one with the
  /// lowest weighted sum of splits and imbalance; a node may split by a plane holding no
  /// polygon. Large subtrees are built in parallel; the tree does not depend on threads.
  /// With \p clusters, a node of at most 128 polygons each lying behind every other's plane
  /// (a patch of a convex surface, or of a concave one) is a cluster leaf, split no further;
  /// without, every node holds one plane's polygons, as in §3.
  /// With \p solids, each convex solid is kept whole as one leaf (Schumacker's clusters),
  /// the planes of its faces and of the gaps around it separating it from the rest, unless
  /// no such plane is found and one crosses it: its faces then go on alone.
  static SceneBsp build(const Scene& scene, const ConvexSolids* solids = nullptr,
                        bool clusters = true);

  /// Calls \p visit with the pieces of each node, nodes in front-to-back order as seen from
  /// \p light (a directional light sits at infinity against its direction). Pieces of one
  /// node are coplanar and cannot hide one another, or they are the faces of one convex
  /// solid, which nothing visited later hides. A cluster leaf hands over its pieces one by
  /// one, those whose front the light sees first.
  void front_to_back(const Light& light, const std::function<void(NodePieces)>& visit) const;

  std::size_t node_count() const { return nodes_.size(); }
  std::size_t piece_count() const { return pieces_.size(); }
  /// Every piece; front_to_back() visits spans of this array, so a piece's index is its
  /// address minus pieces().data().
  std::span<const ConvexPolygon> pieces() const { return pieces_; }
  /// Pieces created by splitting (piece_count minus the convex input polygons).
  std::size_t split_count() const { return splits_; }
  /// Convex solids kept whole, each one leaf.
  std::size_t solid_count() const { return solids_; }
  std::size_t depth() const { return depth_; }
  std::size_t memory_bytes() const;

  /// The tolerance of plane tests, relative to the scene's size.
  static constexpr double kRelativeTolerance = 1e-9;

 private:
  struct Node {
    Plane plane;
    std::uint32_t first = 0, count = 0;  ///< pieces in the plane, into pieces_
    std::int32_t front = -1, back = -1;  ///< children, -1: empty half-space
    std::int32_t solid = -1;             ///< a leaf holding a convex solid's faces
    std::int32_t cluster = -1;  ///< a cluster leaf: its pieces' planes, into cluster_planes_
  };
  struct Draft;
  class Builder;
  // Appends \p draft's subtree in preorder, front before back, and its pieces' builder ids
  // to \p order; returns its root.
  std::int32_t lay_out(const Draft& draft, std::vector<std::uint32_t>& order, std::size_t depth);
  void visit(std::int32_t node, const Light& light,
             const std::function<void(NodePieces)>& fn) const;
  void visit_cluster(const Node& n, const Light& light,
                     const std::function<void(NodePieces)>& fn) const;

  std::vector<Node> nodes_;
  std::vector<ConvexPolygon> pieces_;
  std::vector<Plane> cluster_planes_;
  std::int32_t root_ = -1;
  double eps_ = 0;
  std::size_t splits_ = 0, depth_ = 0, solids_ = 0;
};

/// The convex pieces of every face of \p scene: the face itself when it is convex, its
/// triangles otherwise.
std::vector<ConvexPolygon> convex_faces(const Scene& scene);

}  // namespace shadowkit::svbsp
