#include "shadowkit/raster/screen_polygon.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "shadowkit/core/image.h"

namespace shadowkit::raster {
namespace {

constexpr int kWidth = 96, kHeight = 64;

RasterProjection view() {
  return RasterProjection::perspective({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60, kWidth, kHeight, 1e-3);
}

// Pixel centres owned by setup_polygon's triangles.
Image<int> fan_coverage(std::span<const HomogeneousPoint> corners) {
  Image<int> count(kWidth, kHeight, 0);
  std::vector<ScreenTriangle> tris;
  setup_polygon(corners, 0, view(), tris);
  for (const ScreenTriangle& t : tris) {
    SpanWalker walker(t, t.min_y);
    for (int y = t.min_y; y <= t.max_y; ++y, walker.next_row()) {
      int x0 = t.min_x, x1 = t.max_x;
      if (!walker.span(x0, x1)) continue;
      for (int x = x0; x <= x1; ++x) ++count.at(x, y);
    }
  }
  return count;
}

// Pixel centres owned by setup_convex_polygon's output, each walked in bands of \p band rows
// (a fresh walker per band, as a tiled pass does), over \p margin rows beyond its bounds.
Image<int> polygon_coverage(std::span<const HomogeneousPoint> corners, int band, int margin = 0) {
  Image<int> count(kWidth, kHeight, 0);
  std::vector<ScreenPolygon> polys;
  setup_convex_polygon(corners, 0, view(), polys);
  for (const ScreenPolygon& p : polys) {
    const int first = std::max(0, p.min_y - margin), last = std::min(kHeight - 1, p.max_y + margin);
    for (int y0 = first; y0 <= last; y0 += band) {
      const int y1 = std::min(last, y0 + band - 1);
      PolygonSpanWalker walker(p, y0, y1);
      for (int y = y0; y <= y1; ++y, walker.next_row()) {
        int x0 = 0, x1 = kWidth - 1;
        if (!walker.span(x0, x1)) continue;
        for (int x = x0; x <= x1; ++x) ++count.at(x, y);
      }
    }
  }
  return count;
}

int differing_pixels(const Image<int>& a, const Image<int>& b) {
  int n = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) n += a.at(x, y) != b.at(x, y);
  }
  return n;
}

int covered_pixels(const Image<int>& a) {
  int n = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) n += a.at(x, y) > 0;
  }
  return n;
}

// A convex polygon of \p n corners on an ellipse in the plane z = -1 (about 55 pixels a
// unit), its centre and radii in units, in either sense.
std::vector<HomogeneousPoint> ellipse(std::mt19937& rng, int n, double rx, double ry) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> angles(n);
  for (double& a : angles) a = 2 * M_PI * u(rng);
  std::sort(angles.begin(), angles.end());
  if (u(rng) < 0.5) std::reverse(angles.begin(), angles.end());
  const double cx = u(rng) - 0.5, cy = 0.6 * (u(rng) - 0.5);
  std::vector<HomogeneousPoint> corners;
  for (double a : angles)
    corners.push_back({{cx + rx * std::cos(a), cy + ry * std::sin(a), -1}, 1});
  return corners;
}

TEST(ScreenPolygon, OwnsTheSamePixelCentresAsItsFanOfTriangles) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 300; ++trial) {
    const auto corners = ellipse(rng, 3 + trial % 8, 0.05 + 0.01 * (trial % 40), 0.3);
    const Image<int> fan = fan_coverage(corners);
    EXPECT_EQ(differing_pixels(fan, polygon_coverage(corners, kHeight)), 0) << trial;
    EXPECT_EQ(differing_pixels(fan, polygon_coverage(corners, 8)), 0) << trial;
  }
}

TEST(ScreenPolygon, WalkingRowsBeyondItsBoundsAddsNothing) {
  std::mt19937 rng(11);
  const auto corners = ellipse(rng, 6, 0.2, 0.1);
  const Image<int> fan = fan_coverage(corners);
  ASSERT_GT(covered_pixels(fan), 50);
  for (int band : {1, 3, 8})
    EXPECT_EQ(differing_pixels(fan, polygon_coverage(corners, band, 9)), 0);
}

