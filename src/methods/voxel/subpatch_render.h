#pragma once
// Lai & Cheng §5: the image of the subpatches themselves, each shaded with the shadow state
// of its four corner voxels, from the cubic frame buffer (§5.2: a new view needs no new
// shadow work) or decided on the fly from the projection plane (§5.1: one still image).
#include <cstdint>
#include <vector>

#include "crack_free_tessellation.h"
#include "shadowkit/core/image.h"
#include "shadowkit/methods/voxel.h"
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

/// Per light of \p scene, the shadowed corners of every subpatch: \p method prepared and
/// built for each light in turn.
std::vector<std::vector<std::uint8_t>> shadowed_corners_per_light(const Scene& scene,
                                                                  VoxelMethod& method,
                                                                  const Context& ctx);

/// \brief Tessellated subpatches as a scene the z-buffer draws, one object per scene object
/// that has triangles.
class SubpatchView {
 public:
  SubpatchView(const Scene& scene, const PatchSet& patches,
               const SubpatchTessellation& tessellation);
  /// Shades, as seen by \p camera, the pixels of \p image where these triangles are nearer
  /// than \p depth (distance along the pixel ray), and lowers \p depth there: ambient, plus
  /// per light Lambert diffuse scaled by corner_shading() of \p shadowed (per light, per
  /// subpatch) and a Blinn-Phong highlight. Equal depths keep what was drawn first.
  void draw(const Camera& camera, const std::vector<std::vector<std::uint8_t>>& shadowed,
            Image<Rgb8>& image, std::vector<float>& depth);
  std::size_t triangle_count() const { return leaf_.size(); }

 private:
  Scene view_;                         ///< the triangles, with the scene's lights
  std::vector<std::uint32_t> object_;  ///< per object of view_: the scene's object
  std::vector<std::uint32_t> leaf_;    ///< per face of view_
};

/// An image of \p camera's size, all background, and its depths (+inf).
struct Frame {
  explicit Frame(const Camera& camera);
  Image<Rgb8> image;
  std::vector<float> depth;
};

/// \brief The scene's subpatches, tessellated once (§5.3), with the shadowed-corner counts
/// of every light; render() draws them from any camera (§5.2).
class SubpatchImage {
 public:
  SubpatchImage(const Scene& scene, const PatchSet& patches,
                const SubpatchTessellation& tessellation,
                std::vector<std::vector<std::uint8_t>> shadowed_per_light);
  /// Moves the view's camera to \p camera (the tessellation is not copied).
  Image<Rgb8> render(const Camera& camera);
  std::size_t triangle_count() const { return view_.triangle_count(); }
  /// Per subpatch, its shadowed corners for light \p light.
  const std::vector<std::uint8_t>& shadowed_corners(std::size_t light) const {
    return shadowed_[light];
  }

 private:
  SubpatchView view_;
  std::vector<std::vector<std::uint8_t>> shadowed_;
};

/// §5 for a whole scene: the shadowed corners of each light kept (from the frame buffer,
/// §5.2, or on the fly, §5.1), the subpatches tessellated once.
SubpatchImage make_subpatch_image(const Scene& scene, VoxelMethod& method, const Context& ctx);

/// §5.1 for a whole scene, in little memory: the shadowed corners of each light, then the
/// tessellation drawn batch by batch (tessellate_in_batches(), \p batch_triangles) as it is
/// made, each batch shaded at once and composited by depth into the scene camera's image.
StillImage render_still(const Scene& scene, VoxelMethod& method, const Context& ctx,
                        std::size_t batch_triangles);

}  // namespace shadowkit::voxel
