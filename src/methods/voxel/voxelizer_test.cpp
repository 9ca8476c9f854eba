// Lai & Cheng §3: the stopping rule, separability (no leak through a closed surface),
// minimality (voxels close to the area over a voxel's face) and shared patch sides.
#include "voxelizer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <vector>

#include "cubic_frame_buffer.h"
#include "frame_bound.h"
#include "patch_set.h"
#include "surface_voxels.h"
#include "testing/test_scenes.h"
#include "tunnel_closing.h"

namespace shadowkit::voxel {
namespace {

using testing::box;
using testing::polygon;

Scene scene_of(std::vector<PolygonSoup> soups) {
  return testing::make_scene(testing::camera({0, 0, 10}, {0, 0, 0}, 64, 48),
                             {testing::point_light({0, 10, 0})}, soups);
}

// A closed octahedron, rotated off the axes so that no face lines up with the voxels.
PolygonSoup octahedron(double radius) {
  PolygonSoup s;
  const double c = std::cos(0.3), n = std::sin(0.3);
  const std::vector<Vec3> axes{{c, n, 0}, {-n, c, 0}, {0, 0, 1}};
  for (const Vec3& a : axes) {
    s.positions.push_back(a * radius);
    s.positions.push_back(a * -radius);
  }
  // Vertices 0/1: +-x', 2/3: +-y', 4/5: +-z.
  for (std::uint32_t x : {0u, 1u}) {
    for (std::uint32_t y : {2u, 3u}) {
      for (std::uint32_t z : {4u, 5u}) {
        const bool flip = ((x == 1) != (y == 3)) != (z == 5);
        flip ? s.add_face({x, z, y}) : s.add_face({x, y, z});
      }
    }
  }
  return s;
}

struct Voxelized {
  VoxelGrid grid;
  std::vector<Subpatch> leaves;
  SurfaceVoxels voxels;
};

Voxelized voxelize_scene(const Scene& scene, int resolution, int adjacency,
                         bool corners_only = false) {
  Voxelized v;
  v.grid = make_grid(scene.bounds(), resolution);
  const PatchSet patches(scene);
  v.leaves = *voxelize(patches, v.grid, adjacency, std::numeric_limits<std::size_t>::max());
  v.voxels =
      SurfaceVoxels::collect(v.leaves, v.grid, VoxelKeys(v.grid.dims), adjacency, corners_only);
  return v;
}

// Flood-fills the empty voxels from the grid's corner with \p connectivity-adjacent steps;
// true if it reaches \p inside.
bool leaks(const Voxelized& v, int connectivity, const VoxelIndex& inside) {
  const VoxelKeys keys(v.grid.dims);
  const auto index = [&](const VoxelIndex& a) {
    return (std::size_t(a[2]) * v.grid.dims[1] + a[1]) * v.grid.dims[0] + a[0];
  };
  std::vector<char> blocked(std::size_t(v.grid.dims[0]) * v.grid.dims[1] * v.grid.dims[2], 0);
  for (const std::uint64_t key : v.voxels.keys) blocked[index(keys.voxel(key))] = 1;
  std::deque<VoxelIndex> queue{{0, 0, 0}};
  blocked[0] = 1;
  while (!queue.empty()) {
    const VoxelIndex at = queue.front();
    queue.pop_front();
    if (at == inside) return true;
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const VoxelIndex next{at[0] + dx, at[1] + dy, at[2] + dz};
          if (!v.grid.contains(next) || !adjacent(at, next, connectivity)) continue;
          if (blocked[index(next)]) continue;
          blocked[index(next)] = 1;
          queue.push_back(next);
        }
      }
    }
  }
  return false;
}

TEST(Adjacency, FacesEdgesAndVertices) {
  EXPECT_TRUE(adjacent({1, 1, 1}, {1, 1, 1}, 6));
  EXPECT_TRUE(adjacent({1, 1, 1}, {2, 1, 1}, 6));
  EXPECT_FALSE(adjacent({1, 1, 1}, {2, 2, 1}, 6));
  EXPECT_TRUE(adjacent({1, 1, 1}, {2, 2, 1}, 18));
  EXPECT_FALSE(adjacent({1, 1, 1}, {2, 2, 2}, 18));
  EXPECT_TRUE(adjacent({1, 1, 1}, {2, 2, 2}, 26));
  EXPECT_FALSE(adjacent({1, 1, 1}, {3, 1, 1}, 26));
}

