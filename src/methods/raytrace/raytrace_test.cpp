#include <gtest/gtest.h>

#include <cmath>

#include "raytrace_method.h"
#include "testing/test_scenes.h"

namespace shadowkit::raytrace {
namespace {

ShadowMask shade(const Scene& scene, std::size_t light = 0) {
  RaytraceMethod m({});
  m.prepare(scene, {});
  m.build(scene, light, {});
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  ShadowMask mask(vsb.width, vsb.height, kMaskBackground);
  m.shade(scene, vsb, mask, {});
  return mask;
}

// Checks every ground pixel against an analytic shadow test; pixels within `margin` of the
// shadow's edge are skipped (their visible point is stored in float).
template <class InShadow>
void expect_ground_shadow(const Scene& scene, const ShadowMask& mask, InShadow in_shadow) {
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  int shadowed = 0, lit = 0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (!vsb.covered(i) || vsb.object(i) != 0) continue;
    const Vec3 p = vsb.point(i);
    const int expected = in_shadow(p);  // 1 shadow, 0 lit, -1 too close to tell
    if (expected < 0) continue;
    EXPECT_EQ(mask.pixels[i], expected ? kMaskShadow : kMaskLit) << p.x << " " << p.z;
    (expected ? shadowed : lit)++;
  }
  EXPECT_GT(shadowed, 100);
  EXPECT_GT(lit, 100);
}

TEST(Raytrace, SquareAbovePlaneCastsTheAnalyticShadowOfAPointLight) {
  const Scene scene = testing::square_over_plane(testing::camera({0, 9, 6}, {0, 0, 0}, 160, 120),
                                                 testing::point_light({0, 4, 0}));
  const ShadowMask mask = shade(scene);
  expect_ground_shadow(scene, mask, [](Vec3 p) {
    const double edge = std::max(std::abs(p.x), std::abs(p.z)) - 4.0 / 3.0;
    return std::abs(edge) < 1e-4 ? -1 : int(edge < 0);
  });
}

TEST(Raytrace, SquareAbovePlaneCastsTheAnalyticShadowOfADirectionalLight) {
  const Vec3 d = normalize(Vec3{0.5, -1, 0.25});
  const Scene scene = testing::square_over_plane(testing::camera({0, 9, 6}, {0, 0, 0}, 160, 120),
                                                 testing::directional_light(d));
  const ShadowMask mask = shade(scene);
  expect_ground_shadow(scene, mask, [d](Vec3 p) {
    // Follow the light back up to the square's height 1.
    const Vec3 q = p - d * (1.0 / -d.y);
    const double edge = std::max(std::abs(q.x), std::abs(q.z)) - 1.0;
    return std::abs(edge) < 1e-4 ? -1 : int(edge < 0);
  });
}

TEST(Raytrace, SurfacesAreTwoSided) {
  // Camera below the open square, light above: the camera sees the unlit side.
  Scene scene = testing::make_scene(testing::camera({0, -3, 0.5}, {0, 0, 0}, 40, 40),
                                    {testing::point_light({0, 4, 0})},
                                    {testing::horizontal_quad(-1, 1, -1, 1, 0)});
  const ShadowMask below = shade(scene);
  EXPECT_EQ(below.at(20, 20), kMaskShadow);
  // Light below as well: now lit, whichever way the face's normal points.
  scene.lights[0] = testing::point_light({0, -4, 0});
  EXPECT_EQ(shade(scene).at(20, 20), kMaskLit);
}

TEST(Raytrace, LightInAFacesPlaneShadowsThatFace) {
  const Scene scene = testing::make_scene(testing::camera({0, 3, 0.5}, {0, 0, 0}, 40, 40),
                                          {testing::point_light({5, 0, 0})},
                                          {testing::horizontal_quad(-1, 1, -1, 1, 0)});
  EXPECT_EQ(shade(scene).at(20, 20), kMaskShadow);
}

// A light exactly in the ceiling's plane, inside the room: by the contract nothing lies
// between it and the walls, whose shadow rays run up to it along the ceiling at grazing
// angles (in float they hit the ceiling just short of the light without the filter).
TEST(Raytrace, ACeilingThroughTheLightShadowsNothingUnderIt) {
  const Scene scene = testing::make_scene(testing::camera({0, 1.5, 2.5}, {0, 2.9, -3}, 160, 120),
                                          {testing::point_light({0.3, 3, -0.2})},
                                          {testing::box({-3, 0, -3}, {3, 3, 3})});
  const ShadowMask mask = shade(scene);
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  int walls = 0, ceiling = 0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    ASSERT_TRUE(vsb.covered(i));
    const bool on_ceiling = vsb.point(i).y > 3 - 1e-6;  // condition 1 fails there
    EXPECT_EQ(mask.pixels[i], on_ceiling ? kMaskShadow : kMaskLit) << vsb.point(i).y;
    ++(on_ceiling ? ceiling : walls);
  }
  EXPECT_GT(walls, 5000);
  EXPECT_GT(ceiling, 1000);
}

