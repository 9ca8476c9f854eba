// Frame requests: what they take, and the one-line error naming the key for what they refuse.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "shadowkit/app/viewer.h"
#include "shadowkit/core/error.h"

namespace shadowkit::viewer {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

SceneView scene_view() {
  SceneView view;
  view.camera.width = 320;
  view.camera.height = 180;
  view.lights = {Light::point({1, 5, 2}), Light::directional({0, -1, 0})};
  return view;
}

void expect_refused(const std::string& text, const std::string& reason) {
  SCOPED_TRACE(text.substr(0, 200));
  EXPECT_THAT([&] { parse_frame_request(text, scene_view()); },
              ThrowsMessage<InputError>(HasSubstr(reason)));
}

TEST(FrameRequest, EmptyObjectIsTheScenesOwnViewWithRaytrace) {
  const FrameRequest r = parse_frame_request("{}", scene_view());
  EXPECT_EQ(r.view, scene_view());
  EXPECT_EQ(r.method, "raytrace");
  EXPECT_EQ(r.image, FrameView::shaded);
  EXPECT_FALSE(r.mismatch);
}

TEST(FrameRequest, ReadsEveryKey) {
  const FrameRequest r = parse_frame_request(
      R"({"id": 7, "camera": {"position": [1, 2, 3], "width": 64, "height": 32},
          "lights": [{"type": "point", "position": [0, 9, 0]}], "method": "shadowmap",
          "settings": {"resolution": 512, "pcf": "3"}, "view": "mask", "light": 0,
          "mismatch": true})",
      scene_view());
  EXPECT_EQ(r.id, 7);
  EXPECT_EQ(r.view.camera.position, (Vec3{1, 2, 3}));
  EXPECT_EQ(r.view.camera.width, 64);
  EXPECT_EQ(r.view.camera.look_at, scene_view().camera.look_at);  // kept
  ASSERT_EQ(r.view.lights.size(), 1u);
  EXPECT_EQ(r.view.lights[0].position, (Vec3{0, 9, 0}));
  EXPECT_EQ(r.method, "shadowmap");
  EXPECT_EQ(r.settings.values().at("resolution"), "512");
  EXPECT_EQ(r.settings.values().at("pcf"), "3");
  EXPECT_EQ(r.image, FrameView::mask);
  EXPECT_TRUE(r.mismatch);
}

TEST(FrameRequest, NoLightsIsAShadedFrameOfAmbientOnly) {
  const FrameRequest r = parse_frame_request(R"({"lights": []})", scene_view());
  EXPECT_TRUE(r.view.lights.empty());
  expect_refused(R"({"lights": [], "view": "mask"})", "request: key 'view': a mask or difference");
}

TEST(FrameRequest, UnknownKeysOfTheCameraAreWarnings) {
  const FrameRequest r = parse_frame_request(R"({"camera": {"zoom": 2}})", scene_view());
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_THAT(r.warnings[0], HasSubstr("request: key 'camera.zoom'"));
}

TEST(FrameRequest, RefusesWithTheKey) {
  expect_refused("", "request: is not valid JSON");
  expect_refused("{\"camera\": ", "request: is not valid JSON");
  expect_refused("[1, 2]", "request: expected one JSON object");
  expect_refused(R"({"colour": 1})", "request: key 'colour': unknown key");
  expect_refused(R"({"method": "nosuch"})", "unknown method");
  expect_refused(R"({"method": 3})", "request: key 'method': expected a method name");
  expect_refused(R"({"method": "volume", "settings": {"count": "both"}})", "volume.count");
  expect_refused(R"({"method": "volume", "settings": {"colour": "red"}})", "colour");
  expect_refused(R"({"settings": {"x": [1]}})", "request: key 'settings.x'");
  expect_refused(R"({"view": "x-ray"})", "request: key 'view': unknown view 'x-ray'");
  expect_refused(R"({"light": 2})", "request: key 'light': no light 2 among the frame's 2");
  expect_refused(R"({"light": 0.5})", "request: key 'light'");
  expect_refused(R"({"light": -1})", "request: key 'light'");
  expect_refused(R"({"mismatch": 1})", "request: key 'mismatch': expected true or false");
  expect_refused(R"({"id": "a"})", "request: key 'id': expected a number");
  expect_refused(R"({"camera": {"look_at": [0, 4, 12]}})", "request: key 'camera.look_at'");
  expect_refused(R"({"lights": [{"type": "spot"}]})", "request: key 'lights[0].type'");
  expect_refused(R"({"lights": [{"type": "point", "position": [1e300, 0, 0]}]})",
                 "request: key 'lights[0].position'");
}

TEST(FrameRequest, RefusesFramesBeyondTheLimits) {
  // A billion pixels is refused by the scene format's own side limit...
  expect_refused(R"({"camera": {"width": 31623, "height": 31623}})", "request: key 'camera.width'");
  // ... and a frame within it but past the viewer's 4K before any work.
  expect_refused(R"({"camera": {"width": 4096, "height": 4096}})",
                 "request: key 'camera': 4096x4096 is more than the viewer's 8294400 pixels");
  EXPECT_NO_THROW(
      parse_frame_request(R"({"camera": {"width": 3840, "height": 2160}})", scene_view()));
  std::string lights = R"({"lights": [)";
  for (std::size_t i = 0; i <= kMaxLights; ++i) {
    lights += std::string(i ? "," : "") + R"({"type": "point", "position": [0, 1, 0]})";
  }
  expect_refused(lights + "]}", "request: key 'lights': more than 16 lights");
  expect_refused("{\"id\": 1, \"x\": \"" + std::string(kMaxRequestBytes, 'a') + "\"}",
                 "request: larger than 65536 bytes");
}

TEST(FrameRequest, RefusesDeepNestingAsItReadsIt) {
  expect_refused(R"({"camera": {"position": [[[[[[[[[[1]]]]]]]]]]}})",
                 "request: nests deeper than any request");
  const std::string deep = std::string(30000, '[') + std::string(30000, ']');
  expect_refused(deep, "request: nests deeper than any request");
}

}  // namespace
}  // namespace shadowkit::viewer
