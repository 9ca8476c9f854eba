#pragma once
// The scene as parametric patches (Lai & Cheng §3: voxelization works in each patch's
// (u, v) domain). A Catmull-Clark object gives its surface's patches (the exact limit
// surface, not its tessellation). A polygon is a patch too: each triangle of the scene's
// triangulation is the bilinear patch (a, b, c, c) with one collapsed edge, so non-convex
// polygons and n-gons need no special case.
#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "shadowkit/scene/scene.h"

namespace shadowkit::voxel {

/// \brief One patch: where to evaluate it and the ids of its corners at (u, v) = (0, 0),
/// (1, 0), (1, 1), (0, 1). Ids are unique in the scene; two patches share a side exactly
/// when they share its two corner ids.
struct Patch {
  std::uint32_t object = 0;
  const SubdivisionSurface* surface = nullptr;  ///< null: a triangle
  std::uint32_t index = 0;  ///< triangle of Scene::triangles(), or patch of the surface
  std::array<std::uint32_t, 4> corner_ids{};
};

/// \brief The patches of every object, with canonical evaluation of shared sides. A
/// triangle whose three corners an earlier triangle already has (in any order) is left out:
/// coincident copies are one surface.
///
/// Leak-free voxelization needs a point on a shared side (or a shared corner) to be the same
/// bits from every patch around it. point() therefore evaluates boundary points through one
/// owner per side and per corner, at the side's parameter measured from its lower corner id;
/// the recursion's parameters are dyadic, so 1 - t is exact and both neighbours ask for the
/// same point.
class PatchSet {
 public:
  explicit PatchSet(const Scene& scene);

  std::size_t size() const { return patches_.size(); }
  const Patch& operator[](std::size_t i) const { return patches_[i]; }
  /// The world position of \p patch at (u, v) in [0, 1]^2, canonical on sides and corners.
  Vec3 point(std::uint32_t patch, double u, double v) const;
  /// The side's parameter measured from its lower corner id (the canonical direction) for
  /// parameter \p t measured from corner \p side of \p patch, and back: the same map.
  double canonical_t(std::uint32_t patch, int side, double t) const;
  /// The key of the side of \p patch from corner \p side to the next, shared by every
  /// patch with that side.
  std::uint64_t side_id(std::uint32_t patch, int side) const;

  /// (u, v) at parameter \p t along side \p side (from corner side to corner side + 1).
  static std::array<double, 2> side_uv(int side, double t);
  /// The side a boundary point (u, v) lies on and its parameter along it.
  static std::pair<int, double> side_of(double u, double v);

 private:
  struct Owner {
    std::uint32_t patch = 0;
    std::uint8_t side = 0;  ///< side s runs from corner s to corner (s + 1) % 4
  };
  Vec3 evaluate(std::uint32_t patch, double u, double v) const;
  static std::uint64_t side_key(std::uint32_t a, std::uint32_t b);
  void add_triangles(const Scene& scene);
  void add_surface(std::uint32_t object, const SubdivisionSurface& surface, std::uint32_t& next_id);

  const Scene* scene_ = nullptr;
  std::vector<Patch> patches_;
  std::unordered_map<std::uint64_t, Owner> side_owner_;
  std::unordered_map<std::uint32_t, Owner> corner_owner_;  ///< side = the corner's number
};

}  // namespace shadowkit::voxel
