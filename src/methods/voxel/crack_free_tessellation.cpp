#include "crack_free_tessellation.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <limits>
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

// §5.1's first pass: the points evaluated on the patch sides, per shared side id in
// canonical parameters, all that a patch's tessellation needs from its neighbours. A side
// holds O(M) points, so this is kept for the whole scene while the leaves are not.
PointLists shared_side_points(const PatchSet& patches, const VoxelGrid& grid, int adjacency) {
  std::vector<std::vector<std::pair<std::uint64_t, double>>> per_patch(patches.size());
  tbb::parallel_for(std::uint32_t(0), std::uint32_t(patches.size()), [&](std::uint32_t p) {
    voxelize_patch(patches, p, grid, adjacency, [&](const Subpatch&, const Domain& d) {
      for (const auto& [u, v] : corner_uv(d)) {
        if ((u == 0 || u == 1) == (v == 0 || v == 1)) continue;  // inside, or a corner
        const auto [side, t] = PatchSet::side_of(u, v);
        per_patch[p].emplace_back(patches.side_id(p, side), patches.canonical_t(p, side, t));
      }
    });
  });
  PointLists sides;
  for (auto& points : per_patch) {
    for (const auto& [side, t] : points) sides[side].push_back(t);
    std::vector<std::pair<std::uint64_t, double>>().swap(points);
  }
  sort_unique(sides);
  return sides;
}

// The polylines of the leaves of a run of patches: the points of lines inside those patches,
// and of the whole scene's patch sides.
class Tessellator {
 public:
  /// \p leaves: those of patches first_patch, first_patch + 1, ...
  Tessellator(const PatchSet& patches, const PointLists& sides, std::uint32_t first_patch,
              const std::vector<std::vector<Leaf>>& leaves)
      : patches_(patches), sides_(sides), first_patch_(first_patch), lines_(leaves.size()) {
    for (std::size_t p = 0; p < leaves.size(); ++p) index_lines(leaves[p], lines_[p]);
    for (auto& lines : lines_) sort_unique(lines);
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
      const auto& values = lines_[leaf.patch - first_patch_].at(line_key(1 - axis, fixed));
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
  static void index_lines(const std::vector<Leaf>& leaves, PointLists& lines) {
    for (const Leaf& leaf : leaves) {
      for (const auto& [u, v] : corner_uv(leaf.domain)) {
        if (v != 0 && v != 1) lines[line_key(1, v)].push_back(u);
        if (u != 0 && u != 1) lines[line_key(0, u)].push_back(v);
      }
    }
  }

  const PatchSet& patches_;
  const PointLists& sides_;
  std::uint32_t first_patch_;
  std::vector<PointLists> lines_;  ///< per patch of the run: key (axis of the fixed value, value)
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

// Appends \p leaf's polygon to \p out.
void add_leaf(const PatchSet& patches, const Tessellator& tessellator, const Leaf& leaf,
              SubpatchTessellation& out) {
  const LeafPolygon polygon =
      collapsed(patches, leaf) ? fan_polygon(tessellator, leaf) : zigzag_polygon(tessellator, leaf);
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
    out.leaf.push_back(out.first_leaf + std::uint32_t(out.leaf_patch.size()));
  }
  out.leaf_patch.push_back(leaf.patch);
}

// Patches whose leaves are made at once (in parallel, a few per core) and kept while they
// are tessellated: O(M^2) each, so few.
constexpr std::size_t kRunPatches = 4;

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

void tessellate_in_batches(const PatchSet& patches, const VoxelGrid& grid, int adjacency,
                           std::size_t batch_triangles,
                           const std::function<void(SubpatchTessellation)>& batch) {
  const PointLists sides = shared_side_points(patches, grid, adjacency);
  SubpatchTessellation out;
  const auto send = [&] {
    const auto next_leaf = out.first_leaf + std::uint32_t(out.leaf_patch.size());
    batch(std::move(out));
    out = SubpatchTessellation{};
    out.first_leaf = next_leaf;
  };
  for (std::size_t first = 0; first < patches.size(); first += kRunPatches) {
    const std::vector<std::vector<Leaf>> leaves = map_leaves<Leaf>(
        patches, grid, adjacency,
        [](const Subpatch& leaf, const Domain& d) {
          return Leaf{leaf.patch, d};
        },
        first, kRunPatches);
    const Tessellator tessellator(patches, sides, std::uint32_t(first), leaves);
    for (const auto& patch_leaves : leaves) {
      for (const Leaf& leaf : patch_leaves) {
        add_leaf(patches, tessellator, leaf, out);
        if (out.leaf.size() >= batch_triangles) send();
      }
    }
  }
  if (!out.leaf_patch.empty()) send();
}

SubpatchTessellation tessellate_subpatches(const PatchSet& patches, const VoxelGrid& grid,
                                           int adjacency) {
  SubpatchTessellation whole;
  tessellate_in_batches(patches, grid, adjacency, std::numeric_limits<std::size_t>::max(),
                        [&](SubpatchTessellation all) { whole = std::move(all); });
  return whole;
}

}  // namespace shadowkit::voxel
