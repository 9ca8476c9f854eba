#pragma once
/// \brief Lai & Cheng 2007: shadows of Catmull-Clark surfaces from a parameter-space
/// voxelization, as masks (make_method) and as the paper's own image of the subpatches (§5,
/// the voxel-render command).
#include <cstddef>
#include <memory>
#include <vector>

#include "shadowkit/core/context.h"
#include "shadowkit/core/image.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::voxel {

/// The method with \p options (its settings, docs/methods/voxel.md); InputError for an unknown
/// key or a bad value.
std::unique_ptr<ShadowMethod> make_method(const MethodOptions& options);

/// Whether \p settings keep the shadow states in the cubic frame buffer (§5.2, the default),
/// rather than deciding them on the fly from the projection plane (§5.1, framebuffer=0).
bool keeps_frame_buffer(const MethodOptions& settings);

/// \brief §5.1's one still image and how it was drawn.
struct StillImage {
  Image<Rgb8> image;
  std::size_t triangles = 0, batches = 0;
  std::size_t shadow_bytes = 0;  ///< the method's shadow data at its peak
};

/// §5.1: the image of the subpatches from the scene's camera, in little memory: the
/// tessellation is drawn batch by batch as it is made.
StillImage render_still(const Scene& scene, const MethodOptions& settings, const Context& ctx);

/// \brief §5.2: the scene's subpatches tessellated once (§5.3), with every light's shadow
/// states from the cubic frame buffer; render() draws them from the views it was made for
/// with no new shadow work.
class FrameBufferImage {
 public:
  /// The image of \p scene, which must outlive it, for its camera and \p other_views: with
  /// voxel.bound=view the frame buffer is bounded to hold what each of them needs.
  /// InputError when \p settings are bad or ask for §5.1 (framebuffer=0).
  FrameBufferImage(const Scene& scene, const MethodOptions& settings, const Context& ctx,
                   std::vector<Camera> other_views = {});
  FrameBufferImage(FrameBufferImage&&) noexcept;
  FrameBufferImage& operator=(FrameBufferImage&&) noexcept;
  ~FrameBufferImage();

  /// The subpatches seen by \p camera, shaded with their corners' shadow states (§5).
  /// InputError when the frame buffer lacks voxels \p camera's view needs (a camera it was
  /// not made for, with voxel.bound=view): geometry is never dropped silently.
  Image<Rgb8> render(const Camera& camera);
  std::size_t triangle_count() const;
  /// Bytes of the shadow data kept: the frame buffer and the subpatches' states.
  std::size_t shadow_bytes() const;

 private:
  struct Parts;
  std::unique_ptr<Parts> parts_;
};

}  // namespace shadowkit::voxel
