// The flat per-entry structures of §4 against brute force over the same projection.
#include "projection_entries.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>

namespace shadowkit::voxel {
namespace {

VoxelGrid grid_of(int m) {
  return VoxelGrid{{0, 0, 0}, 1, {m, m, m}};
}

// Small random leaves (about a voxel) all over a 32^3 grid.
std::vector<Subpatch> random_leaves(std::size_t n) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> where(0, 32), jitter(-0.7, 0.7);
  std::vector<Subpatch> leaves(n);
  for (std::size_t l = 0; l < n; ++l) {
    const Vec3 c{where(rng), where(rng), where(rng)};
    for (GridPoint& corner : leaves[l].corner) {
      corner = GridPoint::of(c + Vec3{jitter(rng), jitter(rng), jitter(rng)});
    }
    leaves[l].patch = std::uint32_t(l);
  }
  return leaves;
}

TEST(EntryRectangles, NumbersEveryIncludedEntryOnceAndNothingOutside) {
  EntryRectangles rectangles;
  std::vector<std::uint64_t> entries;
  for (int face : {1, 4}) {
    for (double x : {3.5, 7.5}) {
      for (double y : {10.5, 12.5})
        entries.push_back(LightProjection::entry(PlanePoint{face, x, y}));
    }
  }
  for (std::uint64_t e : entries) rectangles.include(e);
  rectangles.finish();
  EXPECT_EQ(rectangles.size(), 2u * 5 * 3);  // two faces of 5 x 3 entries
  std::set<std::size_t> seen;
  for (std::uint64_t e : entries) {
    const auto index = rectangles.index(e);
    ASSERT_TRUE(index);
    EXPECT_LT(*index, rectangles.size());
    seen.insert(*index);
  }
  EXPECT_EQ(seen.size(), entries.size());
  EXPECT_FALSE(rectangles.index(LightProjection::entry(PlanePoint{1, 8.5, 10.5})));
  EXPECT_FALSE(rectangles.index(LightProjection::entry(PlanePoint{0, 3.5, 10.5})));
  EXPECT_FALSE(EntryRectangles().index(entries[0]));
}

// Every leaf is in the list of the entry of each of its corners, lists are nearest first,
// for a directional light and for a point light inside the grid (all six faces).
void expect_lists_hold_their_leaves(const Light& light) {
  const VoxelGrid grid = grid_of(32);
  const LightProjection projection(light, grid, 1.0);
  const std::vector<Subpatch> leaves = random_leaves(400);
  const BlockingSubpatches lists(projection, leaves);
  std::size_t looked_up = 0;
  for (std::uint32_t l = 0; l < leaves.size(); ++l) {
    for (const GridPoint& c : leaves[l].corner) {
      const auto list = lists.list(projection.entry(c.vec()));
      EXPECT_TRUE(std::is_sorted(list.begin(), list.end()));
      EXPECT_TRUE(std::any_of(list.begin(), list.end(), [&](const auto& r) { return r.leaf == l; }))
          << "leaf " << l;
      looked_up += list.size();
    }
  }
  EXPECT_GE(lists.record_count(), leaves.size());
  EXPECT_GT(looked_up, 0u);
}

TEST(BlockingSubpatches, ListsHoldTheirLeavesNearestFirst) {
  expect_lists_hold_their_leaves(Light::directional({0.3, -1, 0.2}));
  expect_lists_hold_their_leaves(Light::point({16, 16, 16}));
}

TEST(NearestVoxels, IsTheSmallestDistanceOfTheVoxelsProjectedThere) {
  const VoxelGrid grid = grid_of(32);
  const LightProjection projection(Light::point({-10, 40, 5}), grid, 1.0);
  std::vector<GridPoint> centres;
  std::vector<float> distances;
  std::map<std::uint64_t, float> brute;
  for (int x = 0; x < 32; x += 3) {
    for (int y = 0; y < 32; y += 5) {
      for (int z = 0; z < 32; z += 2) {
        centres.push_back(GridPoint::of(VoxelGrid::center({x, y, z})));
        distances.push_back(float(projection.distance(centres.back().vec())));
        const auto [it, fresh] =
            brute.emplace(projection.entry(centres.back().vec()), distances.back());
        if (!fresh) it->second = std::min(it->second, distances.back());
      }
    }
  }
  const NearestVoxels points(
      projection, centres.size(),
      [&](std::size_t i, const auto& centre) { centre(centres[i].vec()); }, 0);
  EXPECT_EQ(points.entry_count(), brute.size());
  for (const auto& [entry, nearest] : brute) EXPECT_EQ(points.nearest(entry), nearest);
  EXPECT_FALSE(points.nearest(LightProjection::entry(PlanePoint{5, 0.5, 0.5})));
}

}  // namespace
}  // namespace shadowkit::voxel