TEST(StoppingRule, StopsWhenEveryPairOfCornerVoxelsIsAdjacent) {
  // Corners in voxels (0,0,0), (1,0,0), (1,1,0), (0,1,0): 18- and 26- but not 6-adjacent.
  const Corners square{{{0.5, 0.5, 0.5}, {1.5, 0.5, 0.5}, {1.5, 1.5, 0.5}, {0.5, 1.5, 0.5}}};
  EXPECT_FALSE(small_enough(square, 6));
  EXPECT_TRUE(small_enough(square, 18));
  EXPECT_TRUE(small_enough(square, 26));
  // Two voxels apart: never small enough.
  const Corners wide{{{0.5, 0.5, 0.5}, {2.5, 0.5, 0.5}, {2.5, 0.6, 0.5}, {0.5, 0.6, 0.5}}};
  EXPECT_FALSE(small_enough(wide, 26));
  // Far below a voxel, even across a voxel corner: a point.
  const Corners tiny{{{0.999f, 0.999f, 0.999f},
                      {1.001f, 0.999f, 0.999f},
                      {1.001f, 1.001f, 1.001f},
                      {0.999f, 1.001f, 0.999f}}};
  EXPECT_TRUE(small_enough(tiny, 6));
}

TEST(StoppingRule, EveryLeafSatisfiesIt) {
  const Scene scene = scene_of({octahedron(3)});
  for (int n : {6, 18, 26}) {
    const Voxelized v = voxelize_scene(scene, 32, n);
    for (const Subpatch& leaf : v.leaves) ASSERT_TRUE(small_enough(leaf.corner, n));
  }
}

// A 26-adjacent voxelization separates 6-connected paths, a 6-adjacent one 26-connected ones.
TEST(Separability, NoLeakFromInsideAClosedSurface) {
  for (const auto& soup : {octahedron(3), box({-2.1, -1.3, -1.7}, {1.9, 2.2, 1.6})}) {
    const Scene scene = scene_of({soup});
    for (const auto& [adjacency, path] : {std::pair{26, 6}, std::pair{18, 6}, std::pair{6, 26}}) {
      const Voxelized v = voxelize_scene(scene, 48, adjacency);
      const VoxelIndex inside = v.grid.voxel_of(v.grid.to_grid({0, 0, 0}));
      EXPECT_FALSE(leaks(v, path, inside)) << "N=" << adjacency << " path " << path;
    }
  }
}

// The surface of a tilted plane: about area x max|n_i| / r^2 voxels (one per column along
// the dominant axis) for N = 26, not a thick slab.
TEST(Minimality, VoxelCountCloseToTheAreaOverAVoxelFace) {
  const Vec3 a{-3, -1, -3}, b{3, -1, -3}, c{3, 2, 3}, d{-3, 2, 3};
  const Scene scene = scene_of({polygon({a, b, c, d})});
  const Voxelized v = voxelize_scene(scene, 64, 26);
  const Vec3 n = normalize(cross(b - a, d - a));
  const double area = length(cross(b - a, d - a)) / (v.grid.size * v.grid.size);
  const double expected = area * max_abs_component(n);
  EXPECT_GT(double(v.voxels.size()), 0.95 * expected);
  EXPECT_LT(double(v.voxels.size()), 1.5 * expected);
}

// A sliver whose two long sides meet at its first corner: taken as given, the patch
// (a, b, c, c) would have long sides in both u and v and be halved both ways down to the
// voxel, about (length / voxel)^2 leaves; with its shortest side first only v is halved.
TEST(Minimality, ASliverCostsItsLengthNotItsLengthSquared) {
  const Scene scene = scene_of({polygon({{0, 0, 0}, {8, 0, 0}, {8, 0.01, 0.02}})});
  const Voxelized v = voxelize_scene(scene, 512, 26);
  const double length_in_voxels = 8 / v.grid.size;  // about 510
  EXPECT_LT(double(v.leaves.size()), 4 * length_in_voxels);
  EXPECT_GT(double(v.voxels.size()), 0.95 * length_in_voxels);
}

