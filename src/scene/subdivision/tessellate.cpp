// A crack-free tessellation of the limit surface (Lai & Cheng §5.3): every point on a patch
// edge or corner is evaluated once and shared by the patches around it. Patches may have
// different segment counts: a side takes the most of its patches, and a cell of the coarser
// patch along it is fanned from its centre over the side's extra points.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "shadowkit/core/error.h"
#include "shadowkit/scene/limits.h"
#include "subdivision_impl.h"

namespace shadowkit {
namespace {

constexpr auto kNone = std::uint32_t(-1);

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return std::uint64_t(std::min(a, b)) << 32 | std::max(a, b);
}

/// \brief Segments per patch (n x n cells) and per patch side: the most of the patches that
/// share it, a multiple of each since all are powers of two or all equal.
struct SegmentPlan {
  std::vector<std::uint32_t> patch;
  std::unordered_map<std::uint64_t, std::uint32_t> side;

  SegmentPlan(const SubdivisionSurface& surface, std::vector<std::uint32_t> per_patch)
      : patch(std::move(per_patch)) {
    for (std::uint32_t p = 0; p < patch.size(); ++p) {
      const std::array<std::uint32_t, 4> c = surface.patch_corners(p);
      for (int k = 0; k < 4; ++k) {
        std::uint32_t& m = side[edge_key(c[k], c[(k + 1) % 4])];
        m = std::max(m, patch[p]);
      }
    }
  }
  std::uint32_t side_of(const std::array<std::uint32_t, 4>& c, int k) const {
    return side.at(edge_key(c[k], c[(k + 1) % 4]));
  }
};

/// \brief The soup under construction and the shared points already in it.
class GridPoints {
 public:
  GridPoints(const SubdivisionSurface& surface, const SegmentPlan& plan)
      : surface_(surface), plan_(plan) {}

  /// Soup index of grid point (i, j), i along u, of \p patch's n x n grid.
  std::uint32_t grid_point(std::uint32_t patch, const std::array<std::uint32_t, 4>& c,
                           std::uint32_t i, std::uint32_t j) {
    const std::uint32_t n = plan_.patch[patch];
    // Steps along side k, from its corner k: sides v = 0, u = 1, v = 1, u = 0.
    if (j == 0) return side_point(patch, c, 0, i * (plan_.side_of(c, 0) / n));
    if (i == n) return side_point(patch, c, 1, j * (plan_.side_of(c, 1) / n));
    if (j == n) return side_point(patch, c, 2, (n - i) * (plan_.side_of(c, 2) / n));
    if (i == 0) return side_point(patch, c, 3, (n - j) * (plan_.side_of(c, 3) / n));
    return add(patch, double(i) / n, double(j) / n);
  }

  /// Soup index of the point \p s of side \p k's segments, counted from corner k.
  std::uint32_t side_point(std::uint32_t patch, const std::array<std::uint32_t, 4>& c, int k,
                           std::uint32_t s) {
    const std::uint32_t m = plan_.side_of(c, k);
    // (u, v) x m: from corner k toward corner k + 1, counter-clockwise.
    const std::array<std::array<std::uint32_t, 2>, 4> at{{{s, 0}, {m, s}, {m - s, m}, {0, m - s}}};
    const double u = double(at[k][0]) / m, v = double(at[k][1]) / m;
    if (s == 0 || s == m) {
      const std::uint32_t corner = c[(k + (s == m)) % 4];
      auto [it, inserted] = corner_points_.try_emplace(corner, 0);
      if (inserted) it->second = add(patch, u, v);
      return it->second;
    }
    auto [it, inserted] = edge_points_.try_emplace(edge_key(c[k], c[(k + 1) % 4]));
    if (inserted) it->second.assign(m - 1, kNone);
    // Stored from the lower corner id, so both patches of the side find the same slot.
    const std::uint32_t slot = (c[k] < c[(k + 1) % 4] ? s : m - s) - 1;
    if (it->second[slot] == kNone) it->second[slot] = add(patch, u, v);
    return it->second[slot];
  }

  std::uint32_t add(std::uint32_t patch, double u, double v) {
    soup.positions.push_back(surface_.evaluate(patch, u, v).position);
    return std::uint32_t(soup.positions.size() - 1);
  }

  PolygonSoup soup;

