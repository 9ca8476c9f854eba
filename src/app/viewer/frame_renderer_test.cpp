// The viewer's frames against the commands' own pipeline, byte for byte, as the view, the
// method and its settings change between frames.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "shadowkit/app/pipeline.h"
#include "shadowkit/app/shading.h"
#include "shadowkit/app/viewer.h"
#include "shadowkit/core/error.h"
#include "shadowkit/methods/mask_compare.h"
#include "shadowkit/scene/scene_assembly.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit::viewer {
namespace {

// A built-in scene, whose working frame is not the world's, at a test's size.
Scene small_scene() {
  Scene scene = load_scene("cubes:27", {});
  SceneView view = world_view(scene);
  view.camera.width = 96;
  view.camera.height = 54;
  place_view(scene, view, "test");
  return scene;
}

FrameRequest request_for(const SceneView& view, const std::string& method,
                         FrameView image = FrameView::shaded) {
  FrameRequest request;
  request.view = view;
  request.method = method;
  request.settings = MethodOptions(method, {});
  request.image = image;
  return request;
}

// What `render` computes for \p view: one run per light, with a fresh method.
std::vector<MethodRun> render_runs(const SceneView& view, const std::string& method,
                                   const MethodOptions& settings = {}) {
  Scene scene = small_scene();
  place_view(scene, view, "test");
  const CameraPass pass = run_camera_pass(scene, {}, {});
  return run_method(scene, pass.surfaces, method, settings, {}, {}, OnFailure::stop);
}

std::string render_png(const SceneView& view, const std::string& method,
                       const MethodOptions& settings = {}) {
  Scene scene = small_scene();
  place_view(scene, view, "test");
  const CameraPass pass = run_camera_pass(scene, {}, {});
  const std::vector<MethodRun> runs =
      run_method(scene, pass.surfaces, method, settings, {}, {}, OnFailure::stop);
  return encode_png(shade_image(scene, pass.surfaces, masks_of(runs)), PngSpeed::fast);
}

SceneView moved(SceneView view) {
  view.camera.position = view.camera.position + Vec3{1.5, 0.5, -1};
  view.lights.push_back(Light::point(view.camera.look_at + Vec3{2, 6, 1}));
  return view;
}

TEST(FrameRenderer, ShadedFrameIsTheRenderCommandsImage) {
  FrameRenderer renderer(small_scene());
  const SceneView view = renderer.scene_view();
  for (const std::string method : {"raytrace", "volume", "svbsp", "angular"}) {
    SCOPED_TRACE(method);
    const std::optional<Frame> frame = renderer.render(request_for(view, method));
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->png, render_png(view, method));
    EXPECT_EQ(frame->info["method"], method);
    EXPECT_EQ(frame->info["lights"].size(), view.lights.size());
    EXPECT_GE(frame->info["scan_ms"].get<double>(), 0);
  }
}

TEST(FrameRenderer, ANewViewIsRenderedAsAFreshSceneWould) {
  FrameRenderer renderer(small_scene());
  const SceneView first = renderer.scene_view();
  const SceneView second = moved(first);
  for (const std::string method : {"volume", "shadowmap"}) {
    SCOPED_TRACE(method);
    const std::string before = renderer.render(request_for(first, method))->png;
    EXPECT_EQ(renderer.render(request_for(second, method))->png, render_png(second, method));
    EXPECT_EQ(renderer.render(request_for(first, method))->png, before);  // and back
    SceneView light_moved = first;  // the camera pass is kept, the light is not
    light_moved.lights[0] = Light::point(first.camera.look_at + Vec3{-3, 5, 2});
    EXPECT_EQ(renderer.render(request_for(light_moved, method))->png,
              render_png(light_moved, method));
  }
}

