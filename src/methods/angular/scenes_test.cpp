#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "angular_method.h"
#include "shadowkit/core/error.h"
#include "shadowkit/scene/scene_file.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"

namespace shadowkit::angular {
namespace {

Scene reduced(Scene scene) {
  return testing::resized(std::move(scene), 480, 270);
}

// Worst interior mismatch (percent) of `angular` against `raytrace` over the lights.
double worst_interior_mismatch(const Scene& scene, const MethodOptions& options = {}) {
  return testing::worst_interior_mismatch(scene, "angular", options);
}

class AngularBuiltInScene : public ::testing::TestWithParam<const char*> {};

TEST_P(AngularBuiltInScene, AgreesWithTheReference) {
  EXPECT_LE(worst_interior_mismatch(reduced(load_scene(GetParam(), {}))), 0.2);
}

INSTANTIATE_TEST_SUITE_P(Angular, AngularBuiltInScene,
                         ::testing::Values("cubes:125", "tetra:3", "table", "three-lights",
                                           "square", "room", "coil", "holed", "hole-like"));

// An open half cylinder of thin strips, bulging toward the camera, lit from the side so
// that its terminator runs down the middle.
Scene open_half_cylinder() {
  PolygonSoup soup;
  constexpr int kStrips = 64;
  for (int i = 0; i <= kStrips; ++i) {
    const double a = std::numbers::pi * i / kStrips;
    soup.positions.push_back({std::cos(a), -1, std::sin(a)});
    soup.positions.push_back({std::cos(a), 1, std::sin(a)});
  }
  for (std::uint32_t i = 0; i < kStrips; ++i) {
    soup.add_face({2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1});
  }
  return testing::make_scene(testing::camera({0, 0.3, 4}, {0, 0, 0}, 320, 240),
                             {testing::point_light({-3, 2, 0.3})}, {soup});
}

// A convex surface never shadows itself: every other strip lies behind a strip's plane,
// where the ray to the light does not go. A pair cut at the entry's centre reaches half
// an entry past its strip onto the lit neighbour; it must not shadow it, however coarse R.
TEST(AngularScenes, AConvexOpenSurfaceDoesNotShadowItselfAtCoarseTheta) {
  const Scene scene = open_half_cylinder();
  for (const char* r : {"20", "99"}) {
    const MethodOptions options("angular", {{"resolution", r}});
    EXPECT_LE(worst_interior_mismatch(scene, options), 0.01) << r;
  }
}

// Sec. 3 / Figs. 6-7: R trades quality for speed; the error falls as R grows.
TEST(AngularScenes, MismatchFallsAsTheThetaResolutionGrows) {
  const Scene scene = reduced(load_scene("table", {}));
  double previous = 100;
  for (const char* r : {"99", "299", "599"}) {
    const MethodOptions options("angular", {{"resolution", r}});
    const double mismatch = worst_interior_mismatch(scene, options);
    EXPECT_LT(mismatch, previous) << r;
    previous = mismatch;
  }
  EXPECT_GT(worst_interior_mismatch(scene, {"angular", {{"resolution", "99"}}}), 0.05);
}

// Sec. 10: dropping covered pairs shrinks the table and leaves the mask alone.
TEST(AngularScenes, TheSaturatedTableGivesTheSameMask) {
  const Scene scene = reduced(load_scene("tetra:3", {}));
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  AngularMethod saturated({});
  AngularMethod full(MethodOptions("angular", {{"saturated", "0"}}));
  const ShadowMask a = testing::method_mask(saturated, scene, vsb, 0);
  const ShadowMask b = testing::method_mask(full, scene, vsb, 0);
  EXPECT_GT(testing::counter(saturated, "saturated_pairs"), 0);
  EXPECT_LT(testing::counter(saturated, "table_pairs"), testing::counter(full, "table_pairs"));
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) differ += a.pixels[i] != b.pixels[i];
  EXPECT_EQ(differ, 0u);
}

// Sec. 10 under a light 1e-4 above the ground: the ground is nearly edge-on to it, nearer
// than a box's far sheet at an entry's centre theta and far beyond it at a bound, so it
// must not drop the box's pairs (it did: 42% of the pixels came out lit).
TEST(AngularScenes, SaturationHoldsAcrossTheWholeEntryUnderAGrazingLight) {
  const Scene scene = load_scene_file(
      std::string(SHADOWKIT_SOURCE_DIR) + "/examples/sweep/angular-saturation-grazing-light.json",
      {});
  EXPECT_LE(worst_interior_mismatch(scene), 0.2);
}

// Sec. 7: one lookup serves a run of pixels.
TEST(AngularScenes, OneLookupServesManyPixels) {
  const Scene scene = reduced(load_scene("cubes:125", {}));
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  AngularMethod angular({});
  testing::method_mask(angular, scene, vsb, 0);
  const double lookups = testing::counter(angular, "lookup_calls");
  EXPECT_GT(lookups, 0);
  EXPECT_LT(lookups * 4, double(vsb.covered_count()));
}

// A box on a ground and an open square above it, everything scaled by \p s about the
// origin; the light, at the height of the box's top, lies in that face's plane.
Scene scaled_box_scene(double s, Light light) {
  const Camera cam = testing::camera(Vec3{6, 5, 7} * s, {0, 0, 0}, 160, 120);
  return testing::make_scene(
      cam, {light},
      {testing::horizontal_quad(-10 * s, 10 * s, -10 * s, 10 * s, 0),
       testing::box(Vec3{-1, 0.2, -1} * s, Vec3{1, 1.2, 1} * s),
       testing::horizontal_quad(-0.5 * s, 1.5 * s, 1.5 * s, 2.5 * s, 2 * s)});
}

// Degenerate cases: tiny and huge coordinates, a light in a face's plane, a directional
// light grazing that face; the tolerances scale with the scene.
TEST(AngularScenes, TinyHugeAndGrazingCasesAgreeWithTheReference) {
  for (const double s : {1e-4, 1.0, 1e4}) {
    for (const Light& light :
         {Light::point(Vec3{-2, 1.2, 1} * s), Light::directional(normalize(Vec3{0.3, -1, -0.2})),
          Light::directional(normalize(Vec3{0.5, 0, -1}))}) {
      const Scene scene = scaled_box_scene(s, light);
      EXPECT_LE(worst_interior_mismatch(scene), 0.2) << "scale " << s;
    }
  }
}

// A directional light travelling along the camera's right axis or along -right (a sun on
// the horizon in the east or the west, seen by a camera looking north) lies in every plane
// holding that axis: its theta-planes also hold the forward axis (light_frame.cpp). Turned
// off the axis by a tiny angle, toward the camera's down or forward axis, it gets the usual
// theta-planes through the axis and the light, whichever way it leaves the axis.
TEST(AngularScenes, ALightAlongTheCamerasRightAxisAgreesWithTheReference) {
  std::vector<Scene> scenes;
  for (const char* name : {"tetra:3", "coil", "cubes:125", "table"}) {
    scenes.push_back(reduced(load_scene(name, {})));
  }
  scenes.push_back(
      reduced(load_scene_file(std::string(SHADOWKIT_SOURCE_DIR) + "/examples/default.json", {})));
  for (const Scene& original : scenes) {
    const Camera& cam = original.camera;
    std::vector<Vec3> directions;
    for (const double sign : {1.0, -1.0}) {
      const Vec3 axis = cam.right() * sign;
      directions.push_back(axis);
      for (const Vec3 toward : {-cam.true_up(), cam.forward()}) {
        for (const double angle : {1e-7, 1e-4}) {
          directions.push_back(axis * std::cos(angle) + toward * std::sin(angle));
        }
      }
    }
    for (const Vec3 d : directions) {
      Scene scene = original;
      // d is a unit vector already: renormalizing it could round it off the axis.
      scene.lights = {Light{Light::Type::directional, {}, d}};
      EXPECT_LE(worst_interior_mismatch(scene), 0.2)
          << scene.name << " light " << d.x << " " << d.y << " " << d.z;
    }
  }
}

// A box beside a point light holds the light's X axis in its shadow, so its RE loop goes
// all around theta and one of its REs passes theta = +-pi. The table is cut to the theta
// the camera sees, which lies within (-pi, pi]: the part of that RE past pi starts the
// table (it was dropped, and a strip of the ground beside the box came out lit).
TEST(AngularScenes, AnREPastThetaPiSlicesTheStartOfATableCutToTheView) {
  const Scene scene =
      testing::make_scene(testing::camera({-1.95, 3.59, -2.55}, {-0.42, 0.2, -0.29}, 320, 240, 40),
                          {testing::point_light({1.84, 1.48, -0.65})},
                          {testing::horizontal_quad(-6, 6, -6, 6, 0),
                           testing::box({0.22, 0, 0.25}, {2.02, 1.8, 2.05})});
  EXPECT_LE(worst_interior_mismatch(scene), 0.2);
}

// Sec. 11.2: the light inside the room, moved into the camera's own plane (beside and
// above the eye, at its depth) and just in front of and behind it: the light's X axis then
// runs along the edge of the view, where theta wraps around the light.
TEST(AngularScenes, ALightInTheRoomNearTheCamerasPlaneAgreesWithTheReference) {
  const Scene room = reduced(load_scene("room", {}));
  const Camera& cam = room.camera;
  for (const double depth : {-0.05, 0.0, 0.05}) {
    Scene scene = room;
    scene.lights[0].position =
        cam.position + cam.right() * -0.5 + cam.true_up() * 0.8 + cam.forward() * depth;
    EXPECT_LE(worst_interior_mismatch(scene), 0.2) << "depth " << depth;
  }
}

TEST(AngularScenes, RejectsAResolutionThatIsNotAWholeNumber) {
  EXPECT_THROW(AngularMethod(MethodOptions("angular", {{"resolution", "2.5"}})), InputError);
  EXPECT_THROW(AngularMethod(MethodOptions("angular", {{"bias", "1"}})), InputError);
  EXPECT_THROW(AngularMethod(MethodOptions("angular", {{"saturated", "2"}})), InputError);
  EXPECT_THROW(AngularMethod(MethodOptions("angular", {{"resolution", "-1"}})), InputError);
}

// The smallest failing scenes of the mismatch sweep (scripts/mismatch_sweep.py): grazing
// lights, a light inside touching boxes, an eye inside a box.
TEST(AngularScenes, EverySweepExampleAgreesWithTheReference) {
  const std::filesystem::path dir =
      std::filesystem::path(SHADOWKIT_SOURCE_DIR) / "examples" / "sweep";
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    EXPECT_LE(worst_interior_mismatch(load_scene_file(entry.path(), {})), 0.2)
        << entry.path().filename();
    ++checked;
  }
  EXPECT_GE(checked, 11);
}

TEST(AngularScenes, EveryExampleAgreesWithTheReference) {
  const std::filesystem::path dir = std::filesystem::path(SHADOWKIT_SOURCE_DIR) / "examples";
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    // A finely tessellated open curved surface (the subdivision example's open box) loses
    // most to the half-entry reach of its own far sheet's pairs (docs/methods/angular.md):
    // 0.22% at 480x270 with the automatic R, 0.04% at its own 1280x720, so it is checked at
    // its own resolution.
    Scene scene = load_scene_file(entry.path(), {});
    if (entry.path().stem() != "subdivision") scene = reduced(std::move(scene));
    EXPECT_LE(worst_interior_mismatch(scene), 0.2) << entry.path().filename();
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

}  // namespace
}  // namespace shadowkit::angular
