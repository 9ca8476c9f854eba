#include "shadowkit/scene/footprints.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <optional>
#include <utility>

#include "shadowkit/core/convex_hull.h"

namespace shadowkit {
namespace {

// A face's grid has about this many cells per footprint on it, within [kMinCells, kMaxCells]
// cells across: footprints that overlap must each cover many cells for their union to hide
// what lies behind the seams between them.
constexpr double kCellsPerFootprint = 16;
constexpr int kMinCells = 128, kMaxCells = 2048;
constexpr double kSlack = 1e-6;  // of a cell: rounding of the projections

struct Point2 {
  double x, y;
};

// Where points lie as seen from the light: a face, coordinates on its plane, and the distance
// along the light's way. A directional light has one face across its direction; a point
// light the six faces of a cube around it (a set of points whose directions share a face
// projects centrally onto it, so the hull of their projections is the projection of their
// hull).
class FootprintProjection {
 public:
  explicit FootprintProjection(const Light& light) : light_(light) {
    if (light.type == Light::Type::point) return;
    const Vec3 d = light.direction;
    u_ = normalize(cross(d, std::abs(d.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
    v_ = normalize(cross(d, u_));
  }

  int face_count() const { return light_.type == Light::Type::point ? 6 : 1; }

  /// The face all of \p points project onto and their coordinates on its plane, or nothing
  /// when they do not share one.
  std::optional<int> project(std::span<const Vec3> points, std::vector<Point2>& out) const {
    out.clear();
    if (light_.type == Light::Type::directional) {
      for (const Vec3& p : points) out.push_back({dot(p, u_), dot(p, v_)});
      return 0;
    }
    std::optional<int> face;
    for (const Vec3& p : points) {
      const Vec3 d = p - light_.position;
      const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
      const int axis = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
      const int f = 2 * axis + (d[axis] < 0);
      if ((face && *face != f) || !(std::abs(d[axis]) > 0)) return std::nullopt;
      face = f;
      const double w = std::abs(d[axis]);
      out.push_back({d[(axis + 1) % 3] / w, d[(axis + 2) % 3] / w});
    }
    return face;
  }

  /// How far along the light's way the farthest of \p points lies.
  double far(std::span<const Vec3> points) const {
    double out = -INFINITY;
    for (const Vec3& p : points) out = std::max(out, depth(p));
    return out;
  }
  /// How far along the light's way the nearest point of \p box lies.
  double near(const Bounds3& box) const {
    if (light_.type == Light::Type::directional) {
      double out = INFINITY;
      for (int c = 0; c < 8; ++c) out = std::min(out, depth(box.corner(c)));
      return out;
    }
    return box.distance(light_.position);
  }

 private:
  double depth(Vec3 p) const {
    return light_.type == Light::Type::point ? length(p - light_.position)
                                             : dot(p, light_.direction);
  }
  const Light& light_;
  Vec3 u_, v_;
};

// The columns [left, right] of a convex polygon along the line at height \p y; empty
// (left > right) where the line misses it.
std::pair<double, double> columns_at(std::span<const Point2> hull, double y) {
  double left = INFINITY, right = -INFINITY;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Point2 a = hull[i], b = hull[(i + 1) % hull.size()];
    if ((a.y > y) == (b.y > y) && a.y != y) continue;
    const double x = a.y == b.y ? a.x : a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y);
    left = std::min(left, x), right = std::max(right, x);
    if (a.y == b.y) left = std::min(left, b.x), right = std::max(right, b.x);
  }
  return {left, right};
}

// \p x as a float no smaller: a far reach rounded up never makes a footprint reach nearer.
float rounded_up(double x) {
  const float f = float(x);
  return double(f) < x ? std::nextafter(f, INFINITY) : f;
}

// The cells [x0, x1] x [y0, y1] of a face's grid.
struct CellRect {
  int x0, x1, y0, y1;
};

// One face's cells: the nearest far reach of the footprints covering each wholly. The cells
// span the square around where the footprints fall on the face's plane.
class FaceGrid {
 public:
  FaceGrid() = default;
  // \p lo, \p hi: the corners of every footprint on the face lie between them.
  FaceGrid(Point2 lo, Point2 hi, std::size_t footprints) : origin_(lo) {
    const double extent = std::max(hi.x - lo.x, hi.y - lo.y);
    if (!(extent > 0) || !std::isfinite(extent)) return;
    side_ =
        std::clamp(int(std::sqrt(kCellsPerFootprint * double(footprints))), kMinCells, kMaxCells);
    scale_ = side_ / extent;
    cells_.assign(std::size_t(side_) * side_, INFINITY);
  }