 private:
  const SubdivisionSurface& surface_;
  const SegmentPlan& plan_;
  std::unordered_map<std::uint32_t, std::uint32_t> corner_points_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> edge_points_;
};

// Extra points of side \p k strictly inside cell \p cell (of n along that side, counted
// the way the side runs), when the side has more segments than the patch: r - 1 of them.
void add_side_points(GridPoints& points, std::uint32_t patch, const std::array<std::uint32_t, 4>& c,
                     int k, std::uint32_t cell, std::uint32_t r, std::vector<std::uint32_t>& ring) {
  for (std::uint32_t s = cell * r + 1; s < (cell + 1) * r; ++s) {
    ring.push_back(points.side_point(patch, c, k, s));
  }
}

// Cell (i, j) of \p patch. Two triangles along the shorter diagonal, the pair closer to the
// surface; where a patch side through the cell has extra points (a finer neighbour), a fan
// from the cell's centre over its corners and those points, so that no T-junction is left.
void add_cell(GridPoints& points, const SegmentPlan& plan, std::uint32_t patch,
              const std::array<std::uint32_t, 4>& c, const std::vector<std::uint32_t>& grid,
              std::uint32_t i, std::uint32_t j) {
  const std::uint32_t n = plan.patch[patch];
  const std::uint32_t a = grid[j * (n + 1) + i], b = grid[j * (n + 1) + i + 1];
  const std::uint32_t cc = grid[(j + 1) * (n + 1) + i + 1], d = grid[(j + 1) * (n + 1) + i];
  const std::array<std::uint32_t, 4> r{plan.side_of(c, 0) / n, plan.side_of(c, 1) / n,
                                       plan.side_of(c, 2) / n, plan.side_of(c, 3) / n};
  // Counter-clockwise around the cell: a, bottom, b, right, cc, top, d, left.
  std::vector<std::uint32_t> ring{a};
  if (j == 0) add_side_points(points, patch, c, 0, i, r[0], ring);
  ring.push_back(b);
  if (i == n - 1) add_side_points(points, patch, c, 1, j, r[1], ring);
  ring.push_back(cc);
  if (j == n - 1) add_side_points(points, patch, c, 2, n - 1 - i, r[2], ring);
  ring.push_back(d);
  if (i == 0) add_side_points(points, patch, c, 3, n - 1 - j, r[3], ring);
  PolygonSoup& soup = points.soup;
  if (ring.size() == 4) {
    const std::vector<Vec3>& p = soup.positions;
    if (length(p[cc] - p[a]) <= length(p[d] - p[b])) {
      soup.add_face({a, b, cc});
      soup.add_face({a, cc, d});
    } else {
      soup.add_face({a, b, d});
      soup.add_face({b, cc, d});
    }
    return;
  }
  const std::uint32_t centre = points.add(patch, (i + 0.5) / n, (j + 0.5) / n);
  for (std::size_t t = 0; t < ring.size(); ++t) {
    soup.add_face({centre, ring[t], ring[(t + 1) % ring.size()]});
  }
}

// Triangles the tessellation of \p plan makes: two a cell, or a fan of as many triangles as
// the cell's ring has points where a side has extra points.
std::size_t triangle_count(const SubdivisionSurface& surface, const SegmentPlan& plan) {
  std::size_t total = 0;
  for (std::uint32_t p = 0; p < plan.patch.size(); ++p) {
    const std::uint32_t n = plan.patch[p];
    const std::array<std::uint32_t, 4> c = surface.patch_corners(p);
    std::array<std::size_t, 4> extra{};  // per cell along side k
    for (int k = 0; k < 4; ++k) extra[k] = plan.side_of(c, k) / n - 1;
    for (std::uint32_t j = 0; j < n; ++j) {
      for (std::uint32_t i = 0; i < n; ++i) {
        const std::size_t more = (j == 0 ? extra[0] : 0) + (i == n - 1 ? extra[1] : 0) +
                                 (j == n - 1 ? extra[2] : 0) + (i == 0 ? extra[3] : 0);
        total += more == 0 ? 2 : 4 + more;
      }
    }
  }
  return total;
}

PolygonSoup tessellate_plan(const SubdivisionSurface& surface, const SegmentPlan& plan,
                            std::vector<std::uint32_t>* face_patch) {
  if (face_patch != nullptr) face_patch->clear();
  GridPoints points(surface, plan);
  for (std::uint32_t patch = 0; patch < plan.patch.size(); ++patch) {
    const std::uint32_t n = plan.patch[patch];
    const std::array<std::uint32_t, 4> c = surface.patch_corners(patch);
    std::vector<std::uint32_t> grid((n + 1) * (n + 1));
    for (std::uint32_t j = 0; j <= n; ++j) {
      for (std::uint32_t i = 0; i <= n; ++i)
        grid[j * (n + 1) + i] = points.grid_point(patch, c, i, j);
    }
    const std::size_t first = points.soup.face_count();
    for (std::uint32_t j = 0; j < n; ++j) {
      for (std::uint32_t i = 0; i < n; ++i) add_cell(points, plan, patch, c, grid, i, j);
    }
    if (face_patch != nullptr)
      face_patch->insert(face_patch->end(), points.soup.face_count() - first, patch);
  }
  return std::move(points.soup);
}

/// \brief The limit surface of one patch on the grid of 2n x 2n: even points are the corners
/// of the n x n cells, odd ones their side midpoints and centres.
class DoubledGrid {
 public:
  DoubledGrid(const SubdivisionSurface& surface, std::uint32_t patch, std::uint32_t n)
      : g_(2 * n), points_((g_ + 1) * (g_ + 1)) {
    for (std::uint32_t y = 0; y <= g_; ++y) {
      for (std::uint32_t x = 0; x <= g_; ++x) {
        points_[y * (g_ + 1) + x] = surface.evaluate(patch, double(x) / g_, double(y) / g_);
      }
    }
  }
  Vec3 at(std::uint32_t x, std::uint32_t y) const { return points_[y * (g_ + 1) + x].position; }
  Vec3 normal(std::uint32_t x, std::uint32_t y) const { return points_[y * (g_ + 1) + x].normal(); }
  std::uint32_t size() const { return g_; }

