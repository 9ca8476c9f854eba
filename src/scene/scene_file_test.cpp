#include "shadowkit/scene/scene_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "scene_file_test_fixture.h"
#include "shadowkit/core/error.h"

namespace shadowkit {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

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
  EXPECT_DOUBLE_EQ(s.world_bounds().hi.x, 10);
  EXPECT_DOUBLE_EQ(s.world_bounds().lo.y, 1);
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
              HasSubstr("key 'objects[0]': a vertex lies beyond +-1e15"));
  EXPECT_THAT(error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                             R"({"type": "point", "position": [3, 10, 4]})",
                             R"({"mesh": "ground.obj", "transform": {"scale": [1, 0, 1]}})")),
              HasSubstr("key 'objects[0].transform.scale': a zero scale"));
  EXPECT_THAT(
      error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0], "fov_y_deg": 1e-300)")),
      HasSubstr("key 'camera.fov_y_deg': must lie between"));
}

// Values that would otherwise be skipped, leaving a default camera or an untransformed
// object where the file meant something else.
TEST_F(SceneFileTest, ValuesOfTheWrongKindAreRejectedNotSkipped) {
  EXPECT_THAT(error_of(scene(R"("look_at": [0, 0, 0])")),
              HasSubstr("key 'camera.position': is missing"));
  EXPECT_THAT(error_of(scene(R"("position": [0, 4, 12])")),
              HasSubstr("key 'camera.look_at': is missing"));
  EXPECT_THAT(error_of(R"({"camera": 5, "lights": []})"),
              HasSubstr("key 'camera': expected an object, got number"));
  for (const std::string transform : {"[1]", "null", "2"}) {
    EXPECT_THAT(error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                               R"({"type": "point", "position": [3, 10, 4]})",
                               R"({"mesh": "ground.obj", "transform": )" + transform + "}")),
                HasSubstr("key 'objects[0].transform': expected an object"));
  }
  EXPECT_THAT(error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                             R"({"type": "point", "position": [3, 10, 4]})", R"({"mesh": ""})")),
              HasSubstr("key 'objects[0].mesh': is an empty path"));
}

TEST_F(SceneFileTest, MisspeltTransformKeysAreWarnedAbout) {
  std::vector<std::string> warnings;
  const Context ctx{0, [&](const std::string& m) { warnings.push_back(m); }};
  const Scene s = load_scene_file(
      write("scene.json", scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                                R"({"type": "point", "position": [3, 10, 4]})",
                                R"({"mesh": "ground.obj", "transform": {"rotate": [90, 0, 0],
                                                  "translate": [0, 1, 0]}})")),
      ctx);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("key 'objects[0].transform.rotate' is not part of the "
                                     "scene format; ignored"));
  EXPECT_DOUBLE_EQ(s.world_bounds().lo.y, 1);
  EXPECT_DOUBLE_EQ(s.world_bounds().hi.x, 5);
}

// nlohmann keeps the last of two equal keys; the first would be dropped unseen.
TEST_F(SceneFileTest, AKeyGivenTwiceInOneObjectIsRejectedByItsPath) {
  EXPECT_THAT(error_of(R"({"camera": {"position": [0, 4, 12], "look_at": [0, 0, 0]},
                           "camera": {"position": [0, 1, 12], "look_at": [0, 0, 0]}})"),
              HasSubstr("scene.json: key 'camera': is given twice in one object"));
  EXPECT_THAT(error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                             R"({"type": "point", "position": [3, 10, 4]},
                                {"type": "directional", "direction": [0, -1, 0], "type": "point"})")),
              HasSubstr("key 'lights[1].type': is given twice in one object"));
  // Equal keys in different objects are no repetition.
  EXPECT_EQ(error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                           R"({"type": "point", "position": [3, 10, 4]},
                              {"type": "point", "position": [3, 10, 5]})")),
            "no error");
}

