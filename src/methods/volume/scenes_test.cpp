#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "shadowkit/scene/scene_file.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"
#include "volume_method.h"

namespace shadowkit::volume {
namespace {

// The analytic shadow of the square on the ground; pixels within 1e-4 of its edge skipped.
template <class InShadow>
void expect_ground_shadow(const Scene& scene, InShadow in_shadow) {
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  VolumeMethod m({});
  const ShadowMask mask = testing::method_mask(m, scene, vsb, 0);
  int shadowed = 0, lit = 0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (!vsb.covered(i) || vsb.object(i) != 0) continue;
    const Vec3 p = vsb.point(i);
    const int expected = in_shadow(p);
    if (expected < 0) continue;
    EXPECT_EQ(mask.pixels[i], expected ? kMaskShadow : kMaskLit) << p.x << " " << p.z;
    (expected ? shadowed : lit)++;
  }
  EXPECT_GT(shadowed, 100);
  EXPECT_GT(lit, 100);
}

TEST(VolumeScenes, SquareAbovePlaneCastsTheAnalyticShadowOfAPointLight) {
  const Scene scene = testing::square_over_plane(testing::camera({0, 9, 6}, {0, 0, 0}, 160, 120),
                                                 testing::point_light({0, 4, 0}));
  expect_ground_shadow(scene, [](Vec3 p) {
    const double edge = std::max(std::abs(p.x), std::abs(p.z)) - 4.0 / 3.0;
    return std::abs(edge) < 1e-4 ? -1 : int(edge < 0);
  });
}

TEST(VolumeScenes, SquareAbovePlaneCastsTheAnalyticShadowOfADirectionalLight) {
  const Vec3 d = normalize(Vec3{0.5, -1, 0.25});
  const Scene scene = testing::square_over_plane(testing::camera({0, 9, 6}, {0, 0, 0}, 160, 120),
                                                 testing::directional_light(d));
  expect_ground_shadow(scene, [d](Vec3 p) {
    const Vec3 q = p - d * (1.0 / -d.y);
    const double edge = std::max(std::abs(q.x), std::abs(q.z)) - 1.0;
    return std::abs(edge) < 1e-4 ? -1 : int(edge < 0);
  });
}

TEST(VolumeScenes, NoCountComesOutNegative) {
  // At full resolution some pixels next to a cube's contour edge are given to the face along
  // it although their rays pass a sub-pixel outside (snapping); their points, taken on the
  // face's plane, lay across the edge's shadow polygon and counted its jump (-2).
  const Scene scene = load_scene("cubes:125", {});
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  VolumeMethod m({});
  testing::method_mask(m, scene, vsb, 0);
  EXPECT_EQ(testing::counter(m, "negative_counts"), 0);
  EXPECT_GT(testing::counter(m, "receiver_culled"), 0);
}

TEST(VolumeScenes, NoCountComesOutNegativeWhereARunIsSettledByItsKeys) {
  // The same hazard on a settled run: a pixel at the open ground's far corner shows a face
  // along the ground's boundary edge, a sub-pixel past it, and the run's keys put the edge's
  // polygon wholly in front of it (-1). Runs and cells that show a polygon's edge faces are
  // now tested pixel by pixel.
  const Scene scene = load_scene_file(
      std::filesystem::path(SHADOWKIT_SOURCE_DIR) / "examples" / "subdivision.json", {});
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  VolumeMethod m({});
  testing::method_mask(m, scene, vsb, 0);
  EXPECT_EQ(testing::counter(m, "negative_counts"), 0);
}

// Two copies of one closed box at one spot: each copy's faces lie in the other's planes, the
// boundary of its volume. The pair casts exactly the one box's shadow, and lights its faces as
// the one box does. Hazard: a plane test left to rounding puts lines of pixels of the top face
// in the other copy's volume.
TEST(VolumeScenes, ACoincidentCopyCastsNoMoreShadow) {
  const testing::CopyDifference d = testing::coincident_copy_difference(
      [] { return std::make_unique<VolumeMethod>(MethodOptions{}); },
      testing::box({-1, 0.2, -1}, {1, 1.2, 1}));
  EXPECT_EQ(d.differ, 0);
  EXPECT_GT(d.lit_box, 1000);
}

}  // namespace
}  // namespace shadowkit::volume
