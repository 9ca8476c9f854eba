#include "view_cells.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace shadowkit::subdivision {
namespace {

/// \brief The limit surface of one patch at grid points, each evaluated once.
class PatchSamples {
 public:
  PatchSamples(const SubdivisionSurface& surface, std::uint32_t patch)
      : surface_(surface), patch_(patch) {}
  const SurfacePoint& at(std::uint32_t x, std::uint32_t y) {
    auto [it, inserted] = points_.try_emplace(y * (kUnits + 1) + x);
    if (inserted) it->second = surface_.evaluate(patch_, double(x) / kUnits, double(y) / kUnits);
    return it->second;
  }

 private:
  const SubdivisionSurface& surface_;
  std::uint32_t patch_;
  std::unordered_map<std::uint32_t, SurfacePoint> points_;
};

/// \brief The limit surface at a cell's corners (0-3, counter-clockwise from its lower one)
/// and centre (4), and how far its normals spread: the most a corner's differs from the
/// centre's, about the angle, and so about how far a chord's normal may differ from them.
struct CellNormals {
  std::array<const SurfacePoint*, 5> points;
  std::array<Vec3, 5> normals;
  double spread = 0;

  CellNormals(PatchSamples& samples, Cell cell) {
    const std::uint32_t x = cell.x, y = cell.y, s = cell.size, h = s / 2;
    points = {&samples.at(x, y), &samples.at(x + s, y), &samples.at(x + s, y + s),
              &samples.at(x, y + s), &samples.at(x + h, y + h)};
    for (std::size_t k = 0; k < 5; ++k) normals[k] = points[k]->normal();
    for (std::size_t k = 0; k < 4; ++k) spread = std::max(spread, length(normals[k] - normals[4]));
  }
};

// Whether a facet of the cell may turn from a light: the limit surface's normal changes
// sides of the light among the corners and the centre, or comes closer to the light's plane
// than the normals spread.
bool near_terminator(const CellNormals& cell, const ViewTolerance& view) {
  const auto turns = [&](const auto& toward) {
    bool lit = false, unlit = false;
    for (std::size_t k = 0; k < 5; ++k) {
      const double facing = dot(cell.normals[k], normalize(toward(cell.points[k]->position)));
      if (std::abs(facing) <= cell.spread) return true;
      (facing > 0 ? lit : unlit) = true;
    }
    return lit && unlit;
  };
  return std::any_of(view.point_lights.begin(), view.point_lights.end(),
                     [&](Vec3 light) { return turns([&](Vec3 p) { return light - p; }); }) ||
         std::any_of(view.toward_lights.begin(), view.toward_lights.end(),
                     [&](Vec3 toward) { return turns([&](Vec3) { return toward; }); });
}

// Whether \p cell is fine enough for \p view: the limit surface within its pixels of the
// cell's chords at the side midpoints and centre; and, where the cell is wider than a pixel,
// its normals within the view's spread (facets are shaded flat) and no facet of it turning
// from a light (there the facets decide the contract's condition 1).
bool fine_enough(PatchSamples& samples, Cell cell, const ViewTolerance& view) {
  const auto pixel = [&](Vec3 p) { return view.pixel_at_unit_distance * length(p - view.eye); };
  const std::uint32_t x = cell.x, y = cell.y, s = cell.size, h = s / 2;
  const Vec3 a = samples.at(x, y).position, b = samples.at(x + s, y).position;
  const Vec3 c = samples.at(x + s, y + s).position, d = samples.at(x, y + s).position;
  const std::array<std::pair<Vec3, Vec3>, 5> midpoints{
      {{samples.at(x + h, y).position, (a + b) * 0.5},
       {samples.at(x + s, y + h).position, (b + c) * 0.5},
       {samples.at(x + h, y + s).position, (c + d) * 0.5},
       {samples.at(x, y + h).position, (d + a) * 0.5},
       {samples.at(x + h, y + h).position, (a + b + c + d) * 0.25}}};
  for (const auto& [surface, chord] : midpoints) {
    if (length(surface - chord) > view.pixels * pixel(surface)) return false;
  }
  if (std::max(length(c - a), length(d - b)) <= pixel(samples.at(x + h, y + h).position)) {
    return true;
  }
  const CellNormals normals(samples, cell);
  return normals.spread <= view.normal_spread && !near_terminator(normals, view);
}

}  // namespace

std::vector<Cell> in_rows(std::vector<Cell> cells) {
  std::sort(cells.begin(), cells.end(),
            [](Cell a, Cell b) { return std::pair(a.y, a.x) < std::pair(b.y, b.x); });
  return cells;
}

std::vector<Cell> coarsened(std::vector<Cell> cells, std::uint16_t size) {
  for (Cell& cell : cells) {
    if (cell.size >= size) continue;
    cell = {std::uint16_t(cell.x / size * size), std::uint16_t(cell.y / size * size), size};
  }
  cells = in_rows(std::move(cells));
  cells.erase(std::unique(cells.begin(), cells.end(),
                          [](Cell a, Cell b) { return a.x == b.x && a.y == b.y; }),
              cells.end());
  return cells;
}

std::array<Cell, 4> quarters(Cell cell) {
  const auto h = std::uint16_t(cell.size / 2);
  return {{{cell.x, cell.y, h},
           {std::uint16_t(cell.x + h), cell.y, h},
           {cell.x, std::uint16_t(cell.y + h), h},
           {std::uint16_t(cell.x + h), std::uint16_t(cell.y + h), h}}};
}

std::optional<std::vector<Cell>> patch_cells(const SubdivisionSurface& surface, std::uint32_t patch,
                                             const ViewTolerance& view, std::uint16_t finest,
                                             std::atomic<std::size_t>& built) {
  PatchSamples samples(surface, patch);
  std::vector<Cell> leaves, open{{0, 0, std::uint16_t(kUnits)}};
  while (!open.empty()) {
    const Cell cell = open.back();
    open.pop_back();
    if (cell.size == finest || fine_enough(samples, cell, view)) {
      leaves.push_back(cell);
      if (++built > kMostCells && finest < kUnits) return std::nullopt;
      continue;
    }
    for (const Cell& quarter : quarters(cell)) open.push_back(quarter);
  }
  return in_rows(std::move(leaves));
}

}  // namespace shadowkit::subdivision
