// OutwardSolids: which faces the solid's own near side shadows, and the far-side skip
// leaving every piece's fragments and the lit areas as they were.
#include "outward_solids.h"

#include <gtest/gtest.h>

#include <string_view>

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
  const OutwardSolids solids(scene);
  const Light above = Light::point({0, 10, 0});
  for (std::uint32_t f = 0; f < 6; ++f) EXPECT_TRUE(solids.bounds_solid(f)) << f;
  EXPECT_FALSE(solids.far_side(scene, kPlusY, above));
  for (const std::uint32_t f : {kMinusX, kPlusX, kMinusY, kMinusZ, kPlusZ}) {
    EXPECT_TRUE(solids.far_side(scene, f, above)) << f;
  }
  const Light corner = Light::point({5, 5, 5});
  EXPECT_FALSE(solids.far_side(scene, kPlusX, corner));
  EXPECT_TRUE(solids.far_side(scene, kMinusX, corner));
  const Light down = Light::directional({0, -1, 0});
  EXPECT_FALSE(solids.far_side(scene, kPlusY, down));
  EXPECT_FALSE(solids.far_side(scene, kPlusX, down));  // the light in its plane
  EXPECT_TRUE(solids.far_side(scene, kMinusY, down));
}

TEST(OutwardSolids, NoFarSideForALightInsideTheBoxOrOnItsWall) {
  const Scene scene = scene_of({testing::box({-1, -1, -1}, {1, 1, 1})});
  const OutwardSolids solids(scene);
  for (const Vec3 p : {Vec3{0, 0, 0}, Vec3{0.9, -0.5, 0.2}, Vec3{1, 0, 0}}) {
    for (std::uint32_t f = 0; f < 6; ++f) {
      EXPECT_FALSE(solids.far_side(scene, f, Light::point(p))) << f;
    }
  }
}

TEST(OutwardSolids, EachConnectedPartHasItsOwnBox) {
  // One object, two boxes: the light inside the first one's box only.
  PolygonSoup two = testing::box({-1, -1, -1}, {1, 1, 1});
  two.append(testing::box({4, -1, -1}, {6, 1, 1}));
  const Scene scene = scene_of({two});
  const OutwardSolids solids(scene);
  const Light light = Light::point({0.5, 0.5, 0.5});
  EXPECT_FALSE(solids.far_side(scene, kPlusX, light));
  EXPECT_TRUE(solids.far_side(scene, 6 + kPlusX, light));
  EXPECT_FALSE(solids.far_side(scene, 6 + kMinusX, light));
}

TEST(OutwardSolids, AFinelyMeshedSphereIsOneSolid) {
  // Joining 1,152 faces makes deep chains of parents; each face must name the root.
  const Scene scene = scene_of({sphere(48, 24)});
  const OutwardSolids solids(scene);
  EXPECT_EQ(solids.size(), 1u);
  for (std::uint32_t f = 0; f < scene.face_count(); ++f) EXPECT_EQ(solids.solid_of(f), 0) << f;
}

TEST(OutwardSolids, OpenAndInsideOutMeshesBoundNoSolid) {
  const Scene scene = scene_of({testing::horizontal_quad(-1, 1, -1, 1, 0),
                                inside_out(testing::box({-1, -1, -1}, {1, 1, 1}))});
  const OutwardSolids solids(scene);
  for (std::uint32_t f = 0; f < scene.face_count(); ++f) {
    EXPECT_FALSE(solids.bounds_solid(f)) << f;
    EXPECT_FALSE(solids.far_side(scene, f, Light::point({0, 10, 0}))) << f;
    EXPECT_FALSE(solids.far_side(scene, f, Light::directional({0, -1, 0}))) << f;
  }
}

TEST(OutwardSolids, SkippingTheFarSideKeepsEveryFragmentAndTheLitAreas) {
  for (const char* name : {"cubes:27", "table", "room"}) {
    const Scene scene = load_scene(name, {});
    const SceneBsp bsp = SceneBsp::build(scene);
    const OutwardSolids solids(scene);
    const Light& light = scene.lights[0];
    const LightFragments all = generate_shadows(bsp, scene, light);
    const LightFragments skipped =
        generate_shadows(bsp, scene, light, {}, far_side_of(solids, scene, light));
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
      if (solids.far_side(scene, face, light)) {
        EXPECT_EQ(a.lit, 0) << name << " " << face;
      }
    }
  }
}

}  // namespace
}  // namespace shadowkit::svbsp