// A direction's length may overflow or underflow double; its sense is still well defined.
TEST_F(SceneFileTest, DirectionsOfAnyMagnitudeKeepTheirSense) {
  const Scene s = load_scene_file(
      write("scene.json",
            scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0], "up": [0, 1e-300, 0])",
                  R"({"type": "directional", "direction": [1e300, -1e300, 0]},
                     {"type": "directional", "direction": [3e-170, -1e-170, 0]})")),
      quiet_);
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_DOUBLE_EQ(s.lights[0].direction.x, std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(s.lights[0].direction.y, -std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(s.lights[1].direction.x, 3 / std::sqrt(10.0));
  EXPECT_DOUBLE_EQ(s.lights[1].direction.y, -1 / std::sqrt(10.0));
  EXPECT_DOUBLE_EQ(s.camera.right().x, 1);
}

// The cube [0, 1]^3 as an OBJ control mesh, faces outward.
constexpr const char* kCubeObj =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
    "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";

std::string object(const std::string& keys) {
  return R"({"mesh": "cube.obj", )" + keys + "}";
}

TEST_F(SceneFileTest, CatmullClarkObjectsAreTessellatedLimitSurfaces) {
  write("cube.obj", kCubeObj);
  const std::string camera = R"("position": [0, 4, 12], "look_at": [0, 0, 0])";
  const std::string light = R"({"type": "point", "position": [3, 10, 4]})";
  const Scene s = load_scene_file(
      write("scene.json", scene(camera, light,
                                object(R"("subdivision": "catmull-clark", "transform": {"scale": 2,
                             "translate": [0, 1, 0]})") +
                                    R"(, {"generator": "box", "subdivision": "catmull-clark",
                            "tessellation": 2}, {"mesh": "ground.obj"})")),
      quiet_);
  ASSERT_EQ(s.objects.size(), 3u);
  const SceneObject& cube = s.objects[0];
  ASSERT_NE(cube.subdivision, nullptr);
  EXPECT_EQ(cube.subdivision->patch_count(), 24u);
  // Fitted to the view by default.
  const Scene fitted = load_scene_file(
      write("fitted.json",
            scene(camera, light, object(R"("subdivision": "catmull-clark", "tessellation": "view",
                            "transform": {"scale": 2, "translate": [0, 1, 0]})"))),
      quiet_);
  EXPECT_EQ(cube.mesh.face_count(), fitted.objects[0].mesh.face_count());
  EXPECT_NE(cube.mesh.face_count(), 24u * 8 * 8 * 2);
  EXPECT_TRUE(cube.mesh.closed());
  // The transform moved the control points: the limit surface is the unit cube's, scaled
  // by 2 about the origin and raised by 1, so its centre sits at (1, 2, 1).
  const Bounds3 working = cube.mesh.bounds();
  const Bounds3 box{s.frame.to_world(working.lo), s.frame.to_world(working.hi)};
  EXPECT_NEAR(box.center().x, 1, 1e-12);
  EXPECT_NEAR(box.center().y, 2, 1e-12);
  EXPECT_GT(box.lo.y, 1);
  EXPECT_LT(box.hi.y, 3);
  EXPECT_EQ(s.objects[1].mesh.face_count(), 24u * 2 * 2 * 2);
  EXPECT_EQ(s.objects[2].subdivision, nullptr);
}

// "tessellation": "view" fits the cells to the camera (64 x 48 pixels here): seen from close,
// the cube needs many cells a patch; from 120 away, half a pixel holds a whole patch.
TEST_F(SceneFileTest, TessellationForTheViewFollowsTheCamera) {
  write("cube.obj", kCubeObj);
  const std::string light = R"({"type": "point", "position": [3, 10, 4]})";
  const auto cube_faces = [&](const std::string& position) {
    const Scene s = load_scene_file(
        write("scene.json",
              scene(R"("position": )" + position + R"(, "look_at": [0, 0, 0])", light,
                    object(R"("subdivision": "catmull-clark", "tessellation": "view")"))),
        quiet_);
    EXPECT_TRUE(s.objects[0].mesh.closed());
    return s.objects[0].mesh.face_count();
  };
  EXPECT_GT(cube_faces("[0, 1, 2.5]"), 24u * 2 * 2 * 2);
  EXPECT_EQ(cube_faces("[0, 40, 120]"), 24u * 2);
}

TEST_F(SceneFileTest, BadSubdivisionKeysAreRejected) {
  write("cube.obj", kCubeObj);
  const std::string camera = R"("position": [0, 4, 12], "look_at": [0, 0, 0])";
  const std::string light = R"({"type": "point", "position": [3, 10, 4]})";
  auto error = [&](const std::string& keys) {
    return error_of(scene(camera, light, object(keys)));
  };
  EXPECT_THAT(error(R"("subdivision": "loop")"),
              HasSubstr("key 'objects[0].subdivision': unknown scheme 'loop' (expected "
                        "\"catmull-clark\")"));
  EXPECT_THAT(error(R"("subdivision": true)"), HasSubstr("key 'objects[0].subdivision'"));
  for (const char* bad : {"0", "2.5", "1000", "\"8\"", "\"fine\"", "-1"}) {
    EXPECT_THAT(error(std::string(R"("subdivision": "catmull-clark", "tessellation": )") + bad),
                HasSubstr("key 'objects[0].tessellation'"));
  }
  EXPECT_THAT(error(R"("tessellation": 4)"),
              HasSubstr("key 'objects[0].tessellation': applies only with \"subdivision\""));
}

TEST_F(SceneFileTest, BadControlMeshesNameTheFileAndObject) {
  // A fourth face on the cube's edge from vertex 1 to vertex 2.
  write("cube.obj", std::string(kCubeObj) + "v 0.5 -1 -1\nf 2 1 9\n");
  EXPECT_THAT(error_of(scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                             R"({"type": "point", "position": [3, 10, 4]})",
                             object(R"("subdivision": "catmull-clark")"))),
              HasSubstr("scene.json: key 'objects[0]' (cube): the control mesh is not manifold"));
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

TEST_F(SceneFileTest, ADirectoryOrADeviceIsNoSceneFile) {
  EXPECT_THAT([&] { load_scene(dir_.string(), quiet_); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("is a directory, not a scene file")));
  EXPECT_THAT([&] { load_scene("/dev/null", quiet_); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr("/dev/null: is not a regular file (a device or a pipe)")));
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

// The sun study names polygons by the scene file's objects entry and the face as read.
TEST_F(SceneFileTest, ObjectsKnowTheirEntryAndFirstInputFace) {
  write("two.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2\nf 1 2 3\n");
  const fs::path p =
      write("scene.json", scene(R"("position": [0, 4, 12], "look_at": [0, 0, 0])",
                                R"({"type": "point", "position": [3, 10, 4]})",
                                R"({"mesh": "two.obj"}, {"generator": "cubes", "count": 2},
                             {"generator": "box"})"));
  const Scene s = load_scene_file(p, quiet_);
  // two.obj; the cubes scene's cubes and ground; the box.
  ASSERT_EQ(s.objects.size(), 4u);
  EXPECT_EQ(s.objects[0].input_object, 0u);
  EXPECT_EQ(s.objects[0].mesh.input_faces, std::vector<std::uint32_t>{1});
  EXPECT_EQ(s.objects[0].mesh.input_face_count(), 2u);
  EXPECT_EQ(s.objects[1].input_object, 1u);
  EXPECT_EQ(s.objects[1].input_first_face, 0u);
  EXPECT_EQ(s.objects[2].input_object, 1u);
  EXPECT_EQ(s.objects[2].input_first_face, s.objects[1].mesh.input_face_count());
  EXPECT_EQ(s.objects[3].input_object, 2u);
  EXPECT_EQ(s.objects[3].input_first_face, 0u);
  EXPECT_EQ(s.objects[3].mesh.input_face_count(), 6u);
}

}  // namespace
}  // namespace shadowkit
