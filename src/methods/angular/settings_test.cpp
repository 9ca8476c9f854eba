// The settings that measure the papers as written: angular.exact, angular.resolution=eq4 and
// angular.light_inside.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "angular_method.h"
#include "occluders.h"
#include "shadowkit/core/error.h"
#include "shadowkit/scene/scene_file.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"
#include "view_theta.h"

namespace shadowkit::angular {
namespace {

constexpr double kPi = std::numbers::pi;

double mismatch(const Scene& scene, std::map<std::string, std::string> settings) {
  return testing::worst_interior_mismatch(scene, "angular", {"angular", std::move(settings)});
}

// A wall in the plane x = 0 that holds the point light, beside a box; both on a ground.
Scene light_in_a_face_plane() {
  return testing::make_scene(testing::camera({0.5, 3, 6}, {0, 0, 0}, 320, 240),
                             {testing::point_light({0, 3, 0})},
                             {testing::horizontal_quad(-5, 5, -5, 5, 0),
                              testing::polygon({{0, 0, -1}, {0, 0, 1}, {0, 2, 1}, {0, 2, -1}}),
                              testing::box({1, 0, -0.5}, {1.6, 0.8, 0.5})});
}

// A light inside a closed room whose XY plane (the image plane's, through the light: z = 1)
// holds a box's face and cuts another box.
Scene light_on_the_hemispheres_split() {
  return testing::make_scene(
      testing::camera({0, 1.5, 4}, {0, 1, 0}, 320, 240), {testing::point_light({0, 1.5, 1})},
      {testing::box({-3, 0, -3}, {3, 3, 5}), testing::box({-1.5, 0, 1}, {-0.8, 0.7, 2}),
       testing::box({0.6, 0, 0.5}, {1.2, 0.5, 1.5})});
}

Scene room() {
  return testing::resized(load_scene("room", {}), 480, 270);
}

// The exact assists keep the default within the conformance bar; without them the table
// alone answers, and its error is the discretization's: it falls as R grows (Figs. 6-7).
TEST(AngularSettings, WithoutTheExactAssistsTheErrorFallsAsRGrows) {
  const Scene scene = testing::resized(load_scene("table", {}), 480, 270);
  double previous = 100;
  for (const char* r : {"99", "299", "599"}) {
    const double paper = mismatch(scene, {{"exact", "0"}, {"resolution", r}});
    EXPECT_LT(paper, previous) << r;
    EXPECT_LE(mismatch(scene, {{"resolution", r}}), paper) << r;
    previous = paper;
  }
  EXPECT_LE(mismatch(scene, {}), 0.2);
}

// The face-corner culling is an assist: without it a coarse entry's pair reaches past its
// strip onto the lit neighbour of a convex surface.
TEST(AngularSettings, WithoutCullingACoarseTableShadowsAConvexSurface) {
  const Scene scene = testing::resized(load_scene("coil", {}), 320, 240);
  EXPECT_GT(mismatch(scene, {{"exact", "0"}, {"resolution", "20"}}),
            mismatch(scene, {{"resolution", "20"}}));
}

// A face plane through the light: its far sheet has no depth along the slices' rays.
TEST(AngularSettings, ALightInAFacePlane) {
  const Scene scene = light_in_a_face_plane();
  EXPECT_LE(mismatch(scene, {}), 0.2);
  EXPECT_LE(mismatch(scene, {{"exact", "0"}, {"resolution", "599"}}), 2);
}

TEST(AngularSettings, Eq4AsWritten) {
  const Scene scene = load_scene("cubes:125", {});
  EXPECT_NEAR(eq4_resolution(scene, 100, 0, kPi / 4, true), 100, 1);
  EXPECT_NEAR(eq4_resolution(scene, 100, -kPi / 4, kPi / 4, true), 200, 1);
  // tan diverges at the light's XY plane: the cap.
  EXPECT_EQ(eq4_resolution(scene, 100, 0, kPi / 2, true), 8 * scene.camera.height);
  // A light far away: the scan lines; no vertex in view: the same.
  EXPECT_EQ(eq4_resolution(scene, 100, 0, 0.5, false), scene.camera.height);
  EXPECT_EQ(eq4_resolution(scene, 0, 0, 0.5, true), scene.camera.height);
  // The table's R is eq. 4 over the table's range.
  const LightFrame frame(scene.lights[0], scene.camera, scene.bounds().center());
  AngularTableOptions options;
  options.eq4 = true;
  const AngularTable table =
      AngularTable::build(scene, frame, occluding_sheets(scene, scene.lights[0]), options);
  const ThetaQuantization& q = table.theta();
  ASSERT_FALSE(q.full_turn);
  EXPECT_EQ(q.resolution, eq4_resolution(scene, farthest_depth(scene, frame), q.lower(0),
                                         q.lower(q.resolution), true));
  EXPECT_GT(q.resolution, 1);
}

TEST(AngularSettings, Eq4ShadowsTheScenes) {
  for (const char* name : {"cubes:125", "table", "room"}) {
    const Scene scene = testing::resized(load_scene(name, {}), 480, 270);
    EXPECT_LE(mismatch(scene, {{"resolution", "eq4"}}), 0.2) << name;
  }
}

// Sec. 11.2: the XY plane falls between entries, and entries are finer towards it.
TEST(AngularSettings, TheHemispheresSplitAtTheXYPlane) {
  ThetaQuantization q;
  q.resolution = 400;
  q.full_turn = q.hemispheres = true;
  EXPECT_NEAR(q.position(-kPi), 0, 1e-9);
  EXPECT_NEAR(q.position(-kPi / 2), 100, 1e-9);
  EXPECT_NEAR(q.position(0), 200, 1e-9);
  EXPECT_NEAR(q.position(kPi / 2), 300, 1e-9);
  EXPECT_NEAR(q.position(kPi), 400, 1e-9);
  for (const double theta : {-3.0, -1.6, -1.5, -0.2, 0.0, 0.7, 1.5707, 1.6, 3.1}) {
    EXPECT_NEAR(q.theta_at(q.position(theta)), theta, 1e-12) << theta;
  }
  EXPECT_EQ(q.index(kPi / 2 - 1e-12), 299);
  EXPECT_EQ(q.index(kPi / 2 + 1e-12), 300);
  const double centre = q.lower(201) - q.lower(200);
  const double edge = q.lower(300) - q.lower(299);
  EXPECT_NEAR(centre / edge, 8, 0.2);
  EXPECT_GE(q.widest(), centre);
}

TEST(AngularSettings, HemispheresShadowALightInTheScene) {
  for (const Scene& scene : {room(), light_on_the_hemispheres_split()}) {
    AngularMethod halves(MethodOptions("angular", {{"light_inside", "hemispheres"}}));
    const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
    testing::method_mask(halves, scene, vsb, 0);
    EXPECT_EQ(int(testing::counter(halves, "theta_resolution")) % 4, 0);
    EXPECT_LE(mismatch(scene, {{"light_inside", "hemispheres"}}), 0.2);
    EXPECT_LE(mismatch(scene, {}), 0.2);
    EXPECT_LE(mismatch(scene, {{"light_inside", "hemispheres"}, {"exact", "0"}}), 2);
  }
}

TEST(AngularSettings, RejectsBadValues) {
  for (const auto& [key, value] :
       std::initializer_list<std::pair<const char*, const char*>>{{"resolution", "eq5"},
                                                                  {"resolution", "EQ4"},
                                                                  {"exact", "2"},
                                                                  {"exact", "yes"},
                                                                  {"light_inside", "sphere"},
                                                                  {"light_inside", "1"}}) {
    EXPECT_THROW(AngularMethod(MethodOptions("angular", {{key, value}})), InputError)
        << key << "=" << value;
  }
}

}  // namespace
}  // namespace shadowkit::angular
