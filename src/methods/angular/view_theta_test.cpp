#include "view_theta.h"

#include <gtest/gtest.h>

#include <algorithm>

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

// Eq. 4: about one entry per scan line where the scene is seen, so R follows the image
// height and not the scene's extent beyond the view.
TEST(ViewTheta, AutomaticResolutionFollowsTheScanLines) {
  Scene scene = load_scene("cubes:125", {});
  const LightFrame frame(scene.lights[0], scene.camera, scene.bounds().center());
  const ViewTheta view = view_theta(scene, frame);
  ASSERT_TRUE(view.bounded);
  const int full = automatic_resolution(scene, entry_theta(scene, frame), view.hi - view.lo);
  scene.camera.height /= 4;
  scene.camera.width /= 4;
  const int quarter = automatic_resolution(scene, entry_theta(scene, frame), view.hi - view.lo);
  EXPECT_NEAR(double(full) / quarter, 4, 0.05);
  EXPECT_GT(full, 1080 / 2);
  EXPECT_LT(full, 4 * 1080);
}

}  // namespace
}  // namespace shadowkit::angular
