#include "shadowkit/raster/cluster_view.h"

#include <gtest/gtest.h>

#include <cmath>

#include "testing/test_scenes.h"

namespace shadowkit::raster {
namespace {

// The clusters of a scene of one box (12 triangles: one cluster) in \p view.
std::vector<ClusterInView> box_in_view(Vec3 lo, Vec3 hi, const RasterProjection& view) {
  const Scene scene = testing::make_scene(testing::camera({0, 0, 10}, {0, 0, 0}, 64, 48), {},
                                          {testing::box(lo, hi)});
  EXPECT_EQ(scene.triangles().clusters.size(), 1u);
  return clusters_in_view(scene, view);
}

// A 90° view from the origin along -z, 100 x 100 pixels: a cube face's, as a shadow map's.
RasterProjection face_view() {
  return RasterProjection::perspective({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90, 100, 100, 1e-3);
}

TEST(ClustersInView, BoxInFrontProjectsWithinItsRectangle) {
  const std::vector<ClusterInView> in = box_in_view({-1, -1, -4}, {1, 1, -2}, face_view());
  ASSERT_EQ(in.size(), 1u);
  // Its corners nearest the eye, at depth 2, reach x = ±1 / 2 of the half width: pixels 25-75.
  EXPECT_LE(in[0].x0, 25);
  EXPECT_GE(in[0].x0, 22);
  EXPECT_GE(in[0].x1, 74);
  EXPECT_LE(in[0].x1, 77);
  EXPECT_NEAR(in[0].nearest, 0.5, 1e-6);  // 1 / 2, raised past rounding
  EXPECT_GE(in[0].nearest, 0.5);
}

// Boxes behind the eye, or beside the view and reaching behind the eye, are in no view: a
// cube map's faces each see a sixth of the scene around a light inside it.
TEST(ClustersInView, BoxesBehindOrBesideTheEyeAreNotInView) {
  EXPECT_TRUE(box_in_view({-1, -1, 2}, {1, 1, 4}, face_view()).empty());
  EXPECT_TRUE(box_in_view({3, -1, -2}, {5, 1, 2}, face_view()).empty());    // right, across z = 0
  EXPECT_TRUE(box_in_view({-1, 3, -2}, {1, 5, 2}, face_view()).empty());    // above
  EXPECT_TRUE(box_in_view({-5, -1, -2}, {-3, 1, 2}, face_view()).empty());  // left
  EXPECT_TRUE(box_in_view({-1, -5, -2}, {1, -3, 2}, face_view()).empty());  // below
  RasterProjection far_near = face_view();
  far_near.near = 5;
  EXPECT_TRUE(
      box_in_view({-1, -1, -3}, {1, 1, -2}, far_near).empty());  // nearer than the near plane
}

// A box the near plane cuts has no projection that bounds it: it may draw anywhere, and is
// nearer than anything drawn, so it is never culled.
TEST(ClustersInView, BoxAcrossTheNearPlaneMayDrawAnywhere) {
  const std::vector<ClusterInView> in = box_in_view({-0.5, -0.5, -2}, {0.5, 0.5, 2}, face_view());
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].nearest, INFINITY);
  EXPECT_EQ(in[0].x0, 0);
  EXPECT_EQ(in[0].y0, 0);
  EXPECT_EQ(in[0].x1, 99);
  EXPECT_EQ(in[0].y1, 99);
}

// An orthographic view's sides are planes along its direction: a box beside them is out
// whatever its depth, and one behind the eye is out too.
TEST(ClustersInView, OrthographicViewKeepsOnlyBoxesOverItsRaster) {
  const RasterProjection view =
      RasterProjection::orthographic_view({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 2, 2, 10, 100, 100);
  EXPECT_EQ(box_in_view({-1, -1, -1}, {1, 1, 1}, view).size(), 1u);
  EXPECT_TRUE(box_in_view({2.2, -1, -1}, {3, 1, 1}, view).empty());
  EXPECT_TRUE(box_in_view({-1, -1, 11}, {1, 1, 12}, view).empty());  // behind the eye
  const std::vector<ClusterInView> edge = box_in_view({1.9, 1.9, -1}, {3, 3, 1}, view);
  ASSERT_EQ(edge.size(), 1u);  // over the corner of the raster
  EXPECT_EQ(edge[0].x1, 99);
  EXPECT_EQ(edge[0].y0, 0);
}

}  // namespace
}  // namespace shadowkit::raster
