#include "shadowkit/scene/footprints.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>

#include "shadowkit/core/convex_hull.h"
#include "shadowkit/core/prefetch.h"

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

  /// Starts loading the cells of \p r (covers and add read and write them).
  void prefetch(const CellRect& r) const {
    for (int y = r.y0; y <= r.y1; ++y) {
      const float* row = cells_.data() + std::size_t(y) * side_;
      __builtin_prefetch(row + r.x0);
      __builtin_prefetch(row + r.x1);
    }
  }

  // Adds the convex footprint \p plane_hull (plane coordinates) reaching as far as \p reach
  // to the cells it covers wholly: a cell's rows y and y + 1 cross it within the cell's
  // columns.
  void add(std::span<const Point2> plane_hull, float reach) {
    if (cells_.empty()) return;
    thread_local std::vector<Point2> hull;
    hull.resize(plane_hull.size());
    std::transform(plane_hull.begin(), plane_hull.end(), hull.begin(),
                   [&](Point2 p) { return to_cells(p); });
    double y_lo = INFINITY, y_hi = -INFINITY;
    for (const Point2& p : hull) y_lo = std::min(y_lo, p.y), y_hi = std::max(y_hi, p.y);
    for (int y = std::max(0, int(std::ceil(y_lo + kSlack)));
         y + 1 <= std::min(double(side_), y_hi - kSlack); ++y) {
      const auto [l0, r0] = columns_at(hull, y);
      const auto [l1, r1] = columns_at(hull, y + 1);
      const int x0 = std::max(0, int(std::ceil(std::max(l0, l1) + kSlack)));
      const int x1 = std::min(side_, int(std::floor(std::min(r0, r1) - kSlack)));
      for (int x = x0; x < x1; ++x) {
        float& c = cells_[std::size_t(y) * side_ + std::size_t(x)];
        c = std::min(c, reach);
      }
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
  std::uint32_t k = 0;                           ///< the sub-object
  double near = 0;                               ///< how near the light its box reaches
  int box_face = -1;                             ///< the face its box projects onto, -1 if none
  Point2 box_lo{}, box_hi{};                     ///< the rectangle of its box's projection
  int hull_face = -1;                            ///< a convex sub-object's: its footprint's face
  std::uint32_t hull_first = 0, hull_count = 0;  ///< its footprint (plane coordinates)
  Point2 hull_lo{}, hull_hi{};                   ///< the footprint's bounds
  float reach = 0;  ///< how far from the light its footprint reaches, rounded up
};

// The bounds [lo, hi] of \p points (at least one).
void bounds_of(std::span<const Point2> points, Point2& lo, Point2& hi) {
  lo = hi = points[0];
  for (const Point2& p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
}

// Sub-object \p k as \p view sees it, its footprint into \p hull (room for its corners).
SubObjectView view_of(const SubObjects& parts, std::uint32_t k, const FootprintProjection& view,
                      Point2* hull) {
  thread_local std::vector<Point2> points, convex;
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
    const std::size_t n = convex_hull(std::span(points), convex);
    if (n >= 3) {
      out.hull_face = *face;
      out.hull_count = std::uint32_t(n);
      std::copy_n(convex.begin(), n, hull);
      bounds_of({hull, n}, out.hull_lo, out.hull_hi);
      out.reach = rounded_up(view.far(parts.corners(k)));
    }
  }
  return out;
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

// Every sub-object as \p view sees it, nearest the light first: the order of the pass over
// them, which cannot run in parallel and then reads them one after another. Their footprints
// go into \p hulls in sub-object order, as the views are made: made in the pass's order, the
// reads of the sub-objects would miss the cache one after another.
std::vector<SubObjectView> nearest_first(const SubObjects& parts, const FootprintProjection& view,
                                         std::vector<Point2>& hulls) {
  std::vector<std::uint32_t> room(parts.size() + 1, 0);  // a footprint has at most its corners
  for (std::size_t k = 0; k < parts.size(); ++k) {
    room[k + 1] = room[k] + std::uint32_t(parts.corners(k).size());
  }
  hulls.resize(room.back());
  std::vector<SubObjectView> by_part(parts.size());
  tbb::parallel_for(std::uint32_t(0), std::uint32_t(parts.size()), [&](std::uint32_t k) {
    by_part[k] = view_of(parts, k, view, hulls.data() + room[k]);
    by_part[k].hull_first = room[k];
  });
  std::vector<std::pair<double, std::uint32_t>> order(parts.size());
  for (std::uint32_t k = 0; k < parts.size(); ++k) order[k] = {by_part[k].near, k};
  tbb::parallel_sort(order.begin(), order.end());
  std::vector<SubObjectView> views(parts.size());
  tbb::parallel_for(std::size_t(0), order.size(),
                    [&](std::size_t i) { views[i] = by_part[order[i].second]; });
  return views;
}

}  // namespace

std::vector<char> shadowed_sub_objects(const SubObjects& parts, const Light& light,
                                       const Bounds3& scene_bounds) {
  const FootprintProjection view(light);
  std::vector<Point2> hulls;
  const std::vector<SubObjectView> views = nearest_first(parts, view, hulls);
  std::vector<FaceGrid> grids = footprint_grids(views, view);
  // Hazard: distances carry rounding of about 1e-16 of the scene's size; a sub-object
  // touching a footprint's far side stays.
  const double tolerance = 1e-9 * (scene_bounds.diagonal() + length(scene_bounds.center()) +
                                   (light.type == Light::Type::point ? length(light.position) : 0));
  // Nearest the light first: a sub-object is tested against the footprints of nearer ones.
  // They lie all over the grids: the cells and footprint of one a few ahead start loading now.
  constexpr std::size_t kLoadAhead = 8;
  std::vector<char> shadowed(parts.size(), 0);
  for (std::size_t i = 0; i < views.size(); ++i) {
    const SubObjectView& v = views[i];
    if (i + kLoadAhead < views.size() && views[i + kLoadAhead].box_face >= 0) {
      const SubObjectView& ahead = views[i + kLoadAhead];
      const FaceGrid& grid = grids[std::size_t(ahead.box_face)];
      if (const std::optional<CellRect> cells = grid.touched(ahead.box_lo, ahead.box_hi))
        grid.prefetch(*cells);
      if (ahead.hull_count > 0) prefetch(hulls[ahead.hull_first]);
    }
    if (v.box_face >= 0) {
      const FaceGrid& grid = grids[std::size_t(v.box_face)];
      const std::optional<CellRect> cells = grid.touched(v.box_lo, v.box_hi);
      if (cells && grid.covers(*cells, v.near - tolerance)) {
        shadowed[v.k] = 1;
        continue;
      }
    }
    if (v.hull_face >= 0) {
      grids[std::size_t(v.hull_face)].add({hulls.data() + v.hull_first, v.hull_count}, v.reach);
    }
  }
  return shadowed;
}

}  // namespace shadowkit
