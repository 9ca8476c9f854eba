#include "crack_free_tessellation.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <unordered_map>

namespace shadowkit::voxel {
namespace {

constexpr double kFlat = 1e-12;

struct Leaf {
  std::uint32_t patch;
  Domain domain;
};

// Parameters evaluated on one line of a patch (a v = const or u = const line inside it),
// or on one shared patch side (canonical parameter).
using PointLists = std::unordered_map<std::uint64_t, std::vector<double>>;

std::uint64_t line_key(int axis, double value) {
  return std::bit_cast<std::uint64_t>(value) << 1 | std::uint64_t(axis);
}

void sort_unique(PointLists& lists) {
  for (auto& [key, values] : lists) {
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
  }
}

// The corners of a leaf in (u, v), in the patch's corner order.
std::array<std::array<double, 2>, 4> corner_uv(const Domain& d) {
  return {{{d.u0, d.v0}, {d.u1, d.v0}, {d.u1, d.v1}, {d.u0, d.v1}}};
}

class Tessellator {
 public:
  Tessellator(const PatchSet& patches, const std::vector<std::vector<Leaf>>& leaves)
      : patches_(patches), leaves_(leaves), lines_(leaves.size()) {
    for (std::uint32_t p = 0; p < leaves.size(); ++p) index_patch(p);
    for (auto& lines : lines_) sort_unique(lines);
    sort_unique(sides_);
  }

  // The points strictly inside side k of \p leaf, in order from corner k.
  std::vector<std::array<double, 2>> side_points(const Leaf& leaf, int k) const {
    const auto c = corner_uv(leaf.domain);
    const auto from = c[k], to = c[(k + 1) % 4];
    const int axis = k % 2 == 0 ? 0 : 1;  // the coordinate that varies along the side
    const double fixed = from[1 - axis];
    std::vector<std::array<double, 2>> out;
    const auto keep = [&](double value) {
      std::array<double, 2> uv;
      uv[axis] = value, uv[1 - axis] = fixed;
      out.push_back(uv);
    };
    const double lo = std::min(from[axis], to[axis]), hi = std::max(from[axis], to[axis]);
    if (fixed == 0 || fixed == 1) {
      // On the patch's own side: the shared list, in canonical parameters. (The side comes
      // from the line, not from an end point, which may be a corner of two sides.)
      const int side = axis == 0 ? (fixed == 0 ? 0 : 2) : (fixed == 0 ? 3 : 1);
      const auto it = sides_.find(patches_.side_id(leaf.patch, side));
      if (it == sides_.end()) return out;  // nothing evaluated between the patch's corners
      for (const double tc : it->second) {
        const auto uv = PatchSet::side_uv(side, patches_.canonical_t(leaf.patch, side, tc));
        if (uv[axis] > lo && uv[axis] < hi) keep(uv[axis]);
      }
    } else {
      const auto& values = lines_[leaf.patch].at(line_key(1 - axis, fixed));
      for (auto it = std::upper_bound(values.begin(), values.end(), lo);
           it != values.end() && *it < hi; ++it) {
        keep(*it);
      }
    }
    // Ascending in the varying coordinate (a patch side's parameter may run either way),
    // then in the side's own direction.
    std::sort(out.begin(), out.end(),
              [axis](const auto& p, const auto& q) { return p[axis] < q[axis]; });
    if (from[axis] > to[axis]) std::reverse(out.begin(), out.end());
    return out;
  }

 private:
  void index_patch(std::uint32_t p) {
    for (const Leaf& leaf : leaves_[p]) {
      for (const auto& [u, v] : corner_uv(leaf.domain)) {
        const bool u_edge = u == 0 || u == 1, v_edge = v == 0 || v == 1;
        if (!v_edge) lines_[p][line_key(1, v)].push_back(u);
        if (!u_edge) lines_[p][line_key(0, u)].push_back(v);
        if (u_edge != v_edge) {
          const auto [side, t] = PatchSet::side_of(u, v);
          sides_[patches_.side_id(p, side)].push_back(patches_.canonical_t(p, side, t));
        }
      }
    }
  }