  /// \p p (plane coordinates) in cell units.
  Point2 to_cells(Point2 p) const {
    return {(p.x - origin_.x) * scale_, (p.y - origin_.y) * scale_};
  }

  /// The cells that the rectangle [lo, hi] (plane coordinates) touches, or none when it
  /// reaches off the grid (or there is none).
  std::optional<CellRect> touched(Point2 lo, Point2 hi) const {
    if (cells_.empty()) return std::nullopt;
    const Point2 a = to_cells(lo), b = to_cells(hi);
    // Compared before conversion: a rectangle far off the grid would overflow an int.
    if (!(a.x - kSlack >= 0 && a.y - kSlack >= 0 && b.x + kSlack < side_ && b.y + kSlack < side_)) {
      return std::nullopt;
    }
    return CellRect{int(a.x - kSlack), int(b.x + kSlack), int(a.y - kSlack), int(b.y + kSlack)};
  }

  int side() const { return side_; }

  /// Whether every cell of \p r holds footprints whose far reach is nearer than \p near.
  bool covers(const CellRect& r, double near) const {
    // In floats, rounded down: a reach equal to the rounded value keeps the sub-object.
    float below = float(near);
    if (double(below) > near) below = std::nextafter(below, -INFINITY);
    for (int y = r.y0; y <= r.y1; ++y) {
      // A whole row at a time, without a branch per cell: the compiler vectorizes it.
      const float* row = cells_.data() + std::size_t(y) * side_;
      int covered = 0;
      for (int x = r.x0; x <= r.x1; ++x) covered += row[x] < below;
      if (covered != r.x1 - r.x0 + 1) return false;
    }
    return true;
  }

  // Adds the convex footprint \p plane_hull (plane coordinates) reaching as far as \p reach
  // to the cells of columns [\p lo, \p hi) it covers wholly: a cell's rows y and y + 1 cross
  // it within the cell's columns.
  void add(std::span<const Point2> plane_hull, float reach, int lo, int hi) {
    if (cells_.empty()) return;
    thread_local std::vector<Point2> hull;
    hull.resize(plane_hull.size());
    std::transform(plane_hull.begin(), plane_hull.end(), hull.begin(),
                   [&](Point2 p) { return to_cells(p); });
    double y_lo = INFINITY, y_hi = -INFINITY;
    for (const Point2& p : hull) y_lo = std::min(y_lo, p.y), y_hi = std::max(y_hi, p.y);
    int y = std::max(0, int(std::ceil(y_lo + kSlack)));
    for (auto [l0, r0] = columns_at(hull, y); y + 1 <= std::min(double(side_), y_hi - kSlack);
         ++y) {
      const auto [l1, r1] = columns_at(hull, y + 1);
      const int x0 = std::max(lo, int(std::ceil(std::max(l0, l1) + kSlack)));
      const int x1 = std::min(hi, int(std::floor(std::min(r0, r1) - kSlack)));
      for (int x = x0; x < x1; ++x) {
        float& c = cells_[std::size_t(y) * side_ + std::size_t(x)];
        c = std::min(c, reach);
      }
      l0 = l1, r0 = r1;
    }
  }

