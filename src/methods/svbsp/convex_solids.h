#pragma once
// §6's contour edges: the convex solids of a scene, whose faces turned to a light together
// cast the volume bounded by the planes of the solid's contour edges alone.
#include <cstdint>
#include <functional>
#include <vector>

#include "shadowkit/scene/outward_solids.h"
#include "svbsp_tree.h"

namespace shadowkit::svbsp {

/// \brief The convex outward solids of a scene: OutwardSolids with every vertex on or behind
/// every face plane. Seen from a light outside one, its faces turned to the light hide none
/// of one another and together hide all the solid hides, so the solid can be filtered as a
/// unit whose volume is bounded by the planes of its contour edges alone (§6: "consider only
/// the silhouette edges of the objects of which the polygons are part").
class ConvexSolids {
 public:
  ConvexSolids(const Scene& scene, const OutwardSolids& outward);

  /// The convex solid that global face \p face bounds, -1 for none.
  std::int32_t solid_of(std::uint32_t face) const { return solid_[face]; }
  std::size_t size() const { return solids_.size(); }

  /// The shadow planes of solid \p s's contour edges for \p light: the edges between a face
  /// turned to it (\p facing of the global face) and one that is not, each plane with the
  /// solid on its positive side. An edge pointing at the light has no plane.
  std::vector<ShadowPlane> contour_planes(std::size_t s, const Light& light,
                                          const std::function<bool(std::uint32_t)>& facing) const;

 private:
  struct Edge {
    Vec3 a, b;
    std::uint32_t faces[2];  ///< global ids
  };
  struct Solid {
    std::vector<Edge> edges;
    Vec3 inside;  ///< the mean of its vertices: strictly inside a convex solid
  };
  std::vector<std::int32_t> solid_;  ///< per global face
  std::vector<Solid> solids_;
};

}  // namespace shadowkit::svbsp
