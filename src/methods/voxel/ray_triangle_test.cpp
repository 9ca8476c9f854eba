// §4.2's five-dot-product test against a brute-force ray/triangle test (barycentric
// coordinates from Cramer's rule with triple products) on random cases.
#include "ray_triangle.h"

#include <gtest/gtest.h>

#include <random>

namespace shadowkit::voxel {
namespace {

double triple(Vec3 a, Vec3 b, Vec3 c) {
  return dot(a, cross(b, c));
}

// Solves origin + t d = v0 + b1 (v1 - v0) + b2 (v2 - v0); the margin says how far the
// answer is from every boundary (to skip cases that rounding may decide either way).
struct BruteForce {
  bool hit = false;
  double margin = 0;
};

BruteForce brute_force(const RaySegment& ray, Vec3 v0, Vec3 v1, Vec3 v2) {
  const Vec3 e1 = v1 - v0, e2 = v2 - v0, s = ray.origin - v0, d = -ray.direction;
  const double det = triple(d, e1, e2);
  if (std::abs(det) < 1e-9) return {false, 0};
  const double t = triple(s, e1, e2) / det, b1 = triple(d, s, e2) / det;
  const double b2 = triple(d, e1, s) / det;
  const double margin = std::min({t - ray.t_min, ray.t_max - t, b1, b2, 1 - b1 - b2});
  return {margin > 0, std::abs(margin)};
}

TEST(FiveDotProducts, AgreesWithBruteForceOnRandomCases) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-2, 2);
  const auto point = [&] {
    return Vec3{coordinate(random), coordinate(random), coordinate(random)};
  };
  int hits = 0, compared = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 v0 = point(), v1 = point(), v2 = point();
    const RaySegment ray{point(), point(), 0.01, 1};
    const BruteForce expected = brute_force(ray, v0, v1, v2);
    if (expected.margin < 1e-6) continue;
    ++compared;
    hits += expected.hit;
    ASSERT_EQ(ray_hits_triangle(ray, v0, v1, v2), expected.hit) << i;
  }
  EXPECT_GT(compared, 19000);
  EXPECT_GT(hits, 500);
}

TEST(FiveDotProducts, DegenerateCasesNeverHit) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  // A ray in the triangle's plane (the light in the subpatch's plane).
  EXPECT_FALSE(ray_hits_triangle({{-1, 0.2, 0}, {3, 0, 0}, 0, 1}, a, b, c));
  // A collapsed triangle.
  EXPECT_FALSE(ray_hits_triangle({{0.2, 0.2, -1}, {0, 0, 2}, 0, 1}, a, b, b));
  // Straight through the middle, and stopping short of the plane.
  EXPECT_TRUE(ray_hits_triangle({{0.2, 0.2, -1}, {0, 0, 2}, 0, 1}, a, b, c));
  EXPECT_FALSE(ray_hits_triangle({{0.2, 0.2, -1}, {0, 0, 2}, 0, 0.4}, a, b, c));
  // Tiny and huge coordinates alike.
  for (double scale : {1e-9, 1e9}) {
    EXPECT_TRUE(ray_hits_triangle({Vec3{0.2, 0.2, -1} * scale, Vec3{0, 0, 2} * scale, 0, 1},
                                  a * scale, b * scale, c * scale));
  }
}

}  // namespace
}  // namespace shadowkit::voxel
