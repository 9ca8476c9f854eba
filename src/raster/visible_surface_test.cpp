#include "shadowkit/raster/visible_surface.h"

#include <gtest/gtest.h>

#include <algorithm>

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
  vsb.width = 300, vsb.height = 2;
  vsb.face.assign(600, kNoFace);
  // Row 1 shows faces at these columns, in blocks 0, 2 and 4 (the last one partial); row 0
  // none.
  const std::vector<int> faces{0, 7, 8, 9, 23, 39, 63, 128, 191, 256, 299};
  for (const int x : faces) vsb.face[vsb.index(x, 1)] = 5;
  vsb.summarize_coverage();
  EXPECT_EQ(vsb.block_covered, (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 1, 0, 1, 0, 1}));
  std::vector<int> found;
  for (int x = vsb.next_covered(0, 300, 1); x < 300; x = vsb.next_covered(x + 1, 300, 1)) {
    found.push_back(x);
  }
  EXPECT_EQ(found, faces);
  EXPECT_EQ(vsb.next_covered(0, 300, 0), 300);  // a row of background
  EXPECT_EQ(vsb.next_covered(10, 23, 1), 23);   // none before the end
  EXPECT_EQ(vsb.next_covered(10, 24, 1), 23);
  EXPECT_EQ(vsb.next_covered(64, 128, 1), 128);  // a block of background, then the end
  EXPECT_EQ(vsb.next_covered(64, 129, 1), 128);
  EXPECT_EQ(vsb.next_covered(192, 250, 1), 250);
  EXPECT_EQ(vsb.next_covered(300, 300, 1), 300);
}

// render_visible_surfaces() marks the blocks as it fills the buffer, as summarize_coverage()
// does from the faces.
TEST(VisibleSurface, TheScanConverterMarksTheBlocksThatShowAFace) {
  const Scene scene = testing::make_scene(testing::camera({0.3, 3, 4}, {0, 0, 0}, 300, 200), {},
                                          {testing::box({-0.5, 0, -0.5}, {0.5, 1, 0.5})});
  VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  const std::vector<std::uint8_t> marked = vsb.block_covered;
  EXPECT_GT(std::count(marked.begin(), marked.end(), 0), 0);
  EXPECT_GT(std::count(marked.begin(), marked.end(), 1), 0);
  vsb.summarize_coverage();
  EXPECT_EQ(marked, vsb.block_covered);
}

}  // namespace
}  // namespace shadowkit
