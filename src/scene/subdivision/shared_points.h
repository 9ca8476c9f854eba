#pragma once
// The points of a crack-free tessellation (Lai & Cheng §5.3): every point on a patch side or
// corner is evaluated once and shared by the patches around it, so a closed control mesh
// gives a closed mesh.
#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>

#include "shadowkit/scene/mesh.h"
#include "shadowkit/scene/subdivision.h"

namespace shadowkit::subdivision {

/// \brief The soup under construction and the points of it that patches share, each patch on
/// a grid of n x n cells (i along u, j along v).
class SharedPoints {
 public:
  SharedPoints(const SubdivisionSurface& surface, std::uint32_t n) : surface_(surface), n_(n) {}

  /// Starts \p patch: its inner points are its own.
  void begin_patch(std::uint32_t patch) {
    patch_ = patch;
    corners_of_patch_ = surface_.patch_corners(patch);
    inner_.clear();
  }

  /// Soup index of grid point (i, j) of the current patch.
  std::uint32_t at(std::uint32_t i, std::uint32_t j) {
    // Sides k = 0..3 are v = 0, u = 1, v = 1, u = 0, each run from corner k toward k + 1.
    if (j == 0) return on_side(0, i, i, j);
    if (i == n_) return on_side(1, j, i, j);
    if (j == n_) return on_side(2, n_ - i, i, j);
    if (i == 0) return on_side(3, n_ - j, i, j);
    auto [it, inserted] = inner_.try_emplace(j * (n_ + 1) + i, 0);
    if (inserted) it->second = add(i, j);
    return it->second;
  }

  /// A new point of the current patch at grid coordinates (i, j), which may be halves.
  std::uint32_t add(double i, double j) {
    soup.positions.push_back(surface_.evaluate(patch_, i / n_, j / n_).position);
    return std::uint32_t(soup.positions.size() - 1);
  }

  PolygonSoup soup;

 private:
  // Point \p s of side \p k, counted from corner k: stored by the side's corner ids and the
  // count from the lower one, so both patches of the side find it.
  std::uint32_t on_side(int k, std::uint32_t s, std::uint32_t i, std::uint32_t j) {
    const std::uint32_t a = corners_of_patch_[k], b = corners_of_patch_[(k + 1) % 4];
    std::uint32_t& slot = s == 0 ? corners_[a]
                          : s == n_
                              ? corners_[b]
                              : sides_[Key{std::min(a, b), std::max(a, b), a < b ? s : n_ - s}];
    if (slot == 0) slot = add(i, j) + 1;
    return slot - 1;
  }

  struct Key {
    std::uint32_t low, high, s;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& key) const {
      return std::hash<std::uint64_t>()(
          (std::uint64_t(key.low) << 32 | key.high) * 0x9E3779B97F4A7C15u ^ key.s);
    }
  };

  const SubdivisionSurface& surface_;
  std::uint32_t n_;
  std::uint32_t patch_ = 0;
  std::array<std::uint32_t, 4> corners_of_patch_{};
  // Soup index + 1, 0 for none yet.
  std::unordered_map<std::uint32_t, std::uint32_t> corners_;
  std::unordered_map<Key, std::uint32_t, KeyHash> sides_;
  std::unordered_map<std::uint32_t, std::uint32_t> inner_;
};

/// Two triangles for the cell (a, b, c, d), counter-clockwise, split along its shorter
/// diagonal: the pair closer to the surface.
inline void add_quad(PolygonSoup& soup, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                     std::uint32_t d) {
  const std::vector<Vec3>& p = soup.positions;
  if (length(p[c] - p[a]) <= length(p[d] - p[b])) {
    soup.add_face({a, b, c});
    soup.add_face({a, c, d});
  } else {
    soup.add_face({a, b, d});
    soup.add_face({b, c, d});
  }
}

}  // namespace shadowkit::subdivision
