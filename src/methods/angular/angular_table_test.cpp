#include "angular_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../../testing/method_testing.h"
#include "../../testing/test_scenes.h"
#include "../raytrace/raytrace_method.h"
#include "angular_method.h"
#include "occluders.h"
#include "shadowkit/core/error.h"

namespace shadowkit {
namespace {

// A camera at the origin looking down -z: the light frame's axes are the world's axes with
// F = -z.
Camera straight_camera() {
  return testing::camera({0, 0, 0}, {0, 0, -1}, 64, 48);
}

TEST(LightFrame, AnglesFollowEquationsOneToThree) {
  const LightFrame frame(Light::point({1, 2, 3}), straight_camera(), {}, 0);
  const AngularPoint ahead = frame.angular({1, 2, 1});
  EXPECT_DOUBLE_EQ(ahead.r, 2);
  EXPECT_DOUBLE_EQ(ahead.theta, 0);
  EXPECT_DOUBLE_EQ(ahead.phi, 0);
  const AngularPoint p = frame.angular({1 + 1, 2 + 1, 3 - 1});  // X = Y = 1, F = 1
  EXPECT_NEAR(p.theta, std::atan(1.0), 1e-15);                  // eq. 2
  EXPECT_NEAR(p.phi, 1 / std::sqrt(2.0), 1e-15);  // tan(phi) within the theta half-plane
  // A line along the camera's right axis keeps theta (Sec. 3, Fig. 19).
  for (double x : {-5.0, 0.0, 7.0}) EXPECT_NEAR(frame.angular({x, 3, 2}).theta, p.theta, 1e-15);
  // Behind the light (F < 0) theta continues past pi/2: the second hemisphere of Sec. 11.2.
  EXPECT_GT(frame.angular({1, 3, 5}).theta, std::numbers::pi / 2);
}

TEST(LightFrame, ADirectionalLightAlongTheScanLinesIsRejectedLoudly) {
  EXPECT_THROW(LightFrame(Light::directional({1, 0, 0}), straight_camera(), {}, 2), InputError);
  const LightFrame frame(Light::directional({0, -1, -1}), straight_camera(), {}, 0);
  EXPECT_NEAR(frame.angular({5, 1, 1}).theta, frame.angular({-3, 1, 1}).theta, 1e-15);
  EXPECT_NEAR(frame.angular({0, 0, 0}).theta, frame.angular(Vec3{0, -1, -1} * 4.0).theta, 1e-15);
}

TEST(AngularTable, ACutIsTheTrianglesCrossingOfTheThetaPlane) {
  const LightFrame frame(Light::point({0, 0, 0}), straight_camera(), {}, 0);
  const Vec3 v[3] = {{-1, -1, 2}, {1, -1, 2}, {0, 1, 2}};  // light frame, F = 2
  AngularPair pair;
  ASSERT_TRUE(cut_triangle(frame, v, 0.0, pair));
  EXPECT_NEAR(pair.phi_begin, -0.25, 1e-15);  // tan(phi) of (-0.5, 0, 2)
  EXPECT_NEAR(pair.phi_end, 0.25, 1e-15);
  EXPECT_FALSE(cut_triangle(frame, v, std::atan2(1.5, 2.0), pair));    // above the apex
  EXPECT_FALSE(cut_triangle(frame, v, 0.0 + std::numbers::pi, pair));  // the other half-plane
}

// Two hidden squares of one open mesh overlapping in phi at different depths (a coil seen
// edge-on, Fig. 4(a)), each entry pairs the crossings of one triangle: points between the
// squares are shadowed by the near one only where it covers them.
TEST(AngularTable, PairsComeFromOneHiddenTriangleEachAndAreSortedByPhi) {
  PolygonSoup coil = testing::horizontal_quad(-1, 0.5, -1, 1, 2);
  coil.append(testing::horizontal_quad(-0.5, 1, -1, 1, 1));
  const Scene scene = testing::make_scene(testing::camera({0, 8, 6}, {0, 0, 0}, 64, 48),
                                          {Light::point({0, 4, 0})}, {coil});
  const LightFrame frame(scene.lights[0], scene.camera, {}, 0);
  AngularTableInput input{occluding_faces(scene, scene.lights[0]), 64};
  const AngularTable table = AngularTable::build(scene, frame, input, {});
  EXPECT_EQ(table.theta().resolution, 64);
  std::size_t pairs = 0;
  for (int k = 0; k < 64; ++k) {
    const auto entry = table.entry(k);
    const std::size_t wide = table.wide(k).size();
    for (std::size_t i = 0; i < entry.size(); ++i) {
      EXPECT_LE(entry[i].phi_begin, entry[i].phi_end);
      if (i > 0 && i != wide) {
        EXPECT_LE(entry[i - 1].phi_begin, entry[i].phi_begin);
      }
      EXPECT_EQ(entry[i].face,
                scene.triangles().triangle_face[table.hidden(entry[i].hidden).triangle]);
    }
    // Each square is two triangles; an entry crossing both squares holds up to four pairs.
    EXPECT_LE(entry.size(), 4u);
    pairs += entry.size();
  }
  EXPECT_GT(pairs, 64u);
}

// A square frame (a closed solid with a hole, Figs. 13 and 25) over the ground: the light
// looks through the hole, so the ground under it is lit and under the frame shadowed.
PolygonSoup square_frame(double inner, double outer, double y0, double y1) {
  PolygonSoup s;
  const double c[4] = {-outer, -inner, inner, outer};
  for (int layer = 0; layer < 2; ++layer) {
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) s.positions.push_back({c[i], layer ? y1 : y0, c[j]});
    }
  }
  const auto at = [](int layer, int i, int j) { return std::uint32_t(layer * 16 + j * 4 + i); };
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      if (i == 1 && j == 1) continue;  // the hole
      s.add_face({at(1, i, j + 1), at(1, i + 1, j + 1), at(1, i + 1, j), at(1, i, j)});
      s.add_face({at(0, i, j), at(0, i + 1, j), at(0, i + 1, j + 1), at(0, i, j + 1)});
    }
  }
  // Walls along the outer and inner rings, each a quad between consecutive ring vertices.
  const int outer_ring[12][2] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2},
                                 {3, 3}, {2, 3}, {1, 3}, {0, 3}, {0, 2}, {0, 1}};
  for (int k = 0; k < 12; ++k) {
    const auto* a = outer_ring[k];
    const auto* b = outer_ring[(k + 1) % 12];
    s.add_face({at(0, b[0], b[1]), at(0, a[0], a[1]), at(1, a[0], a[1]), at(1, b[0], b[1])});
  }
  const int inner_ring[4][2] = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
  for (int k = 0; k < 4; ++k) {
    const auto* a = inner_ring[k];
    const auto* b = inner_ring[(k + 1) % 4];
    s.add_face({at(0, a[0], a[1]), at(0, b[0], b[1]), at(1, b[0], b[1]), at(1, a[0], a[1])});
  }
  return s;
}

