#pragma once
// Lai & Cheng §5: the image of the subpatches themselves, each shaded with the shadow state
// of its four corner voxels, from the cubic frame buffer (§5.2: a new view needs no new
// shadow work) or decided on the fly from the projection plane (§5.1: one still image).
#include <cstdint>
#include <vector>

#include "crack_free_tessellation.h"
#include "shadowkit/core/image.h"
#include "shadowkit/scene/scene.h"
#include "voxel_method.h"

namespace shadowkit::voxel {

/// \brief §5: of a subpatch with n of its four corner voxels shadowed, the share of a
/// light's diffuse reflection (1 / 2^n, none when all four are) and whether the light
/// adds a highlight (only when none is).
struct CornerShading {
  double diffuse = 1;
  bool highlight = true;
};
CornerShading corner_shading(int shadowed_corners);

/// Per subpatch (voxelize()'s order), how many of its corners' voxels are shadowed (0..4)
/// for the light \p method was last built for: read from the frame buffer (§5.2), or
/// decided on the fly (§5.1) by the offset test with the subpatch's normal, running the
/// recursion again. A corner outside the grid counts as lit.
std::vector<std::uint8_t> shadowed_corners(const VoxelMethod& method);

/// \brief The scene's subpatches, tessellated once (§5.3), with the shadowed-corner counts
/// of every light; render() draws them from any camera.
class SubpatchImage {
 public:
  SubpatchImage(const Scene& scene, const PatchSet& patches,
                const SubpatchTessellation& tessellation,
                std::vector<std::vector<std::uint8_t>> shadowed_per_light);
  /// The image seen by \p camera: ambient, plus per light Lambert diffuse scaled by
  /// corner_shading() and a Blinn-Phong highlight.
  Image<Rgb8> render(const Camera& camera) const;
  std::size_t triangle_count() const { return leaf_.size(); }
  /// Per subpatch, its shadowed corners for light \p light.
  const std::vector<std::uint8_t>& shadowed_corners(std::size_t light) const {
    return shadowed_[light];
  }

 private:
  Scene view_;  ///< the triangles as one object per scene object, with the scene's lights
  std::vector<std::uint32_t> leaf_;  ///< per face of view_
  std::vector<std::vector<std::uint8_t>> shadowed_;
};

/// §5 for a whole scene: \p method prepared and built for every light, the shadowed corners
/// of each light kept (from the frame buffer, §5.2, or on the fly, §5.1), the subpatches
/// tessellated once.
SubpatchImage make_subpatch_image(const Scene& scene, VoxelMethod& method, const Context& ctx);

}  // namespace shadowkit::voxel