TEST(FrameRenderer, MaskAndDifferenceViews) {
  FrameRenderer renderer(small_scene());
  const SceneView view = moved(renderer.scene_view());
  const std::vector<MethodRun> runs = render_runs(view, "shadowmap");
  const std::vector<MethodRun> reference = render_runs(view, "raytrace");
  for (std::size_t light = 0; light < view.lights.size(); ++light) {
    FrameRequest mask = request_for(view, "shadowmap", FrameView::mask);
    mask.light = light;
    EXPECT_EQ(renderer.render(mask)->png, encode_png(grey_image(runs[light].mask), PngSpeed::fast));
    FrameRequest difference = request_for(view, "shadowmap", FrameView::difference);
    difference.light = light;
    EXPECT_EQ(
        renderer.render(difference)->png,
        encode_png(difference_image(reference[light].mask, runs[light].mask), PngSpeed::fast));
  }
}

TEST(FrameRenderer, MismatchAgainstRaytraceOnDemand) {
  FrameRenderer renderer(small_scene());
  FrameRequest request = request_for(renderer.scene_view(), "raytrace");
  request.mismatch = true;
  const Frame same = *renderer.render(request);
  EXPECT_EQ(same.info["lights"][0]["mismatch_interior_pct"], 0.0);
  EXPECT_FALSE(same.info.contains("reference_ms"));  // raytrace is its own reference
  request.method = "shadowmap";
  request.settings = MethodOptions("shadowmap", {{"resolution", "16"}});
  const Frame coarse = *renderer.render(request);
  EXPECT_GT(coarse.info["lights"][0]["mismatch_raw_pct"].get<double>(), 0);
  EXPECT_TRUE(coarse.info.contains("reference_ms"));
}

TEST(FrameRenderer, SettingsChangeTheMethodAndAreKeptApart) {
  FrameRenderer renderer(small_scene());
  const SceneView view = renderer.scene_view();
  // More settings than the renderer keeps prepared, then the first again.
  const std::vector<std::string> resolutions = {"16", "32", "64", "128", "256", "16"};
  for (const std::string& resolution : resolutions) {
    SCOPED_TRACE(resolution);
    FrameRequest request = request_for(view, "shadowmap");
    const MethodOptions settings("shadowmap", {{"resolution", resolution}});
    request.settings = settings;
    EXPECT_EQ(renderer.render(request)->png, render_png(view, "shadowmap", settings));
  }
}

// voxel's frame buffer is fitted to the view (voxel.bound=view): a new view prepares it again.
TEST(FrameRenderer, AMethodPreparedForOneViewIsPreparedAgain) {
  FrameRenderer renderer(small_scene());
  const SceneView first = renderer.scene_view();
  const MethodOptions settings("voxel", {{"resolution", "32"}});
  FrameRequest request = request_for(first, "voxel");
  request.settings = settings;
  renderer.render(request);
  request.view = moved(first);
  EXPECT_EQ(renderer.render(request)->png, render_png(request.view, "voxel", settings));
}

TEST(FrameRenderer, AbandonedFrameIsDropped) {
  FrameRenderer renderer(small_scene());
  int asked = 0;
  const auto gone_after = [&](int n) { return [&asked, n] { return ++asked > n; }; };
  EXPECT_FALSE(renderer.render(request_for(renderer.scene_view(), "volume"), gone_after(0)));
  EXPECT_EQ(asked, 1);
  asked = 0;
  EXPECT_TRUE(renderer.render(request_for(renderer.scene_view(), "volume"), gone_after(1)));
  EXPECT_EQ(asked, 1);  // asked once, when the renderer is free: a frame begun is finished
}

TEST(FrameRenderer, AMethodThatRefusesLeavesTheRendererWorking) {
  FrameRenderer renderer(small_scene());
  FrameRequest request = request_for(renderer.scene_view(), "voxel");
  request.settings = MethodOptions("voxel", {{"max_subpatches", "1"}});
  EXPECT_THAT([&] { renderer.render(request); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("voxel.max_subpatches")));
  EXPECT_TRUE(renderer.render(request_for(renderer.scene_view(), "volume")));
  FrameRequest far = request_for(renderer.scene_view(), "volume");
  far.view.camera.position = {1e20, 0, 0};  // past limits::kCoordinate scene sizes away
  EXPECT_THROW(renderer.render(far), InputError);
  EXPECT_TRUE(renderer.render(request_for(renderer.scene_view(), "volume")));
}

}  // namespace
}  // namespace shadowkit::viewer
