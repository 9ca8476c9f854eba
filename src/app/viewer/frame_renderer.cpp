#include <algorithm>

#include "shadowkit/app/pipeline.h"
#include "shadowkit/app/shading.h"
#include "shadowkit/app/viewer.h"
#include "shadowkit/core/error.h"
#include "shadowkit/methods/mask_compare.h"
#include "shadowkit/methods/registry.h"
#include "shadowkit/raster/visible_surface.h"
#include "shadowkit/scene/scene_assembly.h"

namespace shadowkit::viewer {
namespace {

// The stages of a frame, timed as they run.
class StageClock {
 public:
  double lap() {
    const double now = now_ms(), ms = now - last_;
    last_ = now;
    return ms;
  }

 private:
  double last_ = now_ms();
};

const char* view_name(FrameView view) {
  switch (view) {
    case FrameView::shaded:
      return "shaded";
    case FrameView::mask:
      return "mask";
    case FrameView::difference:
      return "difference";
  }
  return "";
}

nlohmann::json light_info(const MethodRun& run) {
  nlohmann::json j = {{"light", run.light},
                      {"build_ms", run.build_ms},
                      {"shade_ms", run.shade_ms},
                      {"memory_bytes", run.memory_bytes}};
  for (const auto& [key, value] : run.counters) j["counters"][key] = value;
  return j;
}

}  // namespace

FrameRenderer::FrameRenderer(Scene scene)
    : scene_(std::move(scene)), scene_view_(world_view(scene_)), view_(scene_view_) {
  ctx_.warn = [](const std::string&) {};  // a frame's warnings would repeat at every frame
}

ShadowMethod& FrameRenderer::prepared(const std::string& method, const MethodOptions& settings) {
  std::string key = method;
  for (const auto& [name, value] : settings.values()) key += "\n" + name + "=" + value;
  auto it = std::find_if(methods_.begin(), methods_.end(),
                         [&](const PreparedMethod& m) { return m.key == key; });
  if (it != methods_.end() && !it->method->prepared_for_every_view() && it->view != view_count_) {
    methods_.erase(it);
    it = methods_.end();
  }
  if (it == methods_.end()) {
    if (methods_.size() == kKeptMethods) {
      methods_.erase(std::min_element(
          methods_.begin(), methods_.end(),
          [](const PreparedMethod& a, const PreparedMethod& b) { return a.used < b.used; }));
    }
    std::unique_ptr<ShadowMethod> fresh = make_method(method, settings);
    fresh->prepare(scene_, ctx_);
    methods_.push_back({key, std::move(fresh), view_count_, 0});
    it = methods_.end() - 1;
  }
  it->used = ++frame_count_;
  return *it->method;
}

std::optional<Frame> FrameRenderer::render(const FrameRequest& request,
                                           const std::function<bool()>& abandoned) {
  std::lock_guard lock(mutex_);
  if (abandoned()) return std::nullopt;
  StageClock clock;
  Frame frame;
  nlohmann::json& info = frame.info;
  info = {{"id", request.id},
          {"method", request.method},
          {"view", view_name(request.image)},
          {"width", request.view.camera.width},
          {"height", request.view.camera.height},
          {"warnings", request.warnings}};
  if (!(view_ == request.view)) {
    place_view(scene_, request.view, "request");
    view_ = request.view;
    ++view_count_;
  }
  // A moved light leaves the camera pass as it was: only a new camera draws it again.
  if (!surfaces_camera_ || !(*surfaces_camera_ == request.view.camera)) {
    surfaces_camera_.reset();
    render_visible_surfaces(scene_, ctx_, surfaces_);
    surfaces_camera_ = request.view.camera;
  }
  const VisibleSurfaceBuffer& surfaces = surfaces_;
  info["scan_ms"] = clock.lap();

  ShadowMethod& method = prepared(request.method, request.settings);
  info["prepare_ms"] = clock.lap();
  const std::vector<MethodRun> runs =
      run_prepared(method, scene_, surfaces, {}, ctx_, OnFailure::stop);
  for (const MethodRun& run : runs) info["lights"].push_back(light_info(run));
  info["method_ms"] = clock.lap();

  // raytrace's own masks are the reference when the method is raytrace as it always is.
  std::vector<MethodRun> raytrace_runs;
  const bool needs_reference = request.mismatch || request.image == FrameView::difference;
  const bool is_reference = request.method == "raytrace" && request.settings.values().empty();
  if (needs_reference && !is_reference) {
    raytrace_runs =
        run_prepared(prepared("raytrace", {}), scene_, surfaces, {}, ctx_, OnFailure::stop);
    info["reference_ms"] = clock.lap();
  }
  const std::vector<MethodRun>& reference = is_reference ? runs : raytrace_runs;
  if (request.mismatch) {
    const std::vector<std::uint32_t> objects = surfaces.object_ids();
    for (std::size_t l = 0; l < runs.size(); ++l) {
      const MaskComparison c = compare_masks(reference[l].mask, runs[l].mask, objects);
      info["lights"][l]["mismatch_raw_pct"] = c.raw_pct();
      info["lights"][l]["mismatch_interior_pct"] = c.interior_pct();
      info["lights"][l]["interior_pixels"] = c.interior_pixels;
    }
    info["compare_ms"] = clock.lap();
  }

  Image<Rgb8> image;
  switch (request.image) {
    case FrameView::shaded:
      image = shade_image(scene_, surfaces, masks_of(runs));
      break;
    case FrameView::mask:
      image = grey_image(runs[request.light].mask);
      break;
    case FrameView::difference:
      image = difference_image(reference[request.light].mask, runs[request.light].mask);
      break;
  }
  info["image_ms"] = clock.lap();
  frame.png = encode_png(image, PngSpeed::fast);
  info["encode_ms"] = clock.lap();
  info["png_bytes"] = frame.png.size();
  return frame;
}

std::string FrameRenderer::sun_hours(const sun::Site& site, const SunSpan& span,
                                     const Camera& camera) {
  std::lock_guard lock(mutex_);
  if (!(view_.camera == camera)) {
    place_view(scene_, {camera, view_.lights}, "request");
    view_.camera = camera;
    ++view_count_;
  }
  return encode_png(sun_hours_heat_map(scene_, site, span, ctx_), PngSpeed::fast);
}

}  // namespace shadowkit::viewer
