#include "shadowkit/scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shadowkit/scene/triangulate.h"
#include "testing/test_scenes.h"

namespace shadowkit {
namespace {

TEST(Camera, PixelRayFollowsTheContract) {
  const Camera cam = testing::camera({1, 2, 3}, {1, 2, -7}, 4, 2, 90);
  // Forward -z, right +x, up +y; tan(45 deg) = 1, aspect 2.
  const Vec3 r = cam.pixel_ray(0, 0);
  const Vec3 expected = normalize(Vec3{(2 * 0.5 / 4 - 1) * 2, (1 - 2 * 0.5 / 2), -1});
  EXPECT_NEAR(r.x, expected.x, 1e-15);
  EXPECT_NEAR(r.y, expected.y, 1e-15);
  EXPECT_NEAR(r.z, expected.z, 1e-15);
  const Vec3 last = cam.pixel_ray(3, 1);  // x = 1.5, y = -0.5
  const Vec3 e2 = normalize(Vec3{1.5, -0.5, -1});
  EXPECT_NEAR(last.x, e2.x, 1e-15);
  EXPECT_NEAR(last.y, e2.y, 1e-15);
}

TEST(Camera, TrueUpIsOrthogonalEvenForATiltedUpVector) {
  Camera cam = testing::camera({0, 0, 0}, {0, -1, -1}, 10, 10);
  cam.up = {0.3, 1, 0};
  EXPECT_NEAR(dot(cam.true_up(), cam.forward()), 0, 1e-15);
  EXPECT_NEAR(length(cam.true_up()), 1, 1e-15);
  EXPECT_GT(cam.true_up().y, 0);
}

TEST(Transform, AppliesScaleThenRotateXYZThenTranslate) {
  std::vector<Vec3> p{{1, 0, 0}};
  // S: (2,0,0); Rx(90): unchanged; Ry(90): (0,0,-2); Rz(90): unchanged; T: +(1,1,1).
  apply_transform(p, {2, 3, 4}, {90, 90, 90}, {1, 1, 1});
  EXPECT_NEAR(p[0].x, 1, 1e-12);
  EXPECT_NEAR(p[0].y, 1, 1e-12);
  EXPECT_NEAR(p[0].z, -1, 1e-12);
  std::vector<Vec3> q{{0, 1, 0}};
  // S: (0,3,0); Rx(90): (0,0,3); Ry(90): (3,0,0); Rz(90): (0,3,0).
  apply_transform(q, {2, 3, 4}, {90, 90, 90}, {0, 0, 0});
  EXPECT_NEAR(q[0].x, 0, 1e-12);
  EXPECT_NEAR(q[0].y, 3, 1e-12);
  EXPECT_NEAR(q[0].z, 0, 1e-12);
}

TEST(Scene, FinalizeNumbersFacesAndTriangulates) {
  const Scene s = testing::make_scene(
      testing::camera({0, 5, 5}, {0, 0, 0}, 8, 8), {},
      {testing::box({0, 0, 0}, {1, 1, 1}), testing::horizontal_quad(-5, 5, -5, 5, 0)});
  EXPECT_EQ(s.face_count(), 7u);
  EXPECT_EQ(s.objects[1].first_face, 6u);
  EXPECT_EQ(s.object_of_face(6), 1u);
  EXPECT_EQ(s.local_face(6), 0u);
  EXPECT_EQ(s.triangles().triangles.size(), 14u);
  EXPECT_EQ(s.triangles().triangle_face.back(), 6u);
  EXPECT_DOUBLE_EQ(s.bounds().lo.x, -5);
  EXPECT_DOUBLE_EQ(s.bounds().hi.y, 1);
}

double triangles_area(const std::vector<Vec3>& p,
                      const std::vector<std::array<std::uint32_t, 3>>& t) {
  double area = 0;
  for (const auto& tri : t)
    area += 0.5 * length(cross(p[tri[1]] - p[tri[0]], p[tri[2]] - p[tri[0]]));
  return area;
}

TEST(Triangulate, EarClippingCoversANonConvexPolygonExactly) {
  // A comb: a 5 x 3 rectangle with two 1 x 2 notches, area 11.
  const std::vector<Vec3> p{{0, 0, 0}, {5, 0, 0}, {5, 3, 0}, {4, 3, 0}, {4, 1, 0}, {3, 1, 0},
                            {3, 3, 0}, {2, 3, 0}, {2, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}};
  std::vector<std::uint32_t> loop(p.size());
  for (std::uint32_t i = 0; i < loop.size(); ++i) loop[i] = i;
  std::vector<std::array<std::uint32_t, 3>> tris;
  triangulate_polygon(p, loop, {0, 0, 1}, tris);
  EXPECT_EQ(tris.size(), p.size() - 2);
  EXPECT_DOUBLE_EQ(triangles_area(p, tris), 0.5 * length(newell_normal(p, loop)));
  EXPECT_DOUBLE_EQ(0.5 * length(newell_normal(p, loop)), 11.0);
  for (const auto& t : tris) {  // same orientation as the polygon
    EXPECT_GT(cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]).z, 0);
  }
}

// A star of 20,000 corners at radii 1 and 0.3 in turn: every outer corner is an ear, each
// found next to the last cut; the triangles cover the star exactly, in its orientation.
TEST(Triangulate, EarClippingCoversAStarOfTwentyThousandCorners) {
  constexpr std::uint32_t kCorners = 20000;
  std::vector<Vec3> p;
  std::vector<std::uint32_t> loop;
  for (std::uint32_t i = 0; i < kCorners; ++i) {
    const double angle = 2 * std::numbers::pi * i / kCorners, r = i % 2 ? 0.3 : 1.0;
    p.push_back({r * std::cos(angle), r * std::sin(angle), 0});
    loop.push_back(i);
  }
  std::vector<std::array<std::uint32_t, 3>> tris;
  triangulate_polygon(p, loop, {0, 0, 1}, tris);
  ASSERT_EQ(tris.size(), kCorners - 2);
  const double area = 0.5 * length(newell_normal(p, loop));
  EXPECT_NEAR(triangles_area(p, tris), area, 1e-9 * area);
  int clockwise = 0;
  for (const auto& t : tris) clockwise += cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]).z < 0;
  EXPECT_EQ(clockwise, 0);
}

// Two squares touching at one corner, given as one loop through that corner twice: a lap
// finds no ear before the end, and the flattest corner is cut so that clipping ends. Every
// cut, ear or not, takes its triangle's signed area off the loop's, so they still sum to it.
TEST(Triangulate, ASelfTouchingLoopEndsWithTheFlattestCorner) {
  const std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 0},
                            {2, 2, 0}, {1, 2, 0}, {0, 1, 0}};
  const std::vector<std::uint32_t> loop{0, 1, 2, 3, 4, 5, 2, 6};
  std::vector<std::array<std::uint32_t, 3>> tris;
  triangulate_polygon(p, loop, {0, 0, 1}, tris);
  ASSERT_EQ(tris.size(), loop.size() - 2);
  double signed_area = 0;
  for (const auto& t : tris) signed_area += 0.5 * cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]).z;
  EXPECT_NEAR(signed_area, 2.0, 1e-12);
}

}  // namespace
}  // namespace shadowkit
