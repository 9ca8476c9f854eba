#include "shadowkit/methods/shadow_method.h"

#include <gtest/gtest.h>

#include "testing/test_scenes.h"

namespace shadowkit {
namespace {

// The ground of examples/sweep/light-in-the-plane-of-a-ground-of-triangles.json in working
// coordinates: a triangle at y = -0.05, whose plane is computed from the average of its
// corners, ((y + y) + y) / 3, which rounds to -0.05000000000000001.
constexpr double kGroundY = -0.05;
const Mesh& ground() {
  static const Mesh mesh = Mesh::build(
      testing::polygon({{-0.6, kGroundY, -0.6}, {-0.6, kGroundY, 0.6}, {0.6, kGroundY, 0.6}}),
      "ground", {});
  return mesh;
}

TEST(LightSide, ALightInAFacesPlaneLiesInItThoughThePlaneIsARoundingOffIt) {
  const Plane& plane = ground().planes[0];
  const Light light = Light::point({0.1875, kGroundY, 0.0625});
  ASSERT_NE(plane.distance(light.position), 0.0);  // the rounding this is about
  EXPECT_EQ(light_side(plane, light), 0.0);
  EXPECT_FALSE(faces_light(plane, {0.4, 0.3, 0.5}, light));  // the ground is in shadow
}

TEST(LightSide, ALightJustOffAFacesPlaneIsOnItsSide) {
  const Plane& plane = ground().planes[0];
  for (const double offset : {1e-9, -1e-9}) {
    const Light light = Light::point({0.1875, kGroundY + offset, 0.0625});
    EXPECT_EQ(light_side(plane, light) > 0, offset > 0) << offset;
    EXPECT_NEAR(light_side(plane, light), offset, 1e-15) << offset;
  }
  EXPECT_TRUE(faces_light(plane, {0.4, 0.3, 0.5}, Light::point({0.1875, kGroundY + 1e-9, 0})));
}

TEST(LightSide, ASunAlongAFacesPlaneLiesInIt) {
  // A triangle's Newell normal is a sum of products: off the plane's true normal by a few ulps.
  const Mesh mesh = Mesh::build(
      testing::polygon({{0.1, 0.3, 0.7}, {0.9, 1.1, 0.2}, {0.4, 0.6, 0.9}}), "ramp", {});
  const Plane& plane = mesh.planes[0];
  const Light along = Light::directional(normalize(Vec3{0.8, 0.8, -0.5}));
  ASSERT_NE(dot(plane.normal, along.direction), 0.0);
  EXPECT_EQ(light_side(plane, along), 0.0);
  const Light above = Light::directional(normalize(Vec3{0.8, 0.8, -0.5}) + plane.normal * 1e-9);
  EXPECT_LT(light_side(plane, above), 0);
}

}  // namespace
}  // namespace shadowkit
