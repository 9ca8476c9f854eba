// The entry points of the voxel-render command (include/shadowkit/methods/voxel.h): §5's
// image of the subpatches with the bounds that keep its memory in hand.
#include <utility>

#include "shadowkit/core/error.h"
#include "shadowkit/methods/voxel.h"
#include "subpatch_render.h"
#include "voxel_method.h"

namespace shadowkit::voxel {
namespace {

// Triangles the §5.1 still render draws at a time: the peak memory of its tessellation.
constexpr std::size_t kStillBatchTriangles = std::size_t(1) << 18;
// With the frame buffer the whole tessellation is kept, about 1 KB a subpatch against the
// masks' 140 bytes (docs/methods/voxel.md): the bound on the subpatches when
// voxel.max_subpatches is not given.
constexpr std::size_t kKeptTessellationSubpatches = std::size_t(1) << 23;

VoxelMethod method_for_render(const MethodOptions& settings) {
  VoxelMethod method(settings);
  const bool bound_given = !settings.text("max_subpatches", "").empty();
  if (!method.keeps_frame_buffer() || bound_given) return method;
  return VoxelMethod(settings, kKeptTessellationSubpatches);
}

}  // namespace

std::unique_ptr<ShadowMethod> make_method(const MethodOptions& options) {
  return std::make_unique<VoxelMethod>(options);
}

bool keeps_frame_buffer(const MethodOptions& settings) {
  return VoxelMethod(settings).keeps_frame_buffer();
}

StillImage render_still(const Scene& scene, const MethodOptions& settings, const Context& ctx) {
  VoxelMethod method = method_for_render(settings);
  StillImage still = render_still(scene, method, ctx, kStillBatchTriangles);
  still.shadow_bytes = method.memory_bytes();
  return still;
}

struct FrameBufferImage::Parts {
  const Scene& scene;
  VoxelMethod method;
  SubpatchImage image;
};

FrameBufferImage::FrameBufferImage(const Scene& scene, const MethodOptions& settings,
                                   const Context& ctx, std::vector<Camera> other_views) {
  VoxelMethod method = method_for_render(settings);
  method.serve_views(std::move(other_views));
  if (!method.keeps_frame_buffer()) {
    throw InputError("option 'voxel.framebuffer'",
                     "the image from the cubic frame buffer (Lai & Cheng 5.2) needs "
                     "voxel.framebuffer=1");
  }
  SubpatchImage image = make_subpatch_image(scene, method, ctx);
  parts_ = std::make_unique<Parts>(Parts{scene, std::move(method), std::move(image)});
}

FrameBufferImage::FrameBufferImage(FrameBufferImage&&) noexcept = default;
FrameBufferImage& FrameBufferImage::operator=(FrameBufferImage&&) noexcept = default;
FrameBufferImage::~FrameBufferImage() = default;

Image<Rgb8> FrameBufferImage::render(const Camera& camera) {
  if (!parts_->method.serves(parts_->scene, camera)) {
    throw InputError("scene '" + parts_->scene.name + "'",
                     "this view sees geometry, or shadows on it, outside the cubic frame "
                     "buffer made for the views given (voxel.bound=view); make the image for "
                     "this view too, or set voxel.bound=scene");
  }
  return parts_->image.render(camera);
}

std::size_t FrameBufferImage::triangle_count() const {
  return parts_->image.triangle_count();
}

std::size_t FrameBufferImage::shadow_bytes() const {
  return parts_->method.memory_bytes();
}

}  // namespace shadowkit::voxel