// Two triangles walk their shared side in opposite directions; every dyadic point on it is
// the same bits from both (PatchSet::point's owners), so no crack opens between their voxels.
TEST(SharedSides, AreEvaluatedCanonically) {
  PolygonSoup soup;
  soup.positions = {{0.1, 0.2, 0.3}, {3.7, -0.4, 1.1}, {2.9, 3.3, -0.7}, {-0.6, 2.1, 0.9}};
  soup.add_face({0, 1, 2});
  soup.add_face({0, 2, 3});
  const Scene scene = scene_of({soup});
  const PatchSet patches(scene);
  ASSERT_EQ(patches.size(), 2u);
  // Each patch's side between vertices 0 and 2, whichever of its sides the triangle's
  // turn (shortest side first) made it, walked from vertex 0.
  const auto along_0_to_2 = [&](std::size_t p, double t) {
    const auto& ids = patches[p].corner_ids;
    for (int side = 0; side < 4; ++side) {
      const std::uint32_t from = ids[side], to = ids[(side + 1) % 4];
      if (from == 0 && to == 2) {
        const auto [u, v] = PatchSet::side_uv(side, t);
        return patches.point(p, u, v);
      }
      if (from == 2 && to == 0) {
        const auto [u, v] = PatchSet::side_uv(side, 1 - t);
        return patches.point(p, u, v);
      }
    }
    ADD_FAILURE() << "patch " << p << " has no side from vertex 0 to 2";
    return Vec3{};
  };
  for (int k = 0; k <= 64; ++k) {
    const double t = k / 64.0;
    EXPECT_EQ(along_0_to_2(0, t), along_0_to_2(1, t)) << t;
  }
}

