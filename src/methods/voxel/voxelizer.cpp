#include "voxelizer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>

#include "shadowkit/core/error.h"

namespace shadowkit::voxel {
namespace {

// Below this extent (grid units) a subpatch is a point for the stopping rule.
constexpr double kTinyExtent = 1.0 / 64;
// A safety net on the recursion: 2^-40 of a patch is far below any voxel of a sane grid.
constexpr int kMaxDepth = 40;
// Coordinates of voxel_floor() are clamped here, far outside any grid (M <= 2^12).
constexpr double kFarVoxel = 1 << 20;
// Leaves a patch counts on its own before adding them to the shared total.
constexpr std::uint32_t kCountBatch = 1 << 12;

// Thrown out of every patch's recursion once the leaves counted pass the bound.
struct TooManyLeaves {};

class PatchVoxelizer {
 public:
  using LeafFn = std::function<void(const Subpatch&, const Domain&)>;
  PatchVoxelizer(const PatchSet& patches, std::uint32_t patch, const VoxelGrid& grid, int adjacency,
                 const LeafFn& leaf)
      : patches_(patches), patch_(patch), grid_(grid), adjacency_(adjacency), leaf_(leaf) {}

  void run() { subdivide({0, 1, 0, 1}, {at(0, 0), at(1, 0), at(1, 1), at(0, 1)}, 0); }

 private:
  // At the stored precision, so that the stopping rule and the frame buffer see the same
  // voxel for every corner.
  GridPoint at(double u, double v) const {
    return GridPoint::of(grid_.to_grid(patches_.point(patch_, u, v)));
  }

  // Subpatches whose corners' box misses the grid (one voxel of slack) are dropped: the
  // frame buffer is bounded to what can be seen or shadow what is seen.
  bool outside_grid(const Corners& c) const {
    for (int a = 0; a < 3; ++a) {
      const double lo = std::min({c[0].vec()[a], c[1].vec()[a], c[2].vec()[a], c[3].vec()[a]});
      const double hi = std::max({c[0].vec()[a], c[1].vec()[a], c[2].vec()[a], c[3].vec()[a]});
      if (hi < -1 || lo > grid_.dims[a] + 1) return true;
    }
    return false;
  }

  void subdivide(const Domain& d, const Corners& c, int depth) {
    if (outside_grid(c)) return;
    if (depth == kMaxDepth || small_enough(c, adjacency_)) {
      leaf_({c, patch_}, d);
      return;
    }
    // Split only the directions whose sides are too long: a sliver triangle then costs
    // its length, not its length squared. Each direction stays dyadic, so the points of a
    // shared side are nested and canonical (PatchSet::point).
    const auto v = [&](int k) { return voxel_floor(c[k].vec()); };
    const bool u_short = adjacent(v(0), v(1), adjacency_) && adjacent(v(3), v(2), adjacency_);
    const bool v_short = adjacent(v(0), v(3), adjacency_) && adjacent(v(1), v(2), adjacency_);
    const bool split_u = !u_short || v_short, split_v = !v_short || u_short;
    const double um = 0.5 * (d.u0 + d.u1), vm = 0.5 * (d.v0 + d.v1);
    if (split_u && split_v) {
      const GridPoint b = at(um, d.v0), r = at(d.u1, vm), t = at(um, d.v1), l = at(d.u0, vm);
      const GridPoint m = at(um, vm);
      subdivide({d.u0, um, d.v0, vm}, {c[0], b, m, l}, depth + 1);
      subdivide({um, d.u1, d.v0, vm}, {b, c[1], r, m}, depth + 1);
      subdivide({um, d.u1, vm, d.v1}, {m, r, c[2], t}, depth + 1);
      subdivide({d.u0, um, vm, d.v1}, {l, m, t, c[3]}, depth + 1);
    } else if (split_u) {
      const GridPoint b = at(um, d.v0), t = at(um, d.v1);
      subdivide({d.u0, um, d.v0, d.v1}, {c[0], b, t, c[3]}, depth + 1);
      subdivide({um, d.u1, d.v0, d.v1}, {b, c[1], c[2], t}, depth + 1);
    } else {
      const GridPoint r = at(d.u1, vm), l = at(d.u0, vm);
      subdivide({d.u0, d.u1, d.v0, vm}, {c[0], c[1], r, l}, depth + 1);
      subdivide({d.u0, d.u1, vm, d.v1}, {l, r, c[2], c[3]}, depth + 1);
    }
  }

