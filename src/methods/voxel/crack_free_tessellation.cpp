#include "crack_free_tessellation.h"

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

// One leaf's polygon: its points in (u, v) and its triangles, counter-clockwise in (u, v).
struct LeafPolygon {
  std::vector<std::array<double, 2>> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

// §5.3: the zigzag between chain a (corner 0, side 0, corner 1, side 1, corner 2) and chain
// b (corner 0, side 3 backwards, corner 3, side 2 backwards, corner 2), a then b.
LeafPolygon zigzag_polygon(const Tessellator& tessellator, const Leaf& leaf) {
  const auto c = corner_uv(leaf.domain);
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
  LeafPolygon out{a, zigzag(a.size(), b.size())};
  out.points.insert(out.points.end(), b.begin(), b.end());
  return out;
}

// Whether side 2 of \p leaf is one point: a polygon triangle is the patch (a, b, c, c),
// and its leaves on v = 1 are triangles (corner 0, corner 1, c).
bool collapsed(const PatchSet& patches, const Leaf& leaf) {
  const auto& ids = patches[leaf.patch].corner_ids;
  return ids[2] == ids[3] && leaf.domain.v1 == 1;
}

// A collapsed leaf fanned from its centre. The zigzag would end chain b in copies of c and
// pair side 1's points with them: triangles without area, leaving side 1 drawn as one
// segment beside a neighbour that has those points (a T-junction, a crack). The centre is
// on no side's line, so no triangle of the fan lacks area. The patch is planar and affine
// along v = const: the centroid of (corner 0, corner 1, c) is at (u mid, v0 + (1 - v0) / 3).
LeafPolygon fan_polygon(const Tessellator& tessellator, const Leaf& leaf) {
  const auto c = corner_uv(leaf.domain);
  LeafPolygon out;
  for (int k : {0, 1, 3}) {  // side 3 runs from c (corner 3) back to corner 0
    out.points.push_back(c[k]);
    const auto side = tessellator.side_points(leaf, k);
    out.points.insert(out.points.end(), side.begin(), side.end());
  }
  const auto n = std::uint32_t(out.points.size());
  const Domain& d = leaf.domain;
  out.points.push_back({0.5 * (d.u0 + d.u1), d.v0 + (1 - d.v0) / 3});
  for (std::uint32_t k = 0; k < n; ++k) out.triangles.push_back({n, k, (k + 1) % n});
  return out;
}

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
  const std::vector<std::vector<Leaf>> leaves =
      map_leaves<Leaf>(patches, grid, adjacency, [](const Subpatch& leaf, const Domain& d) {
        return Leaf{leaf.patch, d};
      });
  const Tessellator tessellator(patches, leaves);
  SubpatchTessellation out;
  for (const auto& patch_leaves : leaves) {
    for (const Leaf& leaf : patch_leaves) {
      const LeafPolygon polygon = collapsed(patches, leaf) ? fan_polygon(tessellator, leaf)
                                                           : zigzag_polygon(tessellator, leaf);
      const auto first = std::uint32_t(out.triangles.positions.size());
      for (const auto& [u, v] : polygon.points) {
        out.triangles.positions.push_back(patches.point(leaf.patch, u, v));
      }
      for (const auto& t : polygon.triangles) {
        const Vec3 p0 = out.triangles.positions[first + t[0]];
        const Vec3 p1 = out.triangles.positions[first + t[1]];
        const Vec3 p2 = out.triangles.positions[first + t[2]];
        // None of the tested scenes gives a triangle without area any more (collapsed
        // leaves are fanned); a sliver polygon of the input still could, and Mesh::build
        // would drop it (at a tolerance far below this): left out here, counted by the
        // watertightness tests.
        const double longest = std::max({length(p1 - p0), length(p2 - p1), length(p0 - p2)});
        if (!(length(cross(p1 - p0, p2 - p0)) > kFlat * longest * longest)) continue;
        out.triangles.add_face({first + t[0], first + t[1], first + t[2]});
        out.leaf.push_back(std::uint32_t(out.leaf_patch.size()));
      }
      out.leaf_patch.push_back(leaf.patch);
    }
  }
  return out;
}

}  // namespace shadowkit::voxel
