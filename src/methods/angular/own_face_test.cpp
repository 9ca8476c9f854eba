#include "own_face.h"

#include <gtest/gtest.h>

#include <cmath>

#include "testing/test_scenes.h"

namespace shadowkit::angular {
namespace {

// A unit square in the plane z = 0, its light frame from a light above it.
class OwnFaceTest : public ::testing::Test {
 protected:
  OwnFaceTest() {
    PolygonSoup soup;
    soup.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    soup.add_face({0, 1, 2, 3});
    scene_ = testing::make_scene(testing::camera({0.5, -3, 4}, {0.5, 0.5, 0}, 64, 48),
                                 {testing::point_light({0.3, 0.2, 5})}, {soup});
    frame_.emplace(scene_.lights[0], scene_.camera, Vec3{0.5, 0.5, 0});
  }
  double outside(Vec3 p) const {
    const OwnFace own{&scene_.objects[0].mesh, 0, &*frame_, frame_->local(scene_.camera.position)};
    return own.outside(frame_->local(p));
  }

  Scene scene_;
  std::optional<LightFrame> frame_;
};

TEST_F(OwnFaceTest, InsideIsNoDistance) {
  EXPECT_EQ(outside({0.5, 0.5, 0}), 0);
  EXPECT_EQ(outside({0.999, 0.001, 0}), 0);
}

TEST_F(OwnFaceTest, OutsideIsTheDistanceFromTheOutline) {
  EXPECT_NEAR(outside({1.25, 0.5, 0}), 0.25, 1e-12);   // past an edge
  EXPECT_NEAR(outside({0.5, -1e-7, 0}), 1e-7, 1e-15);  // a rounding past one
  EXPECT_NEAR(outside({-0.3, -0.4, 0}), 0.5, 1e-12);   // past a corner
}

}  // namespace
}  // namespace shadowkit::angular