// The leaves are counted before they are stored: past the bound there are none, and
// patches counted but not kept are made again, the same leaves in the same order.
TEST(Counting, BoundsTheLeavesAndKeepsTheirOrder) {
  const Scene scene =
      scene_of({octahedron(2), polygon({{-3, -2.5, -3}, {3, -2.5, -3}, {0, -2.5, 3}})});
  const PatchSet patches(scene);
  const VoxelGrid grid = make_grid(scene.bounds(), 64);
  const std::size_t all = std::numeric_limits<std::size_t>::max();
  const std::vector<Subpatch> leaves = *voxelize(patches, grid, 26, all);
  ASSERT_EQ(leaves.size(), 9'119u);
  EXPECT_EQ(count_leaves(patches, grid, 26, all), leaves.size());
  EXPECT_EQ(count_leaves(patches, grid, 26, leaves.size()), leaves.size());
  EXPECT_EQ(count_leaves(patches, grid, 26, leaves.size() - 1), std::nullopt);
  EXPECT_EQ(voxelize(patches, grid, 26, leaves.size() - 1), std::nullopt);
  for (const std::size_t keep : {std::size_t(0), std::size_t(5'000)}) {
    const std::vector<Subpatch> again = *voxelize(patches, grid, 26, all, keep);
    ASSERT_EQ(again.size(), leaves.size()) << keep;
    for (std::size_t l = 0; l < leaves.size(); ++l) {
      ASSERT_EQ(again[l].patch, leaves[l].patch) << keep << " " << l;
      for (int k = 0; k < 4; ++k) {
        ASSERT_EQ(again[l].corner[k].vec(), leaves[l].corner[k].vec()) << keep << " " << l;
      }
    }
  }
}

// A triangle given again, by another object, in another order or winding, is one surface:
// one patch. A triangle sharing two of its corners is not.
TEST(CoincidentTriangles, AreOnePatch) {
  const Vec3 a{0.1, 0.2, 0.3}, b{3.7, -0.4, 1.1}, c{2.9, 3.3, -0.7}, d{-0.6, 2.1, 0.9};
  using testing::polygon;
  const Scene scene = scene_of({polygon({a, b, c}), polygon({a, b, c}), polygon({c, b, a}),
                                polygon({b, c, a}), polygon({a, b, d})});
  const PatchSet patches(scene);
  ASSERT_EQ(patches.size(), 2u);
  EXPECT_EQ(patches[0].object, 0u);
  EXPECT_EQ(patches[1].object, 4u);
}

// A Catmull-Clark cube (a closed limit surface with extraordinary vertices) as one object.
Scene subdivision_scene() {
  Scene scene = scene_of({});
  const PolygonSoup control = box({-2.3, -1.9, -2.1}, {2.2, 2.4, 1.8});
  auto surface = SubdivisionSurface::build(control, "cube");
  scene.objects.push_back({"cube", Mesh::build(surface->tessellate(4), "cube", {}), 0, surface});
  scene.finalize();
  return scene;
}

TEST(SharedSides, SubdivisionPatchesAgreeOnEverySharedSide) {
  const Scene scene = subdivision_scene();
  const PatchSet patches(scene);
  ASSERT_EQ(patches.size(), 24u);  // every cube vertex is extraordinary: subdivided once
  int shared = 0;
  for (std::uint32_t p = 0; p < patches.size(); ++p) {
    for (std::uint32_t q = p + 1; q < patches.size(); ++q) {
      for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
          const auto& a = patches[p].corner_ids;
          const auto& b = patches[q].corner_ids;
          if (a[i] != b[(j + 1) % 4] || a[(i + 1) % 4] != b[j]) continue;  // opposite walks
          ++shared;
          for (int k = 1; k < 16; ++k) {
            const double t = k / 16.0;
            const auto on_side = [](int side, double s) {
              const double uv[4][2] = {{s, 0}, {1, s}, {1 - s, 1}, {0, 1 - s}};
              return std::pair{uv[side][0], uv[side][1]};
            };
            const auto [pu, pv] = on_side(i, t);
            const auto [qu, qv] = on_side(j, 1 - t);
            ASSERT_EQ(patches.point(p, pu, pv), patches.point(q, qu, qv));
          }
        }
      }
    }
  }
  EXPECT_EQ(shared, 48);
}

// §3 on a curved surface: corners in 26-adjacent voxels stop 6-paths, in 6-adjacent voxels
// 26-paths. Where a subpatch grazes a voxel vertex with no corner in the two voxels that
// touch there, N = 6 closes the tunnel (tunnel_closing.h); at M = 48 a 26-path once slipped
// through the cube's surface there.
TEST(Separability, NoLeakFromInsideACatmullClarkSurface) {
  const Scene scene = subdivision_scene();
  for (const int resolution : {32, 48, 64}) {
    for (const auto& [adjacency, path] : {std::pair{26, 6}, std::pair{18, 6}, std::pair{6, 26}}) {
      const Voxelized v = voxelize_scene(scene, resolution, adjacency);
      const VoxelIndex inside = v.grid.voxel_of(v.grid.to_grid({0, 0, 0}));
      EXPECT_FALSE(leaks(v, path, inside)) << "M=" << resolution << " N=" << adjacency;
    }
  }
  // The paper's corners alone (voxel.paper=1) let the 26-path through.
  const Voxelized corners = voxelize_scene(scene, 48, 6, true);
  EXPECT_TRUE(leaks(corners, 26, corners.grid.voxel_of(corners.grid.to_grid({0, 0, 0}))));
}

// Whether the empty voxels of a 2 x 2 x 2 block (bit x + 2y + 4z set for a non-empty one)
// are one 6-connected set, by a flood fill over VoxelIndex adjacency.
bool empties_joined(std::uint8_t occupied) {
  std::vector<VoxelIndex> empty;
  for (int b = 0; b < 8; ++b) {
    if (!(occupied >> b & 1)) empty.push_back({b & 1, b >> 1 & 1, b >> 2 & 1});
  }
  if (empty.empty()) return true;
  std::array<bool, 8> reached{};  // per empty voxel: a vector<bool> trips GCC's null checks
  reached[0] = true;
  for (std::size_t round = 0; round < empty.size(); ++round) {
    for (std::size_t i = 0; i < empty.size(); ++i) {
      for (std::size_t j = 0; j < empty.size(); ++j) {
        if (reached[i] && adjacent(empty[i], empty[j], 6)) reached[j] = true;
      }
    }
  }
  return std::all_of(reached.begin(), reached.begin() + std::ptrdiff_t(empty.size()),
                     [](bool r) { return r; });
}

// Every block: the fill takes only empty voxels and leaves the empty ones joined, and a block
// whose empty voxels are joined already gets none.
TEST(TunnelFill, JoinsTheEmptyVoxelsOfEveryBlock) {
  for (int occupied = 0; occupied < 256; ++occupied) {
    const std::uint8_t fill = tunnel_fill(std::uint8_t(occupied));
    EXPECT_EQ(fill & occupied, 0) << occupied;
    EXPECT_TRUE(empties_joined(std::uint8_t(occupied | fill))) << occupied;
    if (empties_joined(std::uint8_t(occupied))) {
      EXPECT_EQ(fill, 0) << occupied;
    }
  }
  EXPECT_EQ(tunnel_fill(0x00), 0);     // nothing there
  EXPECT_EQ(tunnel_fill(0xFF), 0);     // nothing empty
  EXPECT_EQ(tunnel_fill(0x7E), 0x01);  // the six around the diagonal 0-7: voxel 0 filled
  EXPECT_EQ(tunnel_fill(0xF6), 0x01);  // 0 and 3 touch along an edge, walled off on top
  EXPECT_EQ(tunnel_fill(0x06), 0);     // 0 and 3 joined over the top layer
  EXPECT_EQ(tunnel_fill(0x96), 0x29);  // a checkerboard: three of its four empty voxels
}

// The six voxels around a body diagonal of a block in a 6^3 grid: one end of the diagonal is
// filled, with the samples of a voxel next to it; no voxels, no fill.
TEST(TunnelFill, ClosesATunnelInAGridOnce) {
  VoxelGrid grid;
  grid.dims = {6, 6, 6};
  const VoxelKeys keys(grid.dims);
  std::vector<std::uint64_t> ring;
  for (int b = 1; b < 7; ++b)
    ring.push_back(keys.key({2 + (b & 1), 2 + (b >> 1 & 1), 2 + (b >> 2 & 1)}));
  std::sort(ring.begin(), ring.end());
  const std::vector<TunnelFill> fills = close_tunnels(ring, grid, keys);
  ASSERT_EQ(fills.size(), 1u);
  EXPECT_EQ(keys.voxel(fills[0].key), (VoxelIndex{2, 2, 2}));
  EXPECT_TRUE(std::binary_search(ring.begin(), ring.end(), fills[0].source));
  EXPECT_TRUE(adjacent(keys.voxel(fills[0].source), {2, 2, 2}, 6));
  EXPECT_TRUE(close_tunnels({}, grid, keys).empty());
}

TEST(FrameBound, LeavesOutTheGroundNobodySees) {
  // A camera looking down at a small patch of a 2000-wide ground under a point light.
  Scene scene = testing::make_scene(testing::camera({0, 3, 0.01}, {0, 0, 0}, 64, 48, 30),
                                    {testing::point_light({0, 5, 0})},
                                    {testing::horizontal_quad(-1000, 1000, -1000, 1000, 0),
                                     box({-0.2, 0, -0.2}, {0.2, 0.4, 0.2})});
  const Bounds3 bound = frame_bound(scene, {&scene.camera, 1}, false);
  EXPECT_LT(bound.extent().x, 5.0);
  EXPECT_LT(bound.extent().z, 5.0);
  EXPECT_GE(bound.hi.y, 0.4);
  EXPECT_EQ(frame_bound(scene, {&scene.camera, 1}, true).extent().x, 2000);
  // A camera looking away from everything: nothing to bound but the scene.
  const Camera away = testing::camera({0, 3, 10}, {0, 13, 20}, 64, 48);
  EXPECT_TRUE(view_bound(scene, away).empty());
  EXPECT_EQ(frame_bound(scene, {&away, 1}, false).extent().x, 2000);
}

TEST(FrameBuffer, TwoBitsPerVoxelInSparseBricks) {
  VoxelGrid grid;
  grid.dims = {1024, 1024, 1024};
  const VoxelKeys keys(grid.dims);
  const std::vector<std::uint64_t> sorted{keys.key({0, 0, 0}), keys.key({7, 7, 7}),
                                          keys.key({1023, 5, 600})};
  CubicFrameBuffer buffer(grid, sorted);
  EXPECT_EQ(buffer.state({7, 7, 7}), VoxelState::lit);
  buffer.set(keys.key({7, 7, 7}), VoxelState::shadowed);
  EXPECT_EQ(buffer.state({7, 7, 7}), VoxelState::shadowed);
  EXPECT_EQ(buffer.state({0, 0, 0}), VoxelState::lit);
  EXPECT_EQ(buffer.state({6, 7, 7}), VoxelState::empty);
  EXPECT_EQ(buffer.state({1023, 5, 600}), VoxelState::lit);
  EXPECT_EQ(buffer.state({-1, 0, 0}), VoxelState::empty);
  EXPECT_EQ(keys.voxel(keys.key({1023, 5, 600})), (VoxelIndex{1023, 5, 600}));
  // The directory (128^3 bricks x 4 bytes) and two bricks of 128 bytes.
  EXPECT_EQ(buffer.memory_bytes(), 128u * 128 * 128 * 4 + 2 * 128);
}

}  // namespace
}  // namespace shadowkit::voxel
