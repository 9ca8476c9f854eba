// SunlitAreas: per-face lit areas for one directional light after another from one scene
// BSP tree, equal to the single-light run's fragments.
#include <gtest/gtest.h>

#include "shadowkit/methods/raytrace.h"
#include "shadowkit/methods/svbsp.h"
#include "shadowkit/scene/generators.h"
#include "svbsp_test_support.h"
#include "testing/sampled_shadow.h"
#include "testing/test_scenes.h"

namespace shadowkit::svbsp {
namespace {

TEST(SunlitAreas, EqualTheLitFragmentsOfEachLightInWorldUnits) {
  const Scene scene = make_builtin_scene("table", {});
  const SunlitAreas sunlit(scene);
  const SceneBsp bsp = SceneBsp::build(scene);
  const double scale2 = scene.frame.scale * scene.frame.scale;
  for (const Vec3 toward : {Vec3{0.3, 1, 0.2}, Vec3{-0.7, 0.4, 0.1}, Vec3{0, 0.2, -1}}) {
    const Vec3 t = normalize(toward);
    const std::vector<double> lit = sunlit.lit_areas(t);
    const auto expected =
        face_areas(generate_shadows(bsp, scene, Light::directional(-t)).fragments);
    ASSERT_EQ(lit.size(), scene.face_count());
    double total = 0;
    for (std::uint32_t face = 0; face < scene.face_count(); ++face) {
      const auto it = expected.find(face);
      const double want = it == expected.end() ? 0.0 : it->second.lit * scale2;
      EXPECT_NEAR(lit[face], want, 1e-12 * face_area(scene, face) * scale2) << face;
      EXPECT_LE(lit[face], face_area(scene, face) * scale2 * (1 + 1e-12)) << face;
      total += lit[face];
    }
    EXPECT_GT(total, 0);
    EXPECT_EQ(lit, sunlit.lit_areas(t));  // the same sums, in the same order
  }
}

// The `square` scene (a 2 x 2 square one unit above a larger ground), the light straight
// above: the ground loses exactly the square's area, the square is wholly lit.
TEST(SunlitAreas, SquareAboveGroundShadowsExactlyItsArea) {
  const Scene scene = make_builtin_scene("square", {});
  const SunlitAreas sunlit(scene);
  const std::vector<double> lit = sunlit.lit_areas({0, 1, 0});
  double lit_total = 0, area_total = 0;
  for (std::uint32_t face = 0; face < scene.face_count(); ++face) {
    lit_total += lit[face];
    area_total += face_area(scene, face) * scene.frame.scale * scene.frame.scale;
  }
  ASSERT_GT(area_total, 0);
  // Lit: everything but the square's shadow on the ground, which is as large as the square.
  double square = area_total;
  for (std::uint32_t face = 0; face < scene.face_count(); ++face) {
    const double a = face_area(scene, face) * scene.frame.scale * scene.frame.scale;
    square = std::min(square, a);
  }
  EXPECT_NEAR(lit_total, area_total - square, 1e-9 * area_total);
}

PolygonSoup turned_inside_out(PolygonSoup soup) {
  for (std::size_t f = 0; f + 1 < soup.face_start.size(); ++f) {
    std::reverse(soup.indices.begin() + soup.face_start[f],
                 soup.indices.begin() + soup.face_start[f + 1]);
  }
  return soup;
}

// Faces of a solid turned from the light are skipped: the areas stay those of every face
// filtered, for a box, a box turned inside out (whose faces toward the light are the ones
// turned from it by their normals) and a box with a cavity lined by inward faces.
TEST(SunlitAreas, SkippingTheFarSidesOfSolidsChangesNoArea) {
  using namespace shadowkit::testing;
  PolygonSoup hollow = box({3, 1, -1}, {6, 4, 2});
  const PolygonSoup lining = turned_inside_out(box({4, 2, 0}, {5, 3, 1}));
  hollow.append(lining);
  const Scene scene =
      make_scene(camera({0, 10, 20}, {0, 0, 0}, 64, 48), {},
                 {horizontal_quad(-20, 20, -20, 20, 0), box({-4, 1, -1}, {-2, 3, 1}),
                  turned_inside_out(box({-1, 1, -1}, {1, 3, 1})), hollow});
  const SunlitAreas sunlit(scene);
  const SceneBsp bsp = SceneBsp::build(scene);
  const double scale2 = scene.frame.scale * scene.frame.scale;
  for (const Vec3 toward : {Vec3{0.3, 1, 0.2}, Vec3{-0.7, 0.4, 0.1}, Vec3{0.5, 0.3, -1}}) {
    const Vec3 t = normalize(toward);
    const std::vector<double> lit = sunlit.lit_areas(t);
    const auto expected =
        face_areas(generate_shadows(bsp, scene, Light::directional(-t)).fragments);
    for (std::uint32_t face = 0; face < scene.face_count(); ++face) {
      const auto it = expected.find(face);
      const double want = it == expected.end() ? 0.0 : it->second.lit * scale2;
      EXPECT_NEAR(lit[face], want, 1e-12 * face_area(scene, face) * scale2) << face;
    }
  }
}

// A saddle: corners alternately 1 and 3 above the ground, far from any plane, so that
// Mesh::build keeps it as two triangles folded along a diagonal.
PolygonSoup saddle(Vec3 centre, double half) {
  const Vec3 c = centre;
  return testing::polygon(
      {c + Vec3{0, -1, -half}, c + Vec3{half, 1, 0}, c + Vec3{0, -1, half}, c + Vec3{-half, 1, 0}});
}

std::vector<Vec3> low_and_high_suns() {
  std::vector<Vec3> suns;
  for (int k = 0; k < 8; ++k) {
    const double azimuth = 0.7 + k * 0.785;
    const double elevation = k % 2 ? 0.25 : 0.6;
    suns.push_back({std::cos(azimuth) * std::cos(elevation), std::sin(elevation),
                    std::sin(azimuth) * std::cos(elevation)});
  }
  return suns;
}

// The sun-study contract: a polygon never shades itself. Alone, a warped polygon under any
// sun off its triangles' planes is lit whole, although its triangles hide one another's
// surface from a low sun (which generate_shadows, over faces, shows).
TEST(SunlitAreas, AWarpedPolygonDoesNotShadeItself) {
  using namespace shadowkit::testing;
  const Scene scene = make_scene(camera({0, 10, 20}, {0, 0, 0}, 64, 48), {}, {saddle({}, 3)});
  ASSERT_EQ(scene.face_count(), 2u);
  const SunlitAreas sunlit(scene);
  const SceneBsp bsp = SceneBsp::build(scene);
  const double area = face_area(scene, 0) + face_area(scene, 1);
  double least_face_lit = area;
  for (const Vec3 toward : low_and_high_suns()) {
    const std::vector<double> lit = sunlit.lit_areas(toward);
    EXPECT_NEAR(lit[0] + lit[1], area, 1e-9 * area) << toward.x << " " << toward.z;
    double faces_lit = 0;
    for (const auto& [face, areas] :
         face_areas(generate_shadows(bsp, scene, Light::directional(-toward)).fragments)) {
      faces_lit += areas.lit;
    }
    least_face_lit = std::min(least_face_lit, faces_lit);
  }
  EXPECT_LT(least_face_lit, 0.9 * area);  // the triangles do shade one another as faces
}

// With others around it, a warped polygon's triangles are shadowed by every other surface,
// also where its own triangles hide them too: each face's lit area is that of a scene
// without its polygon (stratified Embree rays, testing/sampled_shadow.h). A square and a
// second saddle lie in the first one's fold, the ground under both.
TEST(SunlitAreas, AWarpedPolygonIsShadowedByEveryOtherSurface) {
  using namespace shadowkit::testing;
  const std::vector<PolygonSoup> polygons{horizontal_quad(-10, 10, -10, 10, 0),
                                          saddle({0, 2, 0}, 3), horizontal_quad(-1, 0, 0, 1, 2.2),
                                          saddle({1.2, 2.6, -0.5}, 1)};
  const Camera view = camera({0, 10, 20}, {0, 0, 0}, 64, 48);
  const Scene scene = make_scene(view, {}, polygons);
  ASSERT_EQ(scene.face_count(), 6u);
  std::vector<Scene> without(polygons.size());
  std::vector<std::unique_ptr<raytrace::ShadowRays>> rays;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    std::vector<PolygonSoup> others = polygons;
    others.erase(others.begin() + std::ptrdiff_t(i));
    without[i] = make_scene(view, {}, others);
    rays.push_back(std::make_unique<raytrace::ShadowRays>(without[i]));
  }
  const SunlitAreas sunlit(scene);
  for (const Vec3 toward : low_and_high_suns()) {
    const std::vector<double> lit = sunlit.lit_areas(toward);
    for (std::uint32_t face = 0; face < scene.face_count(); ++face) {
      const std::size_t polygon = scene.object_of_face(face);
      const double shadowed =
          sampled_shadowed_fraction(scene, *rays[polygon], face, Light::directional(-toward));
      EXPECT_NEAR(lit[face] / face_area(scene, face), 1 - shadowed, 0.005)
          << "face " << face << " sun " << toward.x << " " << toward.y << " " << toward.z;
    }
  }
}

}  // namespace
}  // namespace shadowkit::svbsp
