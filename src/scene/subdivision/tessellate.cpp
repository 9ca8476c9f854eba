// A crack-free tessellation of the limit surface (Lai & Cheng §5.3): every point on a patch
// edge or corner is evaluated once and shared by the patches around it.
#include <unordered_map>

#include "shadowkit/core/error.h"
#include "subdivision_impl.h"

namespace shadowkit {
namespace {

/// \brief The soup under construction and the shared points already in it.
class GridPoints {
 public:
  GridPoints(const SubdivisionSurface& surface, int segments)
      : surface_(surface), n_(std::uint32_t(segments)) {}

  /// Soup index of every grid point (i, j), i along u, of \p patch, row by row.
  std::vector<std::uint32_t> patch_grid(std::uint32_t patch) {
    const std::array<std::uint32_t, 4> c = surface_.patch_corners(patch);
    std::vector<std::uint32_t> grid((n_ + 1) * (n_ + 1));
    for (std::uint32_t j = 0; j <= n_; ++j) {
      for (std::uint32_t i = 0; i <= n_; ++i) {
        grid[j * (n_ + 1) + i] = point(patch, c, i, j);
      }
    }
    return grid;
  }

  PolygonSoup soup;

 private:
  std::uint32_t point(std::uint32_t patch, const std::array<std::uint32_t, 4>& c, std::uint32_t i,
                      std::uint32_t j) {
    const bool u_end = i == 0 || i == n_, v_end = j == 0 || j == n_;
    if (u_end && v_end) {
      // Corners (u, v) = (0, 0), (1, 0), (1, 1), (0, 1).
      const int corner = j == 0 ? (i == 0 ? 0 : 1) : (i == 0 ? 3 : 2);
      auto [it, inserted] = corner_points_.try_emplace(c[corner], 0);
      if (inserted) it->second = add(patch, i, j);
      return it->second;
    }
    if (v_end) return on_edge(patch, j == 0 ? c[0] : c[3], j == 0 ? c[1] : c[2], i, i, j);
    if (u_end) return on_edge(patch, i == 0 ? c[0] : c[1], i == 0 ? c[3] : c[2], j, i, j);
    return add(patch, i, j);
  }

  // Point \p step of n along the edge from corner id \p a to \p b, stored from the lower id.
  std::uint32_t on_edge(std::uint32_t patch, std::uint32_t a, std::uint32_t b, std::uint32_t step,
                        std::uint32_t i, std::uint32_t j) {
    const std::uint64_t key = std::uint64_t(std::min(a, b)) << 32 | std::max(a, b);
    auto [it, inserted] = edge_points_.try_emplace(key);
    if (inserted) it->second.assign(n_ - 1, kNone);
    const std::uint32_t slot = (a < b ? step : n_ - step) - 1;
    if (it->second[slot] == kNone) it->second[slot] = add(patch, i, j);
    return it->second[slot];
  }

  std::uint32_t add(std::uint32_t patch, std::uint32_t i, std::uint32_t j) {
    soup.positions.push_back(surface_.evaluate(patch, double(i) / n_, double(j) / n_).position);
    return std::uint32_t(soup.positions.size() - 1);
  }

  static constexpr auto kNone = std::uint32_t(-1);
  const SubdivisionSurface& surface_;
  std::uint32_t n_;
  std::unordered_map<std::uint32_t, std::uint32_t> corner_points_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> edge_points_;
};

}  // namespace

PolygonSoup SubdivisionSurface::tessellate(int segments,
                                           std::vector<std::uint32_t>* face_patch) const {
  SHADOWKIT_CHECK(segments >= 1);
  if (face_patch != nullptr) face_patch->clear();
  GridPoints points(*this, segments);
  PolygonSoup& soup = points.soup;
  const auto n = std::uint32_t(segments);
  for (std::uint32_t patch = 0; patch < patch_count(); ++patch) {
    const std::vector<std::uint32_t> grid = points.patch_grid(patch);
    for (std::uint32_t j = 0; j < n; ++j) {
      for (std::uint32_t i = 0; i < n; ++i) {
        // Counter-clockwise in (u, v), like the control face; split along the shorter
        // diagonal, the triangles closer to the surface.
        const std::uint32_t a = grid[j * (n + 1) + i], b = grid[j * (n + 1) + i + 1];
        const std::uint32_t c = grid[(j + 1) * (n + 1) + i + 1], d = grid[(j + 1) * (n + 1) + i];
        const std::vector<Vec3>& p = soup.positions;
        if (length(p[c] - p[a]) <= length(p[d] - p[b])) {
          soup.add_face({a, b, c});
          soup.add_face({a, c, d});
        } else {
          soup.add_face({a, b, d});
          soup.add_face({b, c, d});
        }
        if (face_patch != nullptr) face_patch->insert(face_patch->end(), 2, patch);
      }
    }
  }
  return soup;
}

}  // namespace shadowkit
