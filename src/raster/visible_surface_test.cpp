#include "shadowkit/raster/visible_surface.h"

#include <gtest/gtest.h>

#include "testing/test_scenes.h"

namespace shadowkit {
namespace {

TEST(VisibleSurface, PointsLieOnThePixelRayAndTheFacePlane) {
  const Scene scene = testing::make_scene(testing::camera({0.3, 3, 4}, {0, 0, 0}, 96, 64), {},
                                          {testing::horizontal_quad(-20, 20, -20, 20, 0),
                                           testing::box({-0.5, 0, -0.5}, {0.5, 1, 0.5})});
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  ASSERT_EQ(vsb.width, 96);
  int checked = 0;
  for (int y = 0; y < vsb.height; ++y) {
    for (int x = 0; x < vsb.width; ++x) {
      const std::size_t i = vsb.index(x, y);
      if (!vsb.covered(i)) continue;
      const Vec3 p = vsb.point(i);
      const Vec3 ray = scene.camera.pixel_ray(x, y);
      const Vec3 along = scene.camera.position + ray * double(vsb.depth[i]);
      EXPECT_LT(length(p - along), 1e-5);
      EXPECT_LT(std::abs(scene.face_plane(vsb.face[i]).distance(p)), 1e-5);
      EXPECT_EQ(vsb.object(i), scene.object_of_face(vsb.face[i]));
      ++checked;
    }
  }
  EXPECT_GT(checked, 96 * 64 / 2);
  // The centre pixel sees the box's top (y = 1) or its front.
  EXPECT_EQ(vsb.object(vsb.index(48, 32)), 1u);
}

TEST(VisibleSurface, GroundDepthMatchesTheAnalyticDistance) {
  const Scene scene = testing::make_scene(testing::camera({0, 2, 0}, {0, 1, -4}, 50, 50, 60), {},
                                          {testing::horizontal_quad(-50, 50, -50, 50, 0)});
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  for (int y = 30; y < 50; y += 7) {
    for (int x = 0; x < 50; x += 9) {
      const Vec3 ray = scene.camera.pixel_ray(x, y);
      const double t = -2.0 / ray.y;  // ray from height 2 down to y = 0
      EXPECT_NEAR(vsb.depth[vsb.index(x, y)], t, 1e-5 * t);
    }
  }
  // Above the horizon there is nothing.
  EXPECT_FALSE(vsb.covered(vsb.index(25, 0)));
}

TEST(VisibleSurface, NextCoveredSkipsBackgroundToTheFirstFace) {
  VisibleSurfaceBuffer vsb;
  vsb.width = 40, vsb.height = 2;
  vsb.face.assign(80, kNoFace);
  // Row 1 shows faces at columns 0, 7, 8, 9, 23 and 39; row 0 none.
  for (const int x : {0, 7, 8, 9, 23, 39}) vsb.face[vsb.index(x, 1)] = 5;
  std::vector<int> found;
  for (int x = vsb.next_covered(0, 40, 1); x < 40; x = vsb.next_covered(x + 1, 40, 1)) {
    found.push_back(x);
  }
  EXPECT_EQ(found, (std::vector<int>{0, 7, 8, 9, 23, 39}));
  EXPECT_EQ(vsb.next_covered(0, 40, 0), 40);   // a row of background
  EXPECT_EQ(vsb.next_covered(10, 23, 1), 23);  // none before the end
  EXPECT_EQ(vsb.next_covered(10, 24, 1), 23);
  EXPECT_EQ(vsb.next_covered(40, 40, 1), 40);
}

}  // namespace
}  // namespace shadowkit