TEST(Raytrace, ClosedBoxShadowsTheGroundAndItsOwnFarSide) {
  const Scene scene = testing::make_scene(
      testing::camera({4, 5, 6}, {0, 0.5, 0}, 120, 90), {testing::point_light({0, 6, 0})},
      {testing::horizontal_quad(-10, 10, -10, 10, 0), testing::box({-1, 0, -1}, {1, 1, 1})});
  const ShadowMask mask = shade(scene);
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (!vsb.covered(i)) continue;
    const Vec3 p = vsb.point(i);
    const Plane& plane = scene.face_plane(vsb.face[i]);
    if (vsb.object(i) == 1) {  // box: only the top faces the light
      EXPECT_EQ(mask.pixels[i], plane.normal.y > 0.5 ? kMaskLit : kMaskShadow);
    } else {  // ground: shadow of the top square from height 6 is |x|, |z| < 1.2
      const double edge = std::max(std::abs(p.x), std::abs(p.z)) - 1.2;
      if (std::abs(edge) > 1e-4) {
        EXPECT_EQ(mask.pixels[i], edge < 0 ? kMaskShadow : kMaskLit);
      }
    }
  }
}

TEST(Raytrace, WorksAtTinyAndHugeScales) {
  for (double s : {1e-4, 1e5}) {
    auto scaled = [s](Vec3 v) { return v * s; };
    Scene scene =
        testing::make_scene(testing::camera(scaled({0, 9, 6}), {0, 0, 0}, 120, 90),
                            {testing::point_light(scaled({0, 4, 0}))},
                            {testing::horizontal_quad(-10 * s, 10 * s, -10 * s, 10 * s, 0),
                             testing::horizontal_quad(-s, s, -s, s, s)});
    const ShadowMask mask = shade(scene);
    expect_ground_shadow(scene, mask, [s](Vec3 p) {
      const double edge = (std::max(std::abs(p.x), std::abs(p.z)) - 4.0 / 3.0 * s) / s;
      return std::abs(edge) < 1e-4 ? -1 : int(edge < 0);
    });
  }
}

TEST(Raytrace, PrecisionDoesNotDependOnWhereTheSceneSits) {
  // The analytic square scene shrunk to 0.02 units and moved 1e5 from the origin, where a
  // float's spacing (0.008) exceeds the whole scene: Embree stores coordinates relative to
  // the scene's centre, so the shadow is still exact.
  const double s = 1e-3;
  const Vec3 at{1e5, 0, -1e5};
  const Scene scene = testing::make_scene(
      testing::camera(at + Vec3{0, 9, 6} * s, at, 120, 90),
      {testing::point_light(at + Vec3{0, 4, 0} * s)},
      {testing::horizontal_quad(at.x - 10 * s, at.x + 10 * s, at.z - 10 * s, at.z + 10 * s, 0),
       testing::horizontal_quad(at.x - s, at.x + s, at.z - s, at.z + s, s)});
  const ShadowMask mask = shade(scene);
  expect_ground_shadow(scene, mask, [&](Vec3 p) {
    const double edge = (std::max(std::abs(p.x - at.x), std::abs(p.z - at.z)) - 4.0 / 3.0 * s) / s;
    return std::abs(edge) < 1e-2 ? -1 : int(edge < 0);
  });
}

}  // namespace
}  // namespace shadowkit::raytrace
