#include "shadowkit/scene/scene_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "shadowkit/core/error.h"

namespace shadowkit {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class SceneFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("shadowkit_scene_file_" +
            std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    write("ground.obj", "v -5 0 -5\nv 5 0 -5\nv 5 0 5\nv -5 0 5\nf 1 4 3 2\n");
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }

  // A valid scene with one substitution applied.
  std::string scene(const std::string& camera = R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                    const std::string& lights = R"({"type": "point", "position": [3, 10, 4]})",
                    const std::string& objects = R"({"mesh": "ground.obj"})") {
    return "{\n  \"camera\": {" + camera + ", \"width\": 64, \"height\": 48},\n  \"lights\": [" +
           lights + "],\n  \"objects\": [" + objects + "]\n}\n";
  }

  std::string error_of(const std::string& text) {
    const fs::path p = write("scene.json", text);
    try {
      load_scene_file(p, quiet_);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }

  fs::path dir_;
  Context quiet_{0, [](const std::string&) {}};
};

TEST_F(SceneFileTest, LoadsCameraLightsAndTransformedMeshes) {
  const fs::path p =
      write("scene.json", scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                                R"({"type": "directional", "direction": [0, -2, 0]})",
                                R"({"mesh": "ground.obj", "transform": {"scale": 2,
                                                  "translate": [0, 1, 0]}})"));
  const Scene s = load_scene_file(p, quiet_);
  EXPECT_EQ(s.camera.width, 64);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].type, Light::Type::directional);
  EXPECT_DOUBLE_EQ(s.lights[0].direction.y, -1);
  EXPECT_EQ(s.face_count(), 1u);
  EXPECT_DOUBLE_EQ(s.bounds().hi.x, 10);
  EXPECT_DOUBLE_EQ(s.bounds().lo.y, 1);
}

TEST_F(SceneFileTest, MissingFileNamesIt) {
  try {
    load_scene_file(dir_ / "nope.json", quiet_);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("nope.json: cannot open scene file"));
  }
}

TEST_F(SceneFileTest, MalformedJsonNamesTheLine) {
  EXPECT_THAT(error_of("{\n  \"camera\": {\n    \"position\": [0, 1,, 2]\n  }\n}\n"),
              HasSubstr("scene.json:3: malformed JSON"));
}

TEST_F(SceneFileTest, WrongKeyTypeNamesTheKey) {
  EXPECT_THAT(
      error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0], "fov_y_deg": "wide")")),
      HasSubstr("key 'camera.fov_y_deg': expected a number, got string"));
  EXPECT_THAT(error_of(scene(R"("position": [0, 4], "look_at": [0, 0, 0])")),
              HasSubstr("key 'camera.position': expected an array of three numbers"));
  EXPECT_THAT(error_of(R"({"camera": {"position": [0, 4, 12], "look_at": [0, 0, 0],
                                     "width": 10.5}, "lights": []})"),
              HasSubstr("key 'camera.width': expected a whole number"));
}

TEST_F(SceneFileTest, CameraLookingAtItsOwnPositionIsRejected) {
  EXPECT_THAT(error_of(scene(R"("position": [1, 2, 3], "look_at": [1, 2, 3])")),
              HasSubstr("key 'camera.look_at': equals camera.position"));
  EXPECT_THAT(error_of(scene(R"("position": [0, 5, 0], "look_at": [0, 0, 0])")),
              HasSubstr("parallel to the view direction"));
}

TEST_F(SceneFileTest, BadLightsAreRejected) {
  EXPECT_THAT(error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                             R"({"type": "spot", "position": [0, 1, 0]})")),
              HasSubstr("key 'lights[0].type': unknown light type 'spot'"));
  EXPECT_THAT(error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                             R"({"type": "directional", "direction": [0, 0, 0]})")),
              HasSubstr("key 'lights[0].direction': is the zero vector"));
  EXPECT_THAT(
      error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])", R"({"type": "point"})")),
      HasSubstr("key 'lights[0].position': is missing"));
}

TEST_F(SceneFileTest, MeshErrorsNameTheMeshFileAndLine) {
  write("nan.obj", "v 0 0 0\nv 1 0 nan\nv 0 0 1\nf 1 2 3\n");
  EXPECT_THAT(
      error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                     R"({"type": "point", "position": [3, 10, 4]})", R"({"mesh": "nan.obj"})")),
      HasSubstr("nan.obj:2"));
  EXPECT_THAT(
      error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                     R"({"type": "point", "position": [3, 10, 4]})", R"({"mesh": "missing.obj"})")),
      HasSubstr("missing.obj"));
  EXPECT_THAT(error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                             R"({"type": "point", "position": [3, 10, 4]})", R"({"size": 3})")),
              HasSubstr("key 'objects[0]': needs a \"mesh\" file or a \"generator\""));
}

TEST_F(SceneFileTest, OverflowingTransformIsRejected) {
  EXPECT_THAT(error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                             R"({"type": "point", "position": [3, 10, 4]})",
                             R"({"mesh": "ground.obj", "transform": {"scale": 1e308}})")),
              HasSubstr("key 'objects[0]': after its transform, a vertex lies beyond +-1e15"));
  EXPECT_THAT(error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                             R"({"type": "point", "position": [3, 10, 4]})",
                             R"({"mesh": "ground.obj", "transform": {"scale": [1, 0, 1]}})")),
              HasSubstr("key 'objects[0].transform.scale': a zero scale"));
  EXPECT_THAT(
      error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0], "fov_y_deg": 1e-300)")),
      HasSubstr("key 'camera.fov_y_deg': must lie between"));
}

TEST_F(SceneFileTest, SubdivisionSurfacesAreRefusedRatherThanDrawnWrong) {
  EXPECT_THAT(error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                             R"({"type": "point", "position": [3, 10, 4]})",
                             R"({"mesh": "ground.obj", "subdivision": "catmull-clark"})")),
              HasSubstr("key 'objects[0].subdivision'"));
}

TEST_F(SceneFileTest, TopLevelGeneratorTakesItsParametersFromTheFile) {
  const Scene s =
      load_scene_file(write("scene.json", R"({"generator": "cubes", "count": 8})"), quiet_);
  EXPECT_EQ(s.face_count(), 8u * 6 + 1);
  EXPECT_EQ(
      load_scene_file(write("scene.json", R"({"generator": "tetra:2"})"), quiet_).face_count(),
      66u);
  EXPECT_THAT(error_of(R"({"generator": "cubes", "cuont": 8})"), HasSubstr("cuont"));
}

TEST_F(SceneFileTest, UnknownSceneNameListsTheBuiltIns) {
  try {
    load_scene("no-such-scene", quiet_);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("no-such-scene: no such scene file or built-in scene"));
    EXPECT_THAT(e.what(), HasSubstr("cubes"));
  }
}

TEST_F(SceneFileTest, UnknownKeysAreWarnedAbout) {
  std::vector<std::string> warnings;
  const Context ctx{0, [&](const std::string& m) { warnings.push_back(m); }};
  std::string text = scene();
  text.insert(1, "\"camra\": {},");
  load_scene_file(write("scene.json", text), ctx);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("key 'camra' is not part of the scene format"));
}

}  // namespace
}  // namespace shadowkit
