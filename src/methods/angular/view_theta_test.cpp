#include "view_theta.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "shadowkit/raster/visible_surface.h"
#include "shadowkit/scene/scene_file.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"

namespace shadowkit::angular {
namespace {

Scene reduced(Scene scene) {
  return testing::resized(std::move(scene), 240, 135);
}

// Eq. 4's range "based on the view volume": every visible point's theta lies in it.
TEST(ViewTheta, HoldsTheThetaOfEveryVisiblePoint) {
  int bounded = 0;
  for (const char* name : {"cubes:125", "table", "room", "coil", "hole-like"}) {
    const Scene scene = reduced(load_scene(name, {}));
    const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
      const LightFrame frame(scene.lights[l], scene.camera, scene.bounds().center());
      const ViewTheta view = view_theta(scene, frame);
      if (!view.bounded) continue;
      ++bounded;
      double lo = view.hi, hi = view.lo;
      for (std::size_t i = 0; i < vsb.face.size(); ++i) {
        if (!vsb.covered(i)) continue;
        const double theta = frame.angular(vsb.point(i)).theta;
        lo = std::min(lo, theta), hi = std::max(hi, theta);
      }
      EXPECT_GE(lo, view.lo) << name << " light " << l;
      EXPECT_LE(hi, view.hi) << name << " light " << l;
      EXPECT_LT(view.hi - view.lo, 2 * (hi - lo) + 0.1) << name;  // and not much wider
    }
  }
  EXPECT_GE(bounded, 5);
}

// With the eye inside the scene's box, the region in view is bounded by the near plane as
// well as the box's faces: the quad under the eye, inside a closed box, was outside the
// table (and lit) when only the faces counted.
TEST(ViewTheta, AnEyeInsideTheSceneBoxKeepsWhatLiesNearIt) {
  const Scene scene = load_scene_file(
      std::string(SHADOWKIT_SOURCE_DIR) + "/examples/sweep/angular-eye-inside-box.json", {});
  const Bounds3 box = scene.bounds();
  const Vec3 eye = scene.camera.position;
  ASSERT_TRUE(box.lo.x < eye.x && eye.x < box.hi.x && box.lo.y < eye.y && eye.y < box.hi.y &&
              box.lo.z < eye.z && eye.z < box.hi.z);
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const LightFrame frame(scene.lights[l], scene.camera, scene.bounds().center());
    const ViewTheta view = view_theta(scene, frame);
    ASSERT_TRUE(view.bounded);
    for (std::size_t i = 0; i < vsb.face.size(); ++i) {
      const double theta = frame.angular(vsb.point(i)).theta;
      ASSERT_GE(theta, view.lo) << "light " << l << " pixel " << i;
      ASSERT_LE(theta, view.hi) << "light " << l << " pixel " << i;
    }
  }
  EXPECT_LE(testing::worst_interior_mismatch(scene, "angular"), 0.2);
}

// A 2 x 2 ground seen straight down from 4 above, 240 x 240 pixels, under a sun straight
// down: one pixel moves 4 steps on the ground, all of it across theta (the light frame's
// theta axis is the image's up axis), so the theta of a pixel is 4 steps everywhere.
Scene ground_seen_from_above(Vec3 sun) {
  Camera camera = testing::camera({0, 4, 0}, {0, 0, 0}, 240, 240);
  camera.up = {0, 0, -1};
  return testing::make_scene(camera, {testing::directional_light(sun)},
                             {testing::horizontal_quad(-1, 1, -1, 1, 0)});
}

