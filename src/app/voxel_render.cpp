// The voxel-render command: Lai & Cheng §5's image of the subpatches, shaded from the cubic
// frame buffer (§5.2) and a second view that reuses the shadow work, or without the frame
// buffer (§5.1) one still image.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "shadowkit/app/commands.h"
#include "shadowkit/core/error.h"
#include "shadowkit/methods/voxel.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit {
namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// The camera turned by \p degrees around the vertical line through what it looks at.
Camera turned(Camera camera, double degrees) {
  const double a = degrees * M_PI / 180, c = std::cos(a), s = std::sin(a);
  const Vec3 r = camera.position - camera.look_at;
  camera.position = camera.look_at + Vec3{c * r.x + s * r.z, r.y, -s * r.x + c * r.z};
  return camera;
}

// §5.1: one still image, the tessellation drawn in batches as it is made.
int render_still(const Scene& scene, const MethodOptions& settings,
                 const VoxelRenderOptions& options, const Context& ctx) {
  const auto start = std::chrono::steady_clock::now();
  const voxel::StillImage still = voxel::render_still(scene, settings, ctx);
  write_png(options.image, still.image);
  std::printf(
      "%zu triangles in %zu batches; voxelization, shadows, tessellation and view %.1f ms "
      "(shadow data %.1f MB): %s\n",
      still.triangles, still.batches, ms_since(start), double(still.shadow_bytes) / 1e6,
      options.image.c_str());
  return 0;
}

}  // namespace

int run_voxel_render(const VoxelRenderOptions& options, const Context& ctx) {
  if (!std::isfinite(options.turn_deg)) {
    throw InputError("option '--turn'", "expected a finite number of degrees, got " +
                                            std::to_string(options.turn_deg));
  }
  const auto found = options.settings.find("voxel");
  const MethodOptions settings = found == options.settings.end() ? MethodOptions{} : found->second;
  const bool frame_buffer = voxel::keeps_frame_buffer(settings);
  // §5.1 keeps no shadow states: a second view would redo all the shadow work.
  if (!options.turned_image.empty() && !frame_buffer) {
    throw InputError("option '--turned-image'",
                     "a second view without new shadow work is what the cubic frame buffer is "
                     "for; voxel.framebuffer=0 (Lai & Cheng 5.1) renders one still image");
  }
  const Scene scene = load_scene(options.scene, ctx);
  if (!frame_buffer) return render_still(scene, settings, options, ctx);
  // §5.2: the frame buffer is made for both views, so that the turned one drops nothing.
  std::vector<Camera> other_views;
  if (!options.turned_image.empty()) other_views.push_back(turned(scene.camera, options.turn_deg));
  const auto start = std::chrono::steady_clock::now();
  voxel::FrameBufferImage source(scene, settings, ctx, other_views);
  const double prepare_ms = ms_since(start);
  const auto view_start = std::chrono::steady_clock::now();
  write_png(options.image, source.render(scene.camera));
  const double view_ms = ms_since(view_start);
  std::printf(
      "%zu triangles; voxelization, shadows and tessellation %.1f ms (shadow data %.1f MB); "
      "view %.1f ms: %s\n",
      source.triangle_count(), prepare_ms, double(source.shadow_bytes()) / 1e6, view_ms,
      options.image.c_str());
  if (!options.turned_image.empty()) {
    const auto turn_start = std::chrono::steady_clock::now();
    write_png(options.turned_image, source.render(other_views.front()));
    std::printf("view turned by %g degrees, no shadow work: %.1f ms: %s\n", options.turn_deg,
                ms_since(turn_start), options.turned_image.c_str());
  }
  return 0;
}

}  // namespace shadowkit
