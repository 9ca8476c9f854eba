// A tessellation of the limit surface fitted to a view: the cells the view asks for
// (view_cells.h), balanced 2:1 and fanned from their centres over the corners of finer
// neighbours along their sides, within a patch and across patch sides alike, so that no
// T-junction is left.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <optional>
#include <unordered_map>

#include "shadowkit/core/error.h"
#include "shadowkit/scene/limits.h"
#include "shared_points.h"
#include "subdivision_impl.h"
#include "view_cells.h"

namespace shadowkit {
namespace {

using subdivision::Cell;
using subdivision::kUnits;

std::uint64_t side_key(std::uint32_t a, std::uint32_t b) {
  return std::uint64_t(std::min(a, b)) << 32 | std::max(a, b);
}

/// \brief The grid points of one patch that are corners of cells: of its own cells inside
/// it, and of its own or its neighbour's on its sides, so that both patches of a side fan
/// over the same points.
class Corners {
 public:
  Corners() : inner_((kUnits + 1) * (kUnits + 1)) {}

  /// Marks the corners of \p cells.
  void mark_cells(const std::vector<Cell>& cells) {
    std::fill(inner_.begin(), inner_.end(), false);
    for (const Cell& cell : cells) {
      for (const auto& [dx, dy] : {std::pair{0, 0}, {1, 0}, {0, 1}, {1, 1}}) {
        inner_[(cell.y + dy * cell.size) * (kUnits + 1) + cell.x + dx * cell.size] = true;
      }
    }
  }

  /// The marked points of side k (v = 0, u = 1, v = 1, u = 0), counted from corner k.
  std::vector<std::uint16_t> on_side(int k) const {
    std::vector<std::uint16_t> out;
    for (std::uint32_t s = 0; s <= kUnits; ++s) {
      const auto [x, y] = side_point(k, s);
      if (inner_[y * (kUnits + 1) + x]) out.push_back(std::uint16_t(s));
    }
    return out;
  }

  /// Marks the points of side \p k counted from corner k.
  void mark_side(int k, const std::vector<std::uint16_t>& points) {
    for (const std::uint16_t s : points) {
      const auto [x, y] = side_point(k, s);
      inner_[y * (kUnits + 1) + x] = true;
    }
  }

  bool marked(std::uint32_t x, std::uint32_t y) const { return inner_[y * (kUnits + 1) + x]; }

  static std::array<std::uint32_t, 2> side_point(int k, std::uint32_t s) {
    const std::array<std::array<std::uint32_t, 2>, 4> at{
        {{s, 0}, {kUnits, s}, {kUnits - s, kUnits}, {0, kUnits - s}}};
    return at[std::size_t(k)];
  }

 private:
  std::vector<bool> inner_;
};

/// \brief Per patch side, the union of both patches' cell corners on it, counted from the
/// side's lower corner id.
class SidePoints {
 public:
  SidePoints(const SubdivisionSurface& surface, const std::vector<std::vector<Cell>>& cells) {
    Corners corners;
    for (std::uint32_t patch = 0; patch < cells.size(); ++patch) {
      corners.mark_cells(cells[patch]);
      const std::array<std::uint32_t, 4> c = surface.patch_corners(patch);
      for (int k = 0; k < 4; ++k) {
        const bool from_low = c[k] < c[(k + 1) % 4];
        std::vector<std::uint16_t>& side = sides_[side_key(c[k], c[(k + 1) % 4])];
        for (const std::uint16_t s : corners.on_side(k)) {
          side.push_back(from_low ? s : std::uint16_t(kUnits - s));
        }
      }
    }
    for (auto& [key, side] : sides_) {
      std::sort(side.begin(), side.end());
      side.erase(std::unique(side.begin(), side.end()), side.end());
    }
  }

  /// The points of \p patch's side \p k, counted from corner k.
  std::vector<std::uint16_t> of(const std::array<std::uint32_t, 4>& c, int k) const {
    std::vector<std::uint16_t> out = sides_.at(side_key(c[k], c[(k + 1) % 4]));
    if (c[k] > c[(k + 1) % 4]) {
      for (std::uint16_t& s : out) s = std::uint16_t(kUnits - s);
    }
    return out;
  }

