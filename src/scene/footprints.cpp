#include "shadowkit/scene/footprints.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
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
std::pair<double, double> columns_at(const std::vector<Point2>& hull, double y) {
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

  // Adds the convex footprint \p hull (plane coordinates) reaching as far as \p far to the
  // cells it covers wholly: a cell's rows y and y + 1 cross it within the cell's columns.
  void add(std::vector<Point2>& hull, double far) {
    if (cells_.empty()) return;
    to_cells(hull);
    const float reach = rounded_up(far);
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

  // Whether every cell that the rectangle [lo, hi] (plane coordinates) touches holds
  // footprints whose far reach is nearer than \p near.
  bool covers(Point2 lo, Point2 hi, double near) const {
    if (cells_.empty()) return false;
    const double x_lo = (lo.x - origin_.x) * scale_, x_hi = (hi.x - origin_.x) * scale_;
    const double y_lo = (lo.y - origin_.y) * scale_, y_hi = (hi.y - origin_.y) * scale_;
    // Compared before conversion: a rectangle far off the grid would overflow an int.
    if (!(x_lo - kSlack >= 0 && y_lo - kSlack >= 0 && x_hi + kSlack < side_ &&
          y_hi + kSlack < side_)) {
      return false;
    }
    const int x0 = int(x_lo - kSlack), x1 = int(x_hi + kSlack);
    const int y0 = int(y_lo - kSlack), y1 = int(y_hi + kSlack);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        if (!(cells_[std::size_t(y) * side_ + std::size_t(x)] < near)) return false;
      }
    }
    return true;
  }

 private:
  void to_cells(std::vector<Point2>& points) const {
    for (Point2& p : points) p = {(p.x - origin_.x) * scale_, (p.y - origin_.y) * scale_};
  }

  Point2 origin_{};
  double scale_ = 0;
  int side_ = 0;
  std::vector<float> cells_;
};

// What the footprint test needs of one sub-object as the light sees it, found for all of
// them at once.
struct SubObjectView {
  double near = 0;            ///< how near the light its box reaches
  int box_face = -1;          ///< the face its box projects onto, -1 if none
  Point2 box_lo{}, box_hi{};  ///< the rectangle of its box's projection
  int hull_face = -1;         ///< a convex sub-object's: the face of its footprint
  std::vector<Point2> hull;   ///< its footprint (plane coordinates)
  double far = 0;             ///< how far from the light its footprint reaches
};

SubObjectView view_of(const SubObjects& parts, std::uint32_t k, const FootprintProjection& view,
                      std::vector<Point2>& points) {
  SubObjectView out;
  out.near = view.near(parts.bounds[k]);
  std::array<Vec3, 8> corners;
  for (int c = 0; c < 8; ++c) corners[std::size_t(c)] = parts.bounds[k].corner(c);
  if (const std::optional<int> face = view.project(corners, points)) {
    out.box_face = *face;
    out.box_lo = out.box_hi = points[0];
    for (const Point2& p : points) {
      out.box_lo = {std::min(out.box_lo.x, p.x), std::min(out.box_lo.y, p.y)};
      out.box_hi = {std::max(out.box_hi.x, p.x), std::max(out.box_hi.y, p.y)};
    }
  }
  if (!parts.convex[k]) return out;  // only a convex hull of its corners is its footprint
  if (const std::optional<int> face = view.project(parts.corners(k), points)) {
    out.hull.resize(convex_hull(std::span(points), out.hull));
    if (out.hull.size() >= 3) {
      out.hull_face = *face;
      out.far = view.far(parts.corners(k));
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
    for (const Point2& p : v.hull) {
      lo[f] = {std::min(lo[f].x, p.x), std::min(lo[f].y, p.y)};
      hi[f] = {std::max(hi[f].x, p.x), std::max(hi[f].y, p.y)};
    }
  }
  std::vector<FaceGrid> grids(faces);
  for (std::size_t f = 0; f < faces; ++f) {
    if (footprints[f] > 0) grids[f] = FaceGrid(lo[f], hi[f], footprints[f]);
  }
  return grids;
}

}  // namespace

std::vector<char> shadowed_sub_objects(const SubObjects& parts, const Light& light,
                                       const Bounds3& scene_bounds) {
  const FootprintProjection view(light);
  std::vector<SubObjectView> views(parts.size());
  tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, std::uint32_t(parts.size()), 256),
                    [&](const auto& r) {
                      std::vector<Point2> points;
                      for (std::uint32_t k = r.begin(); k != r.end(); ++k) {
                        views[k] = view_of(parts, k, view, points);
                      }
                    });
  std::vector<FaceGrid> grids = footprint_grids(views, view);
  // Hazard: distances carry rounding of about 1e-16 of the scene's size; a sub-object
  // touching a footprint's far side stays.
  const double tolerance = 1e-9 * (scene_bounds.diagonal() + length(scene_bounds.center()) +
                                   (light.type == Light::Type::point ? length(light.position) : 0));
  std::vector<std::pair<double, std::uint32_t>> order(parts.size());
  for (std::uint32_t k = 0; k < parts.size(); ++k) order[k] = {views[k].near, k};
  tbb::parallel_sort(order.begin(), order.end());
  // In that order in memory: the loop below, which cannot run in parallel, then reads them
  // one after another.
  std::vector<SubObjectView> nearest_first(parts.size());
  tbb::parallel_for(std::size_t(0), order.size(),
                    [&](std::size_t i) { nearest_first[i] = std::move(views[order[i].second]); });
  // Nearest the light first: a sub-object is tested against the footprints of nearer ones.
  std::vector<char> shadowed(parts.size(), 0);
  for (std::size_t i = 0; i < order.size(); ++i) {
    SubObjectView& v = nearest_first[i];
    if (v.box_face >= 0 &&
        grids[std::size_t(v.box_face)].covers(v.box_lo, v.box_hi, v.near - tolerance)) {
      shadowed[order[i].second] = 1;
    } else if (v.hull_face >= 0) {
      grids[std::size_t(v.hull_face)].add(v.hull, v.far);
    }
  }
  return shadowed;
}

}  // namespace shadowkit
