#pragma once
// The far side of closed solids: faces that a solid's own near side shadows, known without
// filtering them down the SVBSP tree (§6's silhouette optimization, in its simplest form).
#include <cstdint>
#include <vector>

#include "shadowkit/scene/scene.h"

namespace shadowkit::svbsp {

/// \brief The outward solids of a scene: the connected parts of closed, consistently oriented
/// meshes whose signed volume is positive (a part turned inside out, or a cavity's lining,
/// is none). A face of such a solid turned from a light outside it is shadowed by the
/// solid's faces turned toward the light (a ray entering the solid there left it through one
/// of those), so it neither receives light nor casts a shadow the solid does not.
class OutwardSolids {
 public:
  explicit OutwardSolids(const Scene& scene);

  /// Whether global face \p face bounds an outward solid.
  bool bounds_solid(std::uint32_t face) const { return solid_[face] >= 0; }
  /// The solid global face \p face bounds, -1 for none.
  std::int32_t solid_of(std::uint32_t face) const { return solid_[face]; }
  /// How many solids there are.
  std::size_t size() const { return bounds_.size(); }
  /// Whether \p face is on the far side of its solid from \p light: it bounds an outward
  /// solid, its plane is turned from the light, and the light is outside the solid (a
  /// directional light always is; a point light when it is outside the solid's box).
  bool far_side(const Scene& scene, std::uint32_t face, const Light& light) const;

 private:
  std::vector<std::int32_t> solid_;  ///< per global face: its solid, -1 for none
  std::vector<Bounds3> bounds_;      ///< per solid
};

}  // namespace shadowkit::svbsp
