#pragma once
// The cells a view asks for: each patch a quadtree, a cell split while the limit surface
// strays from it by more than the view's tolerance, or, where it is wider than a pixel,
// while its normals spread or a facet of it may turn from a light.
#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <vector>

#include "shadowkit/scene/limits.h"
#include "shadowkit/scene/subdivision.h"

namespace shadowkit::subdivision {

/// Grid units a patch side: the finest cell is one unit.
inline constexpr auto kUnits = std::uint32_t(limits::kTessellation);

/// \brief A square cell of a patch, (x, y) its lower corner and size its side, in grid units.
struct Cell {
  std::uint16_t x, y, size;
};

/// \p cells in rows from the patch's (0, 0): the order they are drawn in, whatever the order
/// they were split in.
std::vector<Cell> in_rows(std::vector<Cell> cells);

/// \p cells with every cell smaller than \p size replaced by the one of that size holding it.
std::vector<Cell> coarsened(std::vector<Cell> cells, std::uint16_t size);

/// The four cells of half \p cell's size.
std::array<Cell, 4> quarters(Cell cell);

/// The most cells the quadtrees may hold while they are built (about 100 MB): past it, they
/// are built again with cells at least twice as large, so a view that asks for too much
/// costs bounded memory before it is coarsened.
inline constexpr std::size_t kMostCells = std::size_t(1) << 24;

/// The leaves of \p patch's quadtree for \p view, in rows, down to cells of \p finest grid
/// units; nullopt once \p built, counting the leaves of every patch, passes kMostCells.
std::optional<std::vector<Cell>> patch_cells(const SubdivisionSurface& surface, std::uint32_t patch,
                                             const ViewTolerance& view, std::uint16_t finest,
                                             std::atomic<std::size_t>& built);

}  // namespace shadowkit::subdivision
