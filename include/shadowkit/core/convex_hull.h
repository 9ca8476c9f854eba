#pragma once
// The convex hull of points in the plane, for screen outlines and light-space footprints.
#include <algorithm>
#include <span>
#include <vector>

namespace shadowkit {

/// The convex hull of \p p (Andrew's monotone chain) into the first corners of \p hull,
/// turning the way of a positive cross product (ScreenPolygon's orientation in screen
/// coordinates), without repeated or collinear corners; returns their count. \p p is
/// reordered. Exact for integer points.
template <class Point>
std::size_t convex_hull(std::span<Point> p, std::vector<Point>& hull) {
  std::sort(p.begin(), p.end(),
            [](const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  const auto turn = [](const Point& o, const Point& a, const Point& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  if (p.empty()) return 0;
  hull.resize(2 * p.size() + 1);
  std::size_t n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (n >= 2 && turn(hull[n - 2], hull[n - 1], p[i]) <= 0) --n;
    hull[n++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = n + 1; i-- > 0;) {
    while (n >= lower && turn(hull[n - 2], hull[n - 1], p[i]) <= 0) --n;
    hull[n++] = p[i];
  }
  return n > 1 ? n - 1 : n;  // the last corner repeats the first
}

}  // namespace shadowkit