TEST(ViewTheta, TheEntryOfAGroundSeenStraightDownUnderASunStraightDown) {
  const Scene scene = ground_seen_from_above({0, -1, 0});
  const LightFrame frame(scene.lights[0], scene.camera, scene.bounds().center());
  const double step = scene.camera.pixel_grid().step;
  const double side = 2 / (4 * step);  // the ground's side in pixels: about 145
  ASSERT_NEAR(side, 144.85, 0.01);
  // 20,982 pixels: 5.74 entries per pixel.
  EXPECT_NEAR(entries_per_pixel(side * side), 3 * std::sqrt(320.0 * 240 / (side * side)), 1e-12);
  const double entry = entry_theta(scene, frame);
  EXPECT_NEAR(entry / (4 * step / entries_per_pixel(side * side)), 1, 1e-9);
  // The ground's theta range is 2 long: R = 2 / entry, 831 entries for its 145 rows.
  EXPECT_EQ(automatic_resolution(scene, entry, 2), int(2 / entry));
  EXPECT_EQ(automatic_resolution(scene, entry, 2), 831);
}

// Entries per pixel: 3 at a 320 x 240 image's pixels, as many times more as the receivers'
// side in pixels is shorter, and never fewer than one per two pixels.
TEST(ViewTheta, EntriesPerPixelFollowTheReceiversSide) {
  EXPECT_DOUBLE_EQ(entries_per_pixel(320 * 240), 3);
  EXPECT_DOUBLE_EQ(entries_per_pixel(4 * 320 * 240), 1.5);
  EXPECT_DOUBLE_EQ(entries_per_pixel(320 * 240 / 100.0), 30);
  EXPECT_DOUBLE_EQ(entries_per_pixel(36 * 320 * 240), 0.5);
  EXPECT_DOUBLE_EQ(entries_per_pixel(100 * 320 * 240), 0.5);
  EXPECT_NEAR(entries_per_pixel(1920 * 1080), 0.577, 0.001);
}

// No receiver the light can light is in view: the automatic R is the number of scan lines.
TEST(ViewTheta, WithoutAReceiverTheAutomaticResolutionIsTheScanLines) {
  for (const Vec3 sun : {Vec3{1, 0, 0},             // in the ground's plane
                         Vec3{0, 1, 0},             // from below
                         Vec3{0.998, -0.06, 0}}) {  // grazing: sine 0.06 < kGrazingSine
    const Scene scene = ground_seen_from_above(normalize(sun));
    const LightFrame frame(scene.lights[0], scene.camera, scene.bounds().center());
    EXPECT_EQ(entry_theta(scene, frame), 0) << sun.x;
    EXPECT_EQ(automatic_resolution(scene, 0, 2), 240);
  }
  // A sun just steeper than kGrazingSine does count.
  const Scene steeper = ground_seen_from_above(normalize(Vec3{0.99, -0.08, 0}));
  EXPECT_GT(entry_theta(steeper, LightFrame(steeper.lights[0], steeper.camera, {})), 0);
  // The ground behind the eye.
  Scene away = ground_seen_from_above({0, -1, 0});
  away.camera.look_at = {0, 8, 0};
  away.camera.up = {0, 0, 1};
  EXPECT_EQ(entry_theta(away, LightFrame(away.lights[0], away.camera, {})), 0);
}

// An entry's theta keeps the bands along the shadows' edges the same share of the pixels at
// any image size: R hardly changes with it (within the view's pixel rounding).
TEST(ViewTheta, TheAutomaticResolutionHardlyDependsOnTheImageSize) {
  Scene scene = testing::resized(load_scene("cubes:125", {}), 320, 180);
  const LightFrame frame(scene.lights[0], scene.camera, scene.bounds().center());
  const ViewTheta view = view_theta(scene, frame);
  ASSERT_TRUE(view.bounded);
  const int full = automatic_resolution(scene, entry_theta(scene, frame), view.hi - view.lo);
  scene.camera.height /= 2;
  scene.camera.width /= 2;
  const int half = automatic_resolution(scene, entry_theta(scene, frame), view.hi - view.lo);
  EXPECT_NEAR(double(full) / half, 1, 0.02);
  EXPECT_GT(full, 4 * 180);
  EXPECT_LT(full, 16 * 180);
}

}  // namespace
}  // namespace shadowkit::angular