 private:
  std::unordered_map<std::uint64_t, std::vector<std::uint16_t>> sides_;
};

// Marks the corners that \p patch's cells are fanned over.
void mark_patch(Corners& corners, const SubdivisionSurface& surface, const SidePoints& sides,
                std::uint32_t patch, const std::vector<Cell>& cells) {
  corners.mark_cells(cells);
  const std::array<std::uint32_t, 4> c = surface.patch_corners(patch);
  for (int k = 0; k < 4; ++k) corners.mark_side(k, sides.of(c, k));
}

// The marked points around \p cell, counter-clockwise from its lower corner.
std::vector<std::array<std::uint32_t, 2>> ring(const Corners& corners, Cell cell) {
  const std::uint32_t x = cell.x, y = cell.y, s = cell.size;
  std::vector<std::array<std::uint32_t, 2>> out;
  for (std::uint32_t t = 0; t < s; ++t) {
    if (corners.marked(x + t, y)) out.push_back({x + t, y});
  }
  for (std::uint32_t t = 0; t < s; ++t) {
    if (corners.marked(x + s, y + t)) out.push_back({x + s, y + t});
  }
  for (std::uint32_t t = 0; t < s; ++t) {
    if (corners.marked(x + s - t, y + s)) out.push_back({x + s - t, y + s});
  }
  for (std::uint32_t t = 0; t < s; ++t) {
    if (corners.marked(x, y + s - t)) out.push_back({x, y + s - t});
  }
  return out;
}

// Whether a cell meets one less than half its size along a side: a corner is marked there
// between its side's ends and midpoint.
bool meets_finer_than_half(const Corners& corners, Cell cell) {
  const std::uint32_t s = cell.size, h = s / 2;
  for (std::uint32_t t = 1; t < s; ++t) {
    if (t == h) continue;
    if (corners.marked(cell.x + t, cell.y) || corners.marked(cell.x + s, cell.y + t) ||
        corners.marked(cell.x + t, cell.y + s) || corners.marked(cell.x, cell.y + t)) {
      return true;
    }
  }
  return false;
}

// Splits cells until none meets one less than half its size, in its patch or across a patch
// side (a 2:1 balanced quadtree): a fanned cell then has at most one more point a side, and
// no fan of slivers, each shaded flat its own way, saws along a change of size.
void balance(const SubdivisionSurface& surface, std::vector<std::vector<Cell>>& cells) {
  for (bool split = true; split;) {
    split = false;
    const SidePoints sides(surface, cells);
    Corners corners;
    for (std::uint32_t patch = 0; patch < cells.size(); ++patch) {
      mark_patch(corners, surface, sides, patch, cells[patch]);
      std::vector<Cell> balanced;
      for (const Cell& cell : cells[patch]) {
        if (!meets_finer_than_half(corners, cell)) {
          balanced.push_back(cell);
          continue;
        }
        const std::array<Cell, 4> q = subdivision::quarters(cell);
        balanced.insert(balanced.end(), q.begin(), q.end());
        split = true;
      }
      cells[patch] = subdivision::in_rows(std::move(balanced));
    }
  }
}

// Triangles of a cell with \p points around it: two, or a fan from its centre.
std::size_t cell_triangles(std::size_t points) {
  return points == 4 ? 2 : points;
}

std::size_t triangle_count(const SubdivisionSurface& surface,
                           const std::vector<std::vector<Cell>>& cells) {
  const SidePoints sides(surface, cells);
  Corners corners;
  std::size_t total = 0;
  for (std::uint32_t patch = 0; patch < cells.size(); ++patch) {
    mark_patch(corners, surface, sides, patch, cells[patch]);
    for (const Cell& cell : cells[patch]) total += cell_triangles(ring(corners, cell).size());
  }
  return total;
}

PolygonSoup tessellate_cells(const SubdivisionSurface& surface,
                             const std::vector<std::vector<Cell>>& cells) {
  const SidePoints sides(surface, cells);
  Corners corners;
  subdivision::SharedPoints points(surface, kUnits);
  PolygonSoup& soup = points.soup;
  for (std::uint32_t patch = 0; patch < cells.size(); ++patch) {
    points.begin_patch(patch);
    mark_patch(corners, surface, sides, patch, cells[patch]);
    std::vector<std::uint32_t> around;
    for (const Cell& cell : cells[patch]) {
      around.clear();
      for (const auto& [x, y] : ring(corners, cell)) around.push_back(points.at(x, y));
      if (around.size() == 4) {
        subdivision::add_quad(soup, around[0], around[1], around[2], around[3]);
        continue;
      }
      const double h = cell.size / 2.0;
      const std::uint32_t centre = points.add(cell.x + h, cell.y + h);
      for (std::size_t t = 0; t < around.size(); ++t) {
        soup.add_face({centre, around[t], around[(t + 1) % around.size()]});
      }
    }
  }
  return std::move(soup);
}

}  // namespace

ViewTessellation SubdivisionSurface::tessellate_for_view(const ViewTolerance& view,
                                                         std::size_t most_triangles) const {
  ViewTessellation out;
  std::vector<std::vector<Cell>> cells(patch_count());
  for (std::uint16_t finest = 1;; finest *= 2) {
    std::atomic<std::size_t> built = 0;
    std::atomic<bool> over = false;
    tbb::parallel_for(std::uint32_t(0), std::uint32_t(patch_count()), [&](std::uint32_t p) {
      if (over) return;
      std::optional<std::vector<Cell>> leaves =
          subdivision::patch_cells(*this, p, view, finest, built);
      if (leaves) cells[p] = std::move(*leaves);
      if (!leaves) over = true;
    });
    if (!over) break;
    out.coarsened = true;
    out.asked_exactly = false;
  }
  balance(*this, cells);
  const auto smallest = [&] {
    std::uint16_t size = kUnits;
    for (const auto& patch : cells) {
      for (const Cell& cell : patch) size = std::min(size, cell.size);
    }
    return size;
  };
  // Past kMostCells cells, each of two triangles at least, the view asked for more.
  std::size_t count = triangle_count(*this, cells);
  out.triangles_asked = out.asked_exactly ? count : std::max(count, 2 * subdivision::kMostCells);
  // Over the bound: the finest cells merged into their parents, until it fits or every
  // patch is one cell.
  while (count > most_triangles && smallest() < kUnits) {
    const auto size = std::uint16_t(smallest() * 2);
    for (auto& patch : cells) patch = subdivision::coarsened(std::move(patch), size);
    count = triangle_count(*this, cells);
    out.coarsened = true;
  }
  out.finest = int(kUnits / smallest());
  out.soup = tessellate_cells(*this, cells);
  SHADOWKIT_CHECK(out.soup.face_count() == count);
  return out;
}

}  // namespace shadowkit