 private:
  Point2 origin_{};
  double scale_ = 0;
  int side_ = 0;
  std::vector<float> cells_;
};

// What the footprint test needs of one sub-object as the light sees it.
struct SubObjectView {
  std::uint32_t k = 0;            ///< the sub-object
  double near = 0;                ///< how near the light its box reaches
  int box_face = -1;              ///< the face its box projects onto, -1 if none
  Point2 box_lo{}, box_hi{};      ///< the rectangle of its box's projection
  int hull_face = -1;             ///< a convex sub-object's: its footprint's face
  std::span<const Vec3> corners;  ///< its corners, whose projections make its footprint
  Point2 hull_lo{}, hull_hi{};    ///< the footprint's bounds
  float reach = 0;                ///< how far from the light its footprint reaches, rounded up
};

// The bounds [lo, hi] of \p points (at least one).
void bounds_of(std::span<const Point2> points, Point2& lo, Point2& hi) {
  lo = hi = points[0];
  for (const Point2& p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
}

// Sub-object \p k as \p view sees it. Its footprint, the convex hull of its corners' projections,
// is left to when it is added: most sub-objects of a large field lie in the shadow of nearer
// ones and add none; its bounds are those of the projections.
SubObjectView view_of(const SubObjects& parts, std::uint32_t k, const FootprintProjection& view) {
  thread_local std::vector<Point2> points;
  SubObjectView out;
  out.k = k;
  out.near = view.near(parts.bounds[k]);
  std::array<Vec3, 8> corners;
  for (int c = 0; c < 8; ++c) corners[std::size_t(c)] = parts.bounds[k].corner(c);
  if (const std::optional<int> face = view.project(corners, points)) {
    out.box_face = *face;
    bounds_of(points, out.box_lo, out.box_hi);
  }
  if (!parts.convex[k]) return out;  // only a convex hull of its corners is its footprint
  if (const std::optional<int> face = view.project(parts.corners(k), points)) {
    out.hull_face = *face;
    out.corners = parts.corners(k);
    bounds_of(points, out.hull_lo, out.hull_hi);
    out.reach = rounded_up(view.far(parts.corners(k)));
  }
  return out;
}

// The footprint of a sub-object with \p corners on its face of \p view, into \p hull;
// returns its corner count (under 3: it covers no cell).
std::size_t footprint(std::span<const Vec3> corners, const FootprintProjection& view,
                      std::vector<Point2>& hull) {
  thread_local std::vector<Point2> points;
  view.project(corners, points);
  return convex_hull(std::span(points), hull);
}

// Per face of \p view, a grid around the footprints in \p views that fall on it.
std::vector<FaceGrid> footprint_grids(const std::vector<SubObjectView>& views,
                                      const FootprintProjection& view) {
  const std::size_t faces = std::size_t(view.face_count());
  std::vector<Point2> lo(faces, {INFINITY, INFINITY}), hi(faces, {-INFINITY, -INFINITY});
  std::vector<std::size_t> footprints(faces, 0);
  for (const SubObjectView& v : views) {
    if (v.hull_face < 0) continue;
    const std::size_t f = std::size_t(v.hull_face);
    ++footprints[f];
    lo[f] = {std::min(lo[f].x, v.hull_lo.x), std::min(lo[f].y, v.hull_lo.y)};
    hi[f] = {std::max(hi[f].x, v.hull_hi.x), std::max(hi[f].y, v.hull_hi.y)};
  }
  std::vector<FaceGrid> grids(faces);
  for (std::size_t f = 0; f < faces; ++f) {
    if (footprints[f] > 0) grids[f] = FaceGrid(lo[f], hi[f], footprints[f]);
  }
  return grids;
}

// Every sub-object as \p view sees it, nearest the light first: the order in which each
// strip of the grids takes them, reading them one after another. The views are made in
// sub-object order, which reads the sub-objects one after another, then put in order.
std::vector<SubObjectView> nearest_first(const SubObjects& parts, const FootprintProjection& view) {
  std::vector<SubObjectView> by_part(parts.size());
  tbb::parallel_for(std::uint32_t(0), std::uint32_t(parts.size()),
                    [&](std::uint32_t k) { by_part[k] = view_of(parts, k, view); });
  std::vector<std::pair<double, std::uint32_t>> order(parts.size());
  for (std::uint32_t k = 0; k < parts.size(); ++k) order[k] = {by_part[k].near, k};
  tbb::parallel_sort(order.begin(), order.end());
  std::vector<SubObjectView> views(parts.size());
  tbb::parallel_for(std::size_t(0), order.size(),
                    [&](std::size_t i) { views[i] = by_part[order[i].second]; });
  return views;
}

// A face's grid in strips of this many columns, taken in parallel. A sub-object in the shadow
// of nearer ones would change no cell if it added its footprint: nearer footprints already
// hold each cell of it, reaching nearer. So whether a box is covered depends only on the
// footprints nearer the light, never on another box's test: each strip is taken on its own,
// a box is shadowed when every strip it touches covers it, and the answers are those of one
// pass over the whole grid. A strip's cells (64 columns of at most 2048 rows) stay in the
// cache while the sub-objects go by.
constexpr int kStripCells = 64;

// One sub-object as a strip takes it: the test of its box against the strip's cells, or the
// addition of its footprint to them, or both.
struct StripEntry {
  enum : std::uint8_t { kTest = 1, kAdd = 2 };
  double near = 0;                ///< SubObjectView::near
  std::span<const Vec3> corners;  ///< SubObjectView::corners
  std::uint32_t k = 0;            ///< the sub-object
  float reach = 0;                ///< SubObjectView::reach
  CellRect cells{};               ///< the cells its box touches, within the strip
  std::uint8_t what = 0;
};

// The columns [lo, hi) of one face's grid, and what each sub-object that reaches them asks
// of them, nearest the light first: each strip reads its entries one after another.
struct Strip {
  int face = 0, lo = 0, hi = 0;
  std::vector<StripEntry> entries;
};

// The strips of every face's grid, with the boxes each tests and the footprints it adds, in
// the views' order; \p tested (per sub-object) marks the boxes that lie within their grid,
// the only ones tested.
std::vector<Strip> strips_of(const std::vector<SubObjectView>& views,
                             const std::vector<FaceGrid>& grids, std::vector<char>& tested) {
  std::vector<Strip> strips;
  std::vector<std::size_t> first(grids.size() + 1, 0);  // per face, its first strip
  for (std::size_t f = 0; f < grids.size(); ++f) {
    for (int lo = 0; lo < grids[f].side(); lo += kStripCells) {
      strips.push_back({int(f), lo, std::min(grids[f].side(), lo + kStripCells), {}});
    }
    first[f + 1] = strips.size();
  }
  // Adds \p what of \p v to the strips of face f that columns [x0, x1] reach.
  const auto add_to = [&](const SubObjectView& v, int f, int x0, int x1, CellRect cells,
                          std::uint8_t what) {
    const int last = int(first[f + 1] - first[f]) - 1;
    for (int s = std::max(0, x0 / kStripCells); s <= std::min(last, x1 / kStripCells); ++s) {
      Strip& strip = strips[first[f] + std::size_t(s)];
      if (!strip.entries.empty() && strip.entries.back().k == v.k) {
        strip.entries.back().what |= what;
        continue;
      }
      CellRect within = cells;
      within.x0 = std::max(cells.x0, strip.lo), within.x1 = std::min(cells.x1, strip.hi - 1);
      strip.entries.push_back({v.near, v.corners, v.k, v.reach, within, what});
    }
  };
  for (const SubObjectView& v : views) {
    if (v.box_face >= 0) {
      if (const std::optional<CellRect> cells =
              grids[std::size_t(v.box_face)].touched(v.box_lo, v.box_hi)) {
        tested[v.k] = 1;
        add_to(v, v.box_face, cells->x0, cells->x1, *cells, StripEntry::kTest);
      }
    }
    if (v.hull_face < 0 || grids[std::size_t(v.hull_face)].side() == 0) continue;
    const FaceGrid& grid = grids[std::size_t(v.hull_face)];
    const double x0 = std::floor(grid.to_cells(v.hull_lo).x), x1 = grid.to_cells(v.hull_hi).x;
    if (x1 < 0 || x0 >= grid.side()) continue;
    add_to(v, v.hull_face, int(std::max(x0, 0.0)), int(std::min(x1, double(grid.side()))), {},
           StripEntry::kAdd);
  }
  return strips;
}

}  // namespace

std::vector<char> shadowed_sub_objects(const SubObjects& parts, const Light& light,
                                       const Bounds3& scene_bounds) {
  const FootprintProjection view(light);
  std::vector<FaceGrid> grids;
  std::vector<Strip> strips;
  std::vector<char> shadowed(parts.size(), 0);  // first: the boxes tested
  {
    const std::vector<SubObjectView> views = nearest_first(parts, view);
    grids = footprint_grids(views, view);
    strips = strips_of(views, grids, shadowed);
  }
  // Hazard: distances carry rounding of about 1e-16 of the scene's size; a sub-object
  // touching a footprint's far side stays.
  const double tolerance = 1e-9 * (scene_bounds.diagonal() + length(scene_bounds.center()) +
                                   (light.type == Light::Type::point ? length(light.position) : 0));
  tbb::parallel_for(
      std::size_t(0), strips.size(),
      [&](std::size_t s) {
        const Strip& strip = strips[s];
        FaceGrid& grid = grids[std::size_t(strip.face)];
        thread_local std::vector<Point2> hull;
        for (std::size_t e = 0; e < strip.entries.size(); ++e) {
          // The corners of a footprint a few entries ahead start loading now.
          if (e + 4 < strip.entries.size() && strip.entries[e + 4].what & StripEntry::kAdd) {
            for (const Vec3& c : strip.entries[e + 4].corners) __builtin_prefetch(&c);
          }
          const StripEntry& entry = strip.entries[e];
          bool covered = false;
          if (entry.what & StripEntry::kTest) {
            covered = grid.covers(entry.cells, entry.near - tolerance);
            if (!covered)
              std::atomic_ref<char>(shadowed[entry.k]).store(0, std::memory_order_relaxed);
          }
          // Where the strip covers the box, its footprint would change no cell of it.
          if (entry.what & StripEntry::kAdd && !covered) {
            const std::size_t n = footprint(entry.corners, view, hull);
            if (n >= 3) grid.add({hull.data(), n}, entry.reach, strip.lo, strip.hi);
          }
        }
      },
      tbb::simple_partitioner());
  return shadowed;
}

}  // namespace shadowkit
