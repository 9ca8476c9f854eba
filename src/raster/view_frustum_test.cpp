#include "shadowkit/raster/view_frustum.h"

#include <gtest/gtest.h>

#include "testing/test_scenes.h"

namespace shadowkit {
namespace {

// Points on the rays through the image's outer pixel edges lie on the side planes: just
// inside them is in, just outside is out; the near plane cuts at its depth.
TEST(ViewFrustum, SidesPassThroughTheOuterPixelEdges) {
  Camera cam = testing::camera({1, 2, 3}, {-2, 0.5, -4}, 37, 40, 30);
  cam.up = {0.1, 1, 0.2};
  const ViewFrustum view = ViewFrustum::of(cam, 0.5);
  const Camera::PixelGrid g = cam.pixel_grid();
  const Vec3 f = cam.forward(), r = cam.right(), u = cam.true_up();
  const double x_hi = g.x0 + (cam.width - 0.5) * g.step, y_lo = g.y0 - (cam.height - 0.5) * g.step;
  for (const double depth : {0.6, 3.0, 1e4}) {
    const Vec3 edge = cam.position + (f + r * x_hi + u * y_lo) * depth;
    const Vec3 inward = (f - r * x_hi - u * y_lo) * (1e-9 * depth);
    EXPECT_TRUE(view.holds(edge + inward));
    EXPECT_FALSE(view.holds(edge - inward));
  }
  EXPECT_FALSE(view.holds(cam.position + f * 0.49));
  EXPECT_TRUE(view.holds(cam.position + f * 0.51));
  EXPECT_NEAR(view.near_radius,
              0.5 * length(f + r * (g.x0 - 0.5 * g.step) + u * (g.y0 + 0.5 * g.step)), 1e-12);
  // Each corner of the near rectangle lies on the near plane and on the two sides it joins.
  for (int k = 0; k < 4; ++k) {
    const Vec3 c = view.near_corners[k];
    EXPECT_NEAR(view.planes[0].distance(c), 0, 1e-12);
    EXPECT_NEAR(view.planes[1 + k].distance(c), 0, 1e-12);
    EXPECT_NEAR(view.planes[1 + (k + 3) % 4].distance(c), 0, 1e-12);
    EXPECT_NEAR(length(c - cam.position), view.near_radius, 1e-12);
  }
}

TEST(ViewFrustum, ExcludesOnlyWhatOnePlaneSeparates) {
  const Camera cam = testing::camera({0, 0, 0}, {0, 0, -1}, 10, 10, 90);
  const ViewFrustum view = ViewFrustum::of(cam, 0.1);
  const Vec3 behind[2] = {{-1, 0, 1}, {1, 0, 2}};
  const Vec3 across[2] = {{-5, 0, -1}, {5, 0, -1}};  // left and right of the view, not one side
  EXPECT_TRUE(view.excludes(behind));
  EXPECT_FALSE(view.excludes(across));
}

TEST(ViewFrustum, ClipsAPolygonToTheView) {
  const Camera cam = testing::camera({0, 0, 0}, {0, 0, -1}, 10, 10, 90);
  const ViewFrustum view = ViewFrustum::of(cam, 0.1);
  // A square at depth 1 twice as wide as the view there: clipped to the view's square.
  const std::vector<Vec3> clipped = view.clip({{-2, -2, -1}, {2, -2, -1}, {2, 2, -1}, {-2, 2, -1}});
  ASSERT_EQ(clipped.size(), 4u);
  for (const Vec3 p : clipped) {
    EXPECT_NEAR(std::abs(p.x), 1, 1e-12);
    EXPECT_NEAR(std::abs(p.y), 1, 1e-12);
  }
  EXPECT_TRUE(view.clip({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}).empty());  // behind the eye
}

TEST(ClipPolygon, KeepsTheNonNegativeSideAndAddsCrossings) {
  const Plane x_at_least_1{{1, 0, 0}, -1};
  const Vec3 triangle[3] = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  const std::vector<Vec3> out = clip_polygon(triangle, x_at_least_1);
  ASSERT_EQ(out.size(), 3u);  // the corner (2, 0) and the crossings (1, 0), (1, 1)
  EXPECT_EQ(out[0], (Vec3{1, 0, 0}));
  EXPECT_EQ(out[1], (Vec3{2, 0, 0}));
  EXPECT_EQ(out[2], (Vec3{1, 1, 0}));
  const Plane x_at_least_3{{1, 0, 0}, -3};
  EXPECT_TRUE(clip_polygon(triangle, x_at_least_3).empty());
}

}  // namespace
}  // namespace shadowkit
