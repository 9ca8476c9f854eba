#include "shadowkit/raster/projection.h"

#include <gtest/gtest.h>

#include "testing/test_scenes.h"

namespace shadowkit {
namespace {

// A point on the contract's ray through pixel (c, w) projects to that pixel's centre.
TEST(RasterProjection, CameraViewMapsPixelRaysToPixelCentres) {
  Camera cam = testing::camera({1, 2, 3}, {-2, 0.5, -4}, 37, 23, 61);
  cam.up = {0.1, 1, 0.2};
  const RasterProjection p = RasterProjection::from_camera(cam, 1e-3);
  for (int w : {0, 7, 22}) {
    for (int c : {0, 18, 36}) {
      const Vec3 q = cam.position + cam.pixel_ray(c, w) * 7.5;
      const Vec3 v = p.to_view(q);
      EXPECT_NEAR(p.pixel_x(v), c + 0.5, 1e-9);
      EXPECT_NEAR(p.pixel_y(v), w + 0.5, 1e-9);
      EXPECT_NEAR(1.0 / p.depth_key(v.z), dot(q - cam.position, cam.forward()), 1e-9);
    }
  }
}

TEST(RasterProjection, OrthographicViewCoversItsRectangle) {
  const RasterProjection p =
      RasterProjection::orthographic_view({0, 0, 0}, {0, -1, 0}, {0, 0, -1}, 2, 1, 10, 40, 20);
  // Looking down -y with up -z: right is +x... whatever the frame, corners map to corners.
  const Vec3 corner = p.to_view(p.eye + p.forward * 10 + p.right * 2 + p.up * 1);
  EXPECT_NEAR(p.pixel_x(corner), 40, 1e-12);
  EXPECT_NEAR(p.pixel_y(corner), 0, 1e-12);
  EXPECT_NEAR(corner.z, 10, 1e-12);
  EXPECT_NEAR(p.depth_key(corner.z), -10, 1e-12);
}

}  // namespace
}  // namespace shadowkit
