// What an input may ask for is bounded and checked up front; hostile or broken JSON ends in
// one clear line naming the file and the line or key. Each case here was found by fuzzing or
// by a reliability run.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "scene_file_test_fixture.h"
#include "shadowkit/scene/generators.h"

namespace shadowkit {
namespace {

using ::testing::HasSubstr;

std::string nested(int depth, const std::string& inner) {
  return std::string(depth, '[') + inner + std::string(depth, ']');
}

TEST_F(SceneFileTest, DeepNestingIsRefusedAtItsLineBeforeAnyRecursion) {
  // Thousands of levels once overflowed the stack in dump() and in a JSON copy.
  const std::string deep_up = scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0],
    "up": )" + nested(5000, "0"));
  EXPECT_EQ(error_of(deep_up),
            (dir_ / "scene.json").string() + ":3: JSON nested deeper than 100 levels");
  const std::string deep_generator =
      "{\"generator\": \"cubes\",\n\"extra\": " + nested(100000, "") + "}";
  EXPECT_EQ(error_of(deep_generator),
            (dir_ / "scene.json").string() + ":2: JSON nested deeper than 100 levels");
  // Brackets inside strings do not count.
  EXPECT_EQ(error_of("{\"camera\": {\"position\": [0, 4, 12], \"look_at\": [0, 0, 0]},\n"
                     "\"name\": \"" +
                     std::string(500, '[') + "\"}"),
            "no error");
}

TEST_F(SceneFileTest, NumbersBeyondDoubleAreMalformedJsonAtTheirLine) {
  const std::string file = (dir_ / "scene.json").string();
  EXPECT_EQ(error_of("{\n\"camera\": {\"fov_y_deg\": 1e309}}"),
            file + ":2: malformed JSON: number overflow parsing '1e309'");
  const std::string digits(400, '9');
  const std::string message = error_of("{\"camera\": {\"width\": " + digits + "}}");
  EXPECT_THAT(message, HasSubstr(file + ":1: malformed JSON: number overflow parsing '999"));
  EXPECT_LT(message.size(), file.size() + 200) << "the 400 digits are cut short";
}

TEST_F(SceneFileTest, HugeValuesAreDescribedNotDumped) {
  std::string big = "[";
  for (int i = 0; i < 1000; ++i) big += (i ? ", " : "") + std::to_string(i);
  big += "]";
  EXPECT_THAT(error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0], "up": )" + big)),
              HasSubstr("key 'camera.up': expected an array of three numbers, got an array of "
                        "1000 values"));
}

TEST_F(SceneFileTest, AGeneratorSpecInASceneFileNamesTheFileAndKey) {
  EXPECT_EQ(error_of(R"({"generator": "cubes:2:3"})"),
            (dir_ / "scene.json").string() +
                ": key 'generator': '2:3' is not a valid count (expected an integer, e.g. "
                "cubes:2000)");
}

TEST_F(SceneFileTest, ImagesAreBoundedInPixels) {
  EXPECT_THAT(error_of("{\"camera\": {\"position\": [0, 4, 12], \"look_at\": [0, 0, 0], "
                       "\"width\": 16384, \"height\": 16384}}"),
              HasSubstr("key 'camera': 16384x16384 makes 268435456 pixels; at most 33554432 are "
                        "allowed"));
  EXPECT_THAT(error_of("{\"camera\": {\"position\": [0, 4, 12], \"look_at\": [0, 0, 0], "
                       "\"width\": 16385}}"),
              HasSubstr("key 'camera.width': expected a whole number from 1 to 16384, got 16385"));
}

// Every light's mask is held at once: a short file of many lights asked for gigabytes.
TEST_F(SceneFileTest, LightsAreBoundedByTheirMasksPixels) {
  auto with_lights = [](int count) {
    std::string lights;
    for (int i = 0; i < count; ++i) {
      lights += std::string(i ? ", " : "") + R"({"type": "directional", "direction": [0, -1, 0]})";
    }
    // The default image, 1920x1080.
    return R"({"camera": {"position": [0, 4, 12], "look_at": [0, 0, 0]}, "lights": [)" + lights +
           "]}";
  };
  EXPECT_THAT(error_of(with_lights(1036)),
              HasSubstr("key 'lights': 1036 lights of 2073600 pixels each make more than "
                        "2147483648 mask pixels; at most 1035 lights fit this image"));
  EXPECT_EQ(error_of(with_lights(1035)), "no error");
}

// A fine tessellation of a large control mesh once asked for 108 million triangles and ran
// out of memory after two minutes, naming the wrong setting.
TEST_F(SceneFileTest, TessellationIsRefusedBeforeItIsBuilt) {
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THAT(error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                             R"({"type": "point", "position": [3, 10, 4]})",
                             R"({"generator": "sphere", "segments": 64, "rings": 32,
                         "subdivision": "catmull-clark", "tessellation": 256})")),
              HasSubstr("key 'objects[0].tessellation': 256 segments on 8064 patches would make "
                        "1056964608 triangles; at most 16777216 are allowed"));
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
}

TEST_F(SceneFileTest, GeometryFarFromItsSizeIsRefused) {
  EXPECT_THAT(
      error_of(
          scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                R"({"type": "point", "position": [3, 10, 4]})",
                R"({"generator": "box", "size": 1e-6, "transform": {"translate": [1e9, 0, 0]}})")),
      HasSubstr(": the geometry is 1e-06 across but lies 1e+09 from the origin"));
  // A camera a million billion scene sizes away cannot see it.
  EXPECT_THAT(error_of(scene(R"("position": [0, 0, 1e14], "look_at": [0, 0, 0])",
                             R"({"type": "point", "position": [3, 10, 4]})",
                             R"({"generator": "box", "size": 1e-3})")),
              HasSubstr("key 'camera.position': lies more than 1e15 times the scene's size away "
                        "from it"));
}

// Camera checks are relative to the camera's own coordinates and vectors, never absolute.
TEST_F(SceneFileTest, ACameraInTinyUnitsIsAsGoodAsOneInMetres) {
  EXPECT_EQ(error_of(scene(R"("position": [0, 4e-13, 12e-13], "look_at": [0, 0, 0],
                              "up": [0, 1e-20, 0])",
                           R"({"type": "point", "position": [3e-13, 10e-13, 4e-13]})",
                           R"({"generator": "box", "size": 1e-13})")),
            "no error");
}

TEST(BuiltinScenes, SizesBeyondTheCoordinateRangeAreRefused) {
  for (const char* spec : {"room:1e20", "room:1e300"}) {
    EXPECT_THAT([&] { make_builtin_scene(spec, {}); },
                ::testing::ThrowsMessage<InputError>(
                    HasSubstr("scene '" + std::string(spec) +
                              "': a vertex lies beyond +-1e15, which is not supported")));
  }
  EXPECT_THAT([] { make_builtin_scene("room:1e-300", {}); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("below 1e-290")));
  // Far from those ends, the scene's size does not matter.
  const Context quiet{.threads = 0, .warn = [](const std::string&) {}};
  EXPECT_EQ(make_builtin_scene("room:1e-200", quiet).face_count(),
            make_builtin_scene("room:1e12", quiet).face_count());
}

}  // namespace
}  // namespace shadowkit
