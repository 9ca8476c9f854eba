#include "footprints.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <optional>

#include "convex_hull.h"

namespace shadowkit::volume {
namespace {

constexpr int kGrid = 512;       // cells across a face
constexpr double kSlack = 1e-6;  // of a cell: rounding of the projections

struct Point2 {
  double x, y;
};

// Where points lie as seen from the light: a face of the grid, cell coordinates on it, and
// the distance along the light's way. A directional light has one face across its
// direction, over the box \p span; a point light the six faces of a cube around it (a set
// of points whose directions share a face projects centrally onto it, so the hull of their
// projections is the projection of their hull).
class LightView {
 public:
  LightView(const Light& light, const Bounds3& span) : light_(light) {
    if (light.type == Light::Type::point) return;
    const Vec3 d = light.direction;
    u_ = normalize(cross(d, std::abs(d.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
    v_ = normalize(cross(d, u_));
    double u_lo = INFINITY, u_hi = -INFINITY, v_lo = INFINITY, v_hi = -INFINITY;
    if (span.empty()) return;
    for (int c = 0; c < 8; ++c) {
      const Vec3 corner = span.corner(c);
      u_lo = std::min(u_lo, dot(corner, u_)), u_hi = std::max(u_hi, dot(corner, u_));
      v_lo = std::min(v_lo, dot(corner, v_)), v_hi = std::max(v_hi, dot(corner, v_));
    }
    origin_ = {u_lo, v_lo};
    const double extent = std::max(u_hi - u_lo, v_hi - v_lo);
    scale_ = extent > 0 ? kGrid / extent : 0;
  }

  int face_count() const { return light_.type == Light::Type::point ? 6 : 1; }

  /// The face all of \p points project onto and their projections, or nothing when they
  /// do not share one (or the grid is degenerate).
  std::optional<int> project(std::span<const Vec3> points, std::vector<Point2>& out) const {
    out.clear();
    if (light_.type == Light::Type::directional) {
      if (scale_ == 0) return std::nullopt;
      for (const Vec3& p : points) {
        out.push_back({(dot(p, u_) - origin_.x) * scale_, (dot(p, v_) - origin_.y) * scale_});
      }
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
      out.push_back(
          {(d[(axis + 1) % 3] / w + 1) * kGrid / 2, (d[(axis + 2) % 3] / w + 1) * kGrid / 2});
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
  Point2 origin_{};
  double scale_ = 0;
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

// Per face, per cell: the nearest far reach of the footprints covering it wholly.
class FootprintGrid {
 public:
  explicit FootprintGrid(int faces) : cells_(std::size_t(faces)) {}

  // Adds the convex footprint \p hull reaching as far as \p far to the cells it covers
  // wholly: a cell's rows y and y + 1 cross it within the cell's columns.
  void add(int face, const std::vector<Point2>& hull, double far) {
    double y_lo = INFINITY, y_hi = -INFINITY;
    for (const Point2& p : hull) y_lo = std::min(y_lo, p.y), y_hi = std::max(y_hi, p.y);
    std::vector<double>& cells = face_cells(face);
    for (int y = std::max(0, int(std::ceil(y_lo + kSlack)));
         y + 1 <= std::min(double(kGrid), y_hi - kSlack); ++y) {
      const auto [l0, r0] = columns_at(hull, y);
      const auto [l1, r1] = columns_at(hull, y + 1);
      const int x0 = std::max(0, int(std::ceil(std::max(l0, l1) + kSlack)));
      const int x1 = std::min(kGrid, int(std::floor(std::min(r0, r1) - kSlack)));
      for (int x = x0; x < x1; ++x) {
        double& c = cells[std::size_t(y) * kGrid + std::size_t(x)];
        c = std::min(c, far);
      }
    }
  }

  // Whether every cell that the rectangle of \p points touches holds footprints whose far
  // reach is nearer than \p near.
  bool covers(int face, const std::vector<Point2>& points, double near) const {
    const std::vector<double>& cells = cells_[std::size_t(face)];
    if (cells.empty()) return false;
    double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
    for (const Point2& p : points) {
      x_lo = std::min(x_lo, p.x), x_hi = std::max(x_hi, p.x);
      y_lo = std::min(y_lo, p.y), y_hi = std::max(y_hi, p.y);
    }
    const int x0 = int(std::floor(x_lo - kSlack)), x1 = int(std::floor(x_hi + kSlack));
    const int y0 = int(std::floor(y_lo - kSlack)), y1 = int(std::floor(y_hi + kSlack));
    if (x0 < 0 || y0 < 0 || x1 >= kGrid || y1 >= kGrid) return false;
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        if (!(cells[std::size_t(y) * kGrid + std::size_t(x)] < near)) return false;
      }
    }
    return true;
  }

 private:
  std::vector<double>& face_cells(int face) {
    std::vector<double>& cells = cells_[std::size_t(face)];
    if (cells.empty()) cells.assign(std::size_t(kGrid) * kGrid, INFINITY);
    return cells;
  }

  std::vector<std::vector<double>> cells_;
};

}  // namespace

std::vector<char> shadowed_sub_objects(const SubObjects& parts, const Light& light,
                                       const Bounds3& scene_bounds) {
  std::vector<char> shadowed(parts.size(), 0);
  // A directional light's grid spans the footprints only: nothing beyond them is covered.
  Bounds3 occluders;
  for (std::uint32_t k = 0; k < parts.size(); ++k) {
    if (parts.convex[k]) occluders.add(parts.bounds[k]);
  }
  const LightView view(light, occluders);
  // Hazard: distances carry rounding of about 1e-16 of the scene's size; a sub-object
  // touching a footprint's far side stays.
  const double tolerance = 1e-9 * (scene_bounds.diagonal() + length(scene_bounds.center()) +
                                   (light.type == Light::Type::point ? length(light.position) : 0));
  std::vector<double> near(parts.size());
  for (std::size_t k = 0; k < parts.size(); ++k) near[k] = view.near(parts.bounds[k]);
  std::vector<std::uint32_t> order(parts.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return near[a] < near[b] || (near[a] == near[b] && a < b);
  });
  FootprintGrid grid(view.face_count());
  std::vector<Point2> points, hull;
  for (const std::uint32_t k : order) {
    std::array<Vec3, 8> corners;
    for (int c = 0; c < 8; ++c) corners[std::size_t(c)] = parts.bounds[k].corner(c);
    if (const auto face = view.project(corners, points);
        face && grid.covers(*face, points, near[k] - tolerance)) {
      shadowed[k] = 1;
      continue;
    }
    if (!parts.convex[k]) continue;  // only a convex hull of its corners is its footprint
    if (const auto face = view.project(parts.corners(k), points)) {
      hull.resize(convex_hull(std::span(points), hull));
      if (hull.size() >= 3) grid.add(*face, hull, view.far(parts.corners(k)));
    }
  }
  return shadowed;
}

}  // namespace shadowkit::volume