TEST(ScreenPolygon, CornersOnPixelCentresAndHorizontalEdges) {
  // A pixel-aligned diamond and square: corners and edges right on pixel centres, where only
  // the fill rule decides.
  const auto at = [](double px, double py) {
    const RasterProjection v = view();
    return HomogeneousPoint{{(px - v.offset_x) / v.scale_x, -(py - v.offset_y) / v.scale_y, -1}, 1};
  };
  const std::vector<HomogeneousPoint> diamond{at(40.5, 10.5), at(60.5, 30.5), at(40.5, 50.5),
                                              at(20.5, 30.5)};
  const std::vector<HomogeneousPoint> square{at(10.5, 10.5), at(30.5, 10.5), at(30.5, 20.5),
                                             at(10.5, 20.5)};
  for (const auto& corners : {diamond, square}) {
    const Image<int> fan = fan_coverage(corners);
    EXPECT_GT(covered_pixels(fan), 150);
    EXPECT_EQ(differing_pixels(fan, polygon_coverage(corners, kHeight)), 0);
    EXPECT_EQ(differing_pixels(fan, polygon_coverage(corners, 4)), 0);
  }
  // Two squares sharing an edge on pixel centres own each centre on it once.
  const std::vector<HomogeneousPoint> right{at(30.5, 10.5), at(50.5, 10.5), at(50.5, 20.5),
                                            at(30.5, 20.5)};
  Image<int> both = polygon_coverage(square, 8);
  const Image<int> other = polygon_coverage(right, 8);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) both.at(x, y) += other.at(x, y);
  }
  for (int y = 11; y <= 19; ++y) EXPECT_EQ(both.at(30, y), 1) << y;
}

TEST(ScreenPolygon, SliversAndSubPixelPolygonsFallBackToTheFanWhereSnappingBendsThem) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  int triangles_out = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    // Nearly collinear corners a few 1/256 pixel off a line: snapping can make them reflex.
    const double x0 = u(rng), y0 = 0.4 * u(rng), dx = 0.6 * u(rng), dy = 0.6 * u(rng);
    std::vector<HomogeneousPoint> corners;
    for (double t : {0.0, 0.3, 0.6, 1.0}) {
      const double off = 2e-5 * u(rng);
      corners.push_back({{x0 + dx * t - dy * off, y0 + dy * t + dx * off, -1}, 1});
    }
    corners.push_back({{x0 + dx * 0.5 + dy * 0.01, y0 + dy * 0.5 - dx * 0.01, -1}, 1});
    std::vector<ScreenPolygon> polys;
    setup_convex_polygon(corners, 0, view(), polys);
    for (const ScreenPolygon& p : polys) triangles_out += p.count == 3;
    ASSERT_EQ(differing_pixels(fan_coverage(corners), polygon_coverage(corners, 8)), 0) << trial;
  }
  EXPECT_GT(triangles_out, 0);
}

TEST(ScreenPolygon, ClippedByTheNearPlaneAndTheGuardBand) {
  // Corners behind the eye and at infinity (w = 0): clipping adds corners on both.
  const std::vector<HomogeneousPoint> corners{
      {{-0.3, -0.2, -1}, 1}, {{0.4, -0.2, -1}, 1}, {{0.5, -0.1, 2}, 1}, {{-2, 0.3, -1}, 0}};
  const Image<int> fan = fan_coverage(corners);
  EXPECT_GT(covered_pixels(fan), 500);
  EXPECT_EQ(differing_pixels(fan, polygon_coverage(corners, kHeight)), 0);
  EXPECT_EQ(differing_pixels(fan, polygon_coverage(corners, 8)), 0);
}

}  // namespace
}  // namespace shadowkit::raster