  const PatchSet& patches_;
  const std::vector<std::vector<Leaf>>& leaves_;
  std::vector<PointLists> lines_;  ///< per patch: key (axis of the fixed value, value)
  PointLists sides_;               ///< per shared side id: canonical parameters
};

}  // namespace

std::vector<std::array<std::uint32_t, 3>> zigzag(std::size_t a, std::size_t b) {
  // a[0] = b[0] = corner 0 and a[last] = b[last] = corner 2: start with (c0, a1, b1) and
  // close with (a[last-1], c2, b[last-1]).
  const auto B = [&](std::size_t j) { return std::uint32_t(a + j); };
  std::vector<std::array<std::uint32_t, 3>> out{{0, 1, B(1)}};
  std::size_t i = 1, j = 1;
  while (i + 1 < a - 1 || j + 1 < b - 1) {
    const bool advance_a =
        j + 1 == b - 1 || (i + 1 < a - 1 && double(i) / double(a - 1) <= double(j) / double(b - 1));
    if (advance_a) {
      out.push_back({std::uint32_t(i), std::uint32_t(i + 1), B(j)});
      ++i;
    } else {
      out.push_back({std::uint32_t(i), B(j + 1), B(j)});
      ++j;
    }
  }
  out.push_back({std::uint32_t(i), std::uint32_t(a - 1), B(j)});
  return out;
}

SubpatchTessellation tessellate_subpatches(const PatchSet& patches, const VoxelGrid& grid,
                                           int adjacency) {
  std::vector<std::vector<Leaf>> leaves(patches.size());
  tbb::parallel_for(std::size_t(0), patches.size(), [&](std::size_t p) {
    voxelize_patch(patches, std::uint32_t(p), grid, adjacency,
                   [&](const Subpatch&, const Domain& d) {
                     leaves[p].push_back({std::uint32_t(p), d});
                   });
  });
  const Tessellator tessellator(patches, leaves);
  SubpatchTessellation out;
  std::uint32_t leaf_id = 0;
  for (const auto& patch_leaves : leaves) {
    for (const Leaf& leaf : patch_leaves) {
      const auto c = corner_uv(leaf.domain);
      // Chain a: corner 0, side 0, corner 1, side 1, corner 2; chain b: corner 0, side 3
      // backwards, corner 3, side 2 backwards, corner 2.
      std::vector<std::array<double, 2>> a{c[0]}, b{c[0]};
      for (int k : {0, 1}) {
        const auto side = tessellator.side_points(leaf, k);
        a.insert(a.end(), side.begin(), side.end());
        a.push_back(c[k + 1]);
      }
      for (int k : {3, 2}) {
        auto side = tessellator.side_points(leaf, k);
        std::reverse(side.begin(), side.end());
        b.insert(b.end(), side.begin(), side.end());
        b.push_back(c[k]);
      }
      const auto first = std::uint32_t(out.triangles.positions.size());
      for (const auto& chain : {a, b}) {
        for (const auto& [u, v] : chain)
          out.triangles.positions.push_back(patches.point(leaf.patch, u, v));
      }
      for (const auto& t : zigzag(a.size(), b.size())) {
        const Vec3 p0 = out.triangles.positions[first + t[0]];
        const Vec3 p1 = out.triangles.positions[first + t[1]];
        const Vec3 p2 = out.triangles.positions[first + t[2]];
        // Collapsed sides (a triangle patch's corner) give triangles without area; those
        // are left out (Mesh::build would drop them too, at a tolerance far below this).
        const double longest = std::max({length(p1 - p0), length(p2 - p1), length(p0 - p2)});
        if (!(length(cross(p1 - p0, p2 - p0)) > kFlat * longest * longest)) continue;
        out.triangles.add_face({first + t[0], first + t[1], first + t[2]});
        out.leaf.push_back(leaf_id);
      }
      ++leaf_id;
    }
  }
  return out;
}

}  // namespace shadowkit::voxel
