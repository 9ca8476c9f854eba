#include "shadowkit/raster/screen_polygon.h"

#include <algorithm>

#include "shadowkit/core/error.h"

namespace shadowkit::raster {
namespace {

std::int64_t cross(FixedPoint o, FixedPoint a, FixedPoint b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Drops corners equal to the one before them: zero-length edges bound nothing.
void drop_repeats(std::vector<FixedPoint>& p) {
  const auto same = [](FixedPoint a, FixedPoint b) { return a.x == b.x && a.y == b.y; };
  p.erase(std::unique(p.begin(), p.end(), same), p.end());
  while (p.size() > 1 && same(p.front(), p.back())) p.pop_back();
}

// Whether the snapped corners still form a convex polygon of non-zero area that winds once,
// and in which sense: +1 positively, -1 negatively, 0 not convex. Every turn has the sign of
// the area (or is straight on), and the edges go down and up once each.
int convex_orientation(const std::vector<FixedPoint>& p) {
  const std::size_t n = p.size();
  if (n < 3) return 0;
  std::int64_t area = 0;
  for (std::size_t i = 2; i < n; ++i) area += cross(p[0], p[i - 1], p[i]);
  if (area == 0) return 0;
  const auto slope = [&](std::size_t i) {
    const std::int64_t dy = p[(i + 1) % n].y - p[i].y;
    return (dy > 0) - (dy < 0);
  };
  int last_dy = 0;  // of the last sloped edge, to count the change back to the first
  for (std::size_t i = 0; i < n; ++i) last_dy = slope(i) ? slope(i) : last_dy;
  int y_turns = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const FixedPoint a = p[i], b = p[(i + 1) % n], c = p[(i + 2) % n];
    const std::int64_t turn = cross(a, b, c);
    if ((turn > 0 && area < 0) || (turn < 0 && area > 0)) return 0;
    if (turn == 0 && (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y) < 0) return 0;
    if (const int dy = slope(i)) y_turns += dy != last_dy, last_dy = dy;
  }
  return y_turns == 2 ? (area > 0 ? 1 : -1) : 0;
}

ScreenPolygon from_triangle(const ScreenTriangle& t) {
  ScreenPolygon p;
  p.count = 3;
  for (int i = 0; i < 3; ++i) {
    p.corners[i] = {t.x[i], t.y[i]};
    p.bias_bits |= std::uint16_t(t.bias[i] << i);
  }
  p.min_x = t.min_x, p.min_y = t.min_y, p.max_x = t.max_x, p.max_y = t.max_y;
  p.face = t.face;
  return p;
}

}  // namespace

void setup_convex_polygon(std::span<const HomogeneousPoint> corners, std::uint32_t id,
                          const RasterProjection& view, std::vector<ScreenPolygon>& out) {
  thread_local std::vector<FixedPoint> fixed;
  snapped_polygon(corners, view, fixed);
  drop_repeats(fixed);
  const int orientation = convex_orientation(fixed);
  if (orientation == 0) {
    // Not convex after snapping (or no area): the fan's own triangles.
    thread_local std::vector<ScreenTriangle> tris;
    tris.clear();
    setup_polygon(corners, id, view, tris);
    for (const ScreenTriangle& t : tris) out.push_back(from_triangle(t));
    return;
  }
  if (orientation < 0) std::reverse(fixed.begin(), fixed.end());
  SHADOWKIT_CHECK(fixed.size() <= std::size_t(kMaxPolygonCorners));
  ScreenPolygon p;
  p.count = int(fixed.size());
  std::int64_t x_min = fixed[0].x, x_max = x_min, y_min = fixed[0].y, y_max = y_min;
  for (int i = 0; i < p.count; ++i) {
    const FixedPoint a = fixed[i], b = fixed[(i + 1) % p.count];
    const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
    // As TriangleBuilder: antisymmetric ownership of the centres on an edge.
    p.corners[i] = a;
    p.bias_bits |= std::uint16_t((dy < 0 || (dy == 0 && dx > 0)) ? 0 : 1 << i);
    x_min = std::min(x_min, a.x), x_max = std::max(x_max, a.x);
    y_min = std::min(y_min, a.y), y_max = std::max(y_max, a.y);
  }
  const auto lo = [](std::int64_t a) {
    return int((a - kSubpixel / 2 + kSubpixel - 1) >> kSubpixelBits);
  };
  const auto hi = [](std::int64_t a) { return int((a - kSubpixel / 2) >> kSubpixelBits); };
  p.min_x = std::max(0, lo(x_min));
  p.min_y = std::max(0, lo(y_min));
  p.max_x = std::min(view.width - 1, hi(x_max));
  p.max_y = std::min(view.height - 1, hi(y_max));
  if (p.min_x > p.max_x || p.min_y > p.max_y) return;
  p.face = id;
  out.push_back(p);
}

PolygonSpanWalker::PolygonSpanWalker(const ScreenPolygon& p, int first_row, int last_row) {
  const std::int64_t top = std::int64_t(first_row) * kSubpixel + kSubpixel / 2;
  const std::int64_t bottom = std::int64_t(last_row) * kSubpixel + kSubpixel / 2;
  for (int i = 0; i < p.count; ++i) {
    const FixedPoint a = p.corners[i], b = p.corners[(i + 1) % p.count];
    if (std::max(a.y, b.y) < top || std::min(a.y, b.y) > bottom) continue;
    edges_[count_++] = EdgeWalker(a, b, p.bias(i), first_row);
  }
  empty_ = count_ == 0;  // the rows lie wholly above or below the polygon
}

}  // namespace shadowkit::raster
