// OutwardSolids: which faces the solid's own near side shadows, and the far-side skip
// leaving every piece's fragments and the lit areas as they were.
#include "shadowkit/scene/outward_solids.h"

#include <gtest/gtest.h>

#include <string_view>

#include "shadow_generator.h"
#include "shadowkit/scene/scene_file.h"
#include "svbsp_test_support.h"
#include "testing/test_scenes.h"

namespace shadowkit::svbsp {
namespace {

// Face ids of testing::box, in order.
enum BoxFace : std::uint32_t { kMinusX, kPlusX, kMinusY, kPlusY, kMinusZ, kPlusZ };

Scene scene_of(std::vector<PolygonSoup> soups) {
  return testing::make_scene(testing::camera({0, 5, 9}, {0, 0, 0}, 64, 48),
                             {testing::point_light({0, 10, 0})}, soups);
}

TEST(OutwardSolids, FarSideOfABoxIsTurnedFromALightOutsideIt) {
  const Scene scene = scene_of({testing::box({-1, -1, -1}, {1, 1, 1})});
  const OutwardSolids& solids = scene.outward_solids();
  const Light above = Light::point({0, 10, 0});
  for (std::uint32_t f = 0; f < 6; ++f) EXPECT_TRUE(solids.bounds_solid(f)) << f;
  EXPECT_FALSE(far_side_of(scene, above)(kPlusY));
  for (const std::uint32_t f : {kMinusX, kPlusX, kMinusY, kMinusZ, kPlusZ}) {
    EXPECT_TRUE(far_side_of(scene, above)(f)) << f;
  }
  const Light corner = Light::point({5, 5, 5});
  EXPECT_FALSE(far_side_of(scene, corner)(kPlusX));
  EXPECT_TRUE(far_side_of(scene, corner)(kMinusX));
  const Light down = Light::directional({0, -1, 0});
  EXPECT_FALSE(far_side_of(scene, down)(kPlusY));
  EXPECT_FALSE(far_side_of(scene, down)(kPlusX));  // the light in its plane
  EXPECT_TRUE(far_side_of(scene, down)(kMinusY));
}

TEST(OutwardSolids, NoFarSideForALightInsideTheBoxOrOnItsWall) {
  const Scene scene = scene_of({testing::box({-1, -1, -1}, {1, 1, 1})});
  for (const Vec3 p : {Vec3{0, 0, 0}, Vec3{0.9, -0.5, 0.2}, Vec3{1, 0, 0}}) {
    for (std::uint32_t f = 0; f < 6; ++f) {
      EXPECT_FALSE(far_side_of(scene, Light::point(p))(f)) << f;
    }
  }
}

TEST(OutwardSolids, EachConnectedPartHasItsOwnBox) {
  // One object, two boxes: the light inside the first one's box only.
  PolygonSoup two = testing::box({-1, -1, -1}, {1, 1, 1});
  two.append(testing::box({4, -1, -1}, {6, 1, 1}));
  const Scene scene = scene_of({two});
  const Light light = Light::point({0.5, 0.5, 0.5});
  EXPECT_FALSE(far_side_of(scene, light)(kPlusX));
  EXPECT_TRUE(far_side_of(scene, light)(6 + kPlusX));
  EXPECT_FALSE(far_side_of(scene, light)(6 + kMinusX));
}

TEST(OutwardSolids, AFinelyMeshedSphereIsOneSolid) {
  // Joining 1,152 faces makes deep chains of parents; each face must name the root.
  const Scene scene = scene_of({sphere(48, 24)});
  const OutwardSolids& solids = scene.outward_solids();
  EXPECT_EQ(solids.size(), 1u);
  for (std::uint32_t f = 0; f < scene.face_count(); ++f) EXPECT_EQ(solids.solid_of(f), 0) << f;
}

TEST(OutwardSolids, OpenAndInsideOutMeshesBoundNoSolid) {
  const Scene scene = scene_of({testing::horizontal_quad(-1, 1, -1, 1, 0),
                                inside_out(testing::box({-1, -1, -1}, {1, 1, 1}))});
  const OutwardSolids& solids = scene.outward_solids();
  for (std::uint32_t f = 0; f < scene.face_count(); ++f) {
    EXPECT_FALSE(solids.bounds_solid(f)) << f;
    EXPECT_FALSE(far_side_of(scene, Light::point({0, 10, 0}))(f)) << f;
    EXPECT_FALSE(far_side_of(scene, Light::directional({0, -1, 0}))(f)) << f;
  }
}

TEST(OutwardSolids, SkippingTheFarSideKeepsEveryFragmentAndTheLitAreas) {
  for (const char* name : {"cubes:27", "table", "room"}) {
    const Scene scene = load_scene(name, {});
    const SceneBsp bsp = SceneBsp::build(scene);
    const Light& light = scene.lights[0];
    const LightFragments all = generate_shadows(bsp, scene, light);
    const LightFragments skipped =
        generate_shadows(bsp, scene, light, {}, far_side_of(scene, light));
    EXPECT_LE(skipped.light_facing, all.light_facing) << name;
    if (std::string_view(name) == "cubes:27") {
      EXPECT_LT(skipped.light_facing, all.light_facing);
    }
    const auto want = face_areas(all.fragments);
    const auto got = face_areas(skipped.fragments);
    ASSERT_EQ(got.size(), scene.face_count()) << name;
    for (const auto& [face, a] : got) {
      const double size = face_area(scene, face);
      EXPECT_NEAR(a.lit + a.shadowed, size, 1e-9 * size) << name << " " << face;
      EXPECT_NEAR(a.lit, want.at(face).lit, 1e-9 * size) << name << " " << face;
      if (far_side_of(scene, light)(face)) {
        EXPECT_EQ(a.lit, 0) << name << " " << face;
      }
    }
  }
}

}  // namespace
}  // namespace shadowkit::svbsp
