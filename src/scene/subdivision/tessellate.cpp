// The uniform tessellation of the limit surface: n x n cells a patch, two triangles each.
#include "shadowkit/core/error.h"
#include "shared_points.h"
#include "subdivision_impl.h"

namespace shadowkit {

PolygonSoup SubdivisionSurface::tessellate(int segments,
                                           std::vector<std::uint32_t>* face_patch) const {
  SHADOWKIT_CHECK(segments >= 1);
  const auto n = std::uint32_t(segments);
  if (face_patch != nullptr) face_patch->assign(patch_count() * n * n * 2, 0);
  subdivision::SharedPoints points(*this, n);
  PolygonSoup& soup = points.soup;
  std::vector<std::uint32_t> grid((n + 1) * (n + 1));
  for (std::uint32_t patch = 0; patch < patch_count(); ++patch) {
    points.begin_patch(patch);
    for (std::uint32_t j = 0; j <= n; ++j) {
      for (std::uint32_t i = 0; i <= n; ++i) grid[j * (n + 1) + i] = points.at(i, j);
    }
    if (face_patch != nullptr) {
      std::fill_n(face_patch->begin() + std::ptrdiff_t(soup.face_count()), n * n * 2, patch);
    }
    for (std::uint32_t j = 0; j < n; ++j) {
      for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t a = grid[j * (n + 1) + i], b = grid[j * (n + 1) + i + 1];
        const std::uint32_t c = grid[(j + 1) * (n + 1) + i + 1], d = grid[(j + 1) * (n + 1) + i];
        subdivision::add_quad(soup, a, b, c, d);
      }
    }
  }
  return std::move(soup);
}

}  // namespace shadowkit
