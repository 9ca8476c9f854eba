#pragma once
// Lai & Cheng §4: the projection plane perpendicular to the light's beams, with entries
// about one voxel wide. A directional light has one orthographic plane; a point light six
// perspective planes around it (a cube), so a light inside the scene sees every direction.
#include <cstdint>
#include <optional>

#include "shadowkit/scene/scene.h"
#include "voxel_grid.h"

namespace shadowkit::voxel {

/// \brief Continuous coordinates on one projection plane; entry (floor x, floor y).
struct PlanePoint {
  int face = 0;
  double x = 0, y = 0;
};

/// \brief The light's projection, in grid units.
class LightProjection {
 public:
  /// Entries are 1 / \p entries_per_voxel voxels wide at the grid (point light: at the
  /// distance of the grid's centre, at least a quarter of its diagonal, so that a light
  /// inside the grid still gets entries of a useful size).
  LightProjection(const Light& light, const VoxelGrid& grid, double entries_per_voxel);

  /// Where the beam through \p p meets the projection (the plane of its cube face).
  PlanePoint project(Vec3 p) const;
  /// \p p on the plane of \p face, or nothing when \p p is not in front of that face.
  std::optional<PlanePoint> project_on(int face, Vec3 p) const;
  /// The entry holding \p q, as one key.
  static std::uint64_t entry(const PlanePoint& q);
  /// \brief An entry key's face and integer cell (the inverse of entry()).
  struct Cell {
    int face;
    std::uint64_t x, y;
  };
  static Cell cell(std::uint64_t entry);
  std::uint64_t entry(Vec3 p) const { return entry(project(p)); }
  /// Entries per voxel width at \p p, across the beam.
  double entry_width(Vec3 p) const;
  /// Distance from the light along the beam (point light: Euclidean; directional: depth).
  double distance(Vec3 p) const;
  /// Unit vector from \p p toward the light.
  Vec3 toward_light(Vec3 p) const;
  /// The segment from \p p to the light (to twice the grid's diagonal for a directional
  /// light), with t in (0, 1).
  Vec3 to_light(Vec3 p) const;
  bool point_light() const { return point_; }
  /// Entries per side of a cube face (point light).
  long resolution() const { return resolution_; }

 private:
  bool point_ = true;
  Vec3 light_;       ///< position (point light) or direction of travel (directional), grid units
  Vec3 right_, up_;  ///< directional: the plane's axes, entries_per_voxel long
  long resolution_ = 1;
  double reach_ = 1;
};

}  // namespace shadowkit::voxel