  const PatchSet& patches_;
  std::uint32_t patch_;
  const VoxelGrid& grid_;
  int adjacency_;
  const LeafFn& leaf_;
};

}  // namespace

void voxelize_patch(const PatchSet& patches, std::uint32_t patch, const VoxelGrid& grid,
                    int adjacency,
                    const std::function<void(const Subpatch&, const Domain&)>& leaf) {
  PatchVoxelizer(patches, patch, grid, adjacency, leaf).run();
}

VoxelIndex voxel_floor(Vec3 g) {
  VoxelIndex v;
  for (int a = 0; a < 3; ++a) v[a] = int(std::floor(std::clamp(g[a], -kFarVoxel, kFarVoxel)));
  return v;
}

bool small_enough(const Corners& corners, int adjacency) {
  const std::array<Vec3, 4> corner{corners[0].vec(), corners[1].vec(), corners[2].vec(),
                                   corners[3].vec()};
  double extent = 0;
  for (int a = 0; a < 3; ++a) {
    const double lo = std::min({corner[0][a], corner[1][a], corner[2][a], corner[3][a]});
    const double hi = std::max({corner[0][a], corner[1][a], corner[2][a], corner[3][a]});
    extent = std::max(extent, hi - lo);
  }
  if (extent < kTinyExtent) return true;
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      if (!adjacent(voxel_floor(corner[i]), voxel_floor(corner[j]), adjacency)) return false;
    }
  }
  return true;
}

namespace {

// What counting made: per patch its leaf count and, if the running total stayed within the
// bound on kept leaves, its leaves.
struct CountedLeaves {
  std::vector<std::uint32_t> counts;
  std::vector<std::vector<Subpatch>> kept;
  bool complete(std::size_t patch) const { return kept[patch].size() == counts[patch]; }
};

// Runs the recursion over every patch and counts the leaves, stopping once they pass
// \p most; a patch keeps its leaves while the total counted stays within \p keep.
std::optional<CountedLeaves> count(const PatchSet& patches, const VoxelGrid& grid, int adjacency,
                                   std::size_t most, std::size_t keep) {
  CountedLeaves out{std::vector<std::uint32_t>(patches.size(), 0),
                    std::vector<std::vector<Subpatch>>(patches.size())};
  std::atomic<std::size_t> total{0};
  try {
    tbb::parallel_for(std::size_t(0), patches.size(), [&](std::size_t p) {
      std::uint32_t& count = out.counts[p];
      std::vector<Subpatch>& kept = out.kept[p];
      bool keeping = total.load(std::memory_order_relaxed) < keep;
      const auto add = [&](std::uint32_t n) {
        const std::size_t counted = total.fetch_add(n, std::memory_order_relaxed) + n;
        if (counted > most) throw TooManyLeaves{};
        if (counted > keep && keeping) {
          keeping = false;
          std::vector<Subpatch>().swap(kept);
        }
      };
      voxelize_patch(patches, std::uint32_t(p), grid, adjacency,
                     [&](const Subpatch& leaf, const Domain&) {
                       if (keeping) kept.push_back(leaf);
                       if (++count % kCountBatch == 0) add(kCountBatch);
                     });
      add(count % kCountBatch);
    });
  } catch (const TooManyLeaves&) {
    return std::nullopt;
  }
  return out;
}

}  // namespace

std::optional<std::size_t> count_leaves(const PatchSet& patches, const VoxelGrid& grid,
                                        int adjacency, std::size_t most) {
  const std::optional<CountedLeaves> counted = count(patches, grid, adjacency, most, 0);
  if (!counted) return std::nullopt;
  return std::accumulate(counted->counts.begin(), counted->counts.end(), std::size_t(0));
}

std::optional<std::vector<Subpatch>> voxelize(const PatchSet& patches, const VoxelGrid& grid,
                                              int adjacency, std::size_t most, std::size_t keep) {
  std::optional<CountedLeaves> counted = count(patches, grid, adjacency, most, keep);
  if (!counted) return std::nullopt;
  const std::vector<std::uint32_t>& counts = counted->counts;
  std::vector<std::size_t> first(counts.size() + 1, 0);
  std::inclusive_scan(counts.begin(), counts.end(), first.begin() + 1, std::plus<>(),
                      std::size_t(0));
  std::vector<Subpatch> leaves(first.back());
  tbb::parallel_for(std::size_t(0), patches.size(), [&](std::size_t p) {
    if (counted->complete(p)) {
      std::copy(counted->kept[p].begin(), counted->kept[p].end(), leaves.begin() + first[p]);
      std::vector<Subpatch>().swap(counted->kept[p]);
      return;
    }
    // Counted only: made again, the same leaves in the same order.
    std::size_t next = first[p];
    voxelize_patch(patches, std::uint32_t(p), grid, adjacency,
                   [&](const Subpatch& leaf, const Domain&) {
                     SHADOWKIT_CHECK(next < first[p + 1]);
                     leaves[next++] = leaf;
                   });
    SHADOWKIT_CHECK(next == first[p + 1]);
  });
  return leaves;
}

}  // namespace shadowkit::voxel