TEST(AngularTable, AHoleLetsTheLightThroughAndDepthIsExactInsideSpans) {
  const Scene scene = testing::make_scene(
      testing::camera({0, 10, 1}, {0, 0, 0}, 160, 120), {Light::point({0.2, 6, 0.1})},
      {testing::horizontal_quad(-8, 8, -8, 8, 0), square_frame(1, 2, 1.5, 2)});
  ASSERT_TRUE(scene.objects[1].mesh.closed());
  ASSERT_TRUE(scene.objects[1].mesh.consistently_oriented());
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  AngularMethod angular({});
  RaytraceMethod reference({});
  const ShadowMask mask = testing::method_mask(angular, scene, vsb, 0);
  const MaskComparison c =
      compare_masks(testing::method_mask(reference, scene, vsb, 0), mask, vsb.object_ids());
  EXPECT_EQ(c.interior_mismatched, 0u);
  int hole = 0, under_frame = 0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (!vsb.covered(i) || vsb.object(i) != 0) continue;
    const Vec3 p = vsb.point(i);
    if (std::max(std::abs(p.x), std::abs(p.z)) < 0.5)
      hole += mask.pixels[i] == kMaskLit ? 1 : -1000;
    const double ring = std::max(std::abs(p.x - 0.1 / 3), std::abs(p.z));
    if (ring > 2.0 && ring < 2.3) under_frame += mask.pixels[i] == kMaskShadow ? 1 : -1000;
  }
  EXPECT_GT(hole, 20);
  EXPECT_GT(under_frame, 20);
  EXPECT_GT(testing::counter(angular, "re_loops"), 1);  // outer and hole loops
}

}  // namespace
}  // namespace shadowkit