 private:
  std::uint32_t g_;
  std::vector<SurfacePoint> points_;
};

// Whether the limit surface turns from a light within the cell whose lower corner is grid
// point (x, y): its normal's side of the light differs among the corners and the centre.
bool holds_terminator(const DoubledGrid& grid, std::uint32_t x, std::uint32_t y,
                      const ViewTolerance& view) {
  const std::array<std::array<std::uint32_t, 2>, 5> samples{
      {{x, y}, {x + 2, y}, {x + 2, y + 2}, {x, y + 2}, {x + 1, y + 1}}};
  const auto turns = [&](const auto& toward) {
    bool lit = false, unlit = false;
    for (const auto& [sx, sy] : samples) {
      (dot(grid.normal(sx, sy), toward(grid.at(sx, sy))) > 0 ? lit : unlit) = true;
    }
    return lit && unlit;
  };
  for (const Vec3& light : view.point_lights) {
    if (turns([&](Vec3 p) { return light - p; })) return true;
  }
  for (const Vec3& toward : view.toward_lights) {
    if (turns([&](Vec3) { return toward; })) return true;
  }
  return false;
}

// Whether every cell of \p grid is fine enough for \p view: the limit surface within its
// pixels of the cell's chords at the side midpoints and centre, and a cell the terminator
// crosses no more than a pixel across (a facet lies on one side of the light).
bool fine_enough(const DoubledGrid& grid, const ViewTolerance& view) {
  const auto pixel = [&](Vec3 p) { return view.pixel_at_unit_distance * length(p - view.eye); };
  const std::uint32_t g = grid.size();
  for (std::uint32_t y = 0; y < g; y += 2) {
    for (std::uint32_t x = 0; x < g; x += 2) {
      const Vec3 a = grid.at(x, y), b = grid.at(x + 2, y), c = grid.at(x + 2, y + 2),
                 d = grid.at(x, y + 2);
      const std::array<std::pair<Vec3, Vec3>, 5> midpoints{
          {{grid.at(x + 1, y), (a + b) * 0.5},
           {grid.at(x + 2, y + 1), (b + c) * 0.5},
           {grid.at(x + 1, y + 2), (c + d) * 0.5},
           {grid.at(x, y + 1), (d + a) * 0.5},
           {grid.at(x + 1, y + 1), (a + b + c + d) * 0.25}}};
      for (const auto& [surface, chord] : midpoints) {
        if (length(surface - chord) > view.pixels * pixel(surface)) return false;
      }
      const double across = std::max(length(c - a), length(d - b));
      if (across > pixel(grid.at(x + 1, y + 1)) && holds_terminator(grid, x, y, view)) {
        return false;
      }
    }
  }
  return true;
}

// The fewest segments, a power of two up to limits::kTessellation, fine enough for \p view.
std::uint32_t segments_for_view(const SubdivisionSurface& surface, std::uint32_t patch,
                                const ViewTolerance& view) {
  std::uint32_t n = 1;
  while (n < std::uint32_t(limits::kTessellation) &&
         !fine_enough(DoubledGrid(surface, patch, n), view)) {
    n *= 2;
  }
  return n;
}

}  // namespace

PolygonSoup SubdivisionSurface::tessellate(int segments,
                                           std::vector<std::uint32_t>* face_patch) const {
  SHADOWKIT_CHECK(segments >= 1);
  const SegmentPlan plan(*this, std::vector<std::uint32_t>(patch_count(), std::uint32_t(segments)));
  return tessellate_plan(*this, plan, face_patch);
}

ViewTessellation SubdivisionSurface::tessellate_for_view(const ViewTolerance& view,
                                                         std::size_t most_triangles) const {
  std::vector<std::uint32_t> segments(patch_count());
  tbb::parallel_for(std::uint32_t(0), std::uint32_t(patch_count()),
                    [&](std::uint32_t p) { segments[p] = segments_for_view(*this, p, view); });
  ViewTessellation out;
  SegmentPlan plan(*this, segments);
  out.triangles_asked = triangle_count(*this, plan);
  // Over the bound: every patch coarser by halves, until it fits or all are one cell.
  std::size_t count = out.triangles_asked;
  while (count > most_triangles && *std::max_element(segments.begin(), segments.end()) > 1) {
    for (std::uint32_t& n : segments) n = std::max<std::uint32_t>(1, n / 2);
    plan = SegmentPlan(*this, segments);
    count = triangle_count(*this, plan);
    out.coarsened = true;
  }
  out.finest = *std::max_element(segments.begin(), segments.end());
  out.soup = tessellate_plan(*this, plan, nullptr);
  SHADOWKIT_CHECK(out.soup.face_count() == count);
  return out;
}

}  // namespace shadowkit
