#include "shadowkit/raster/scan_converter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <mutex>
#include <random>
#include <string>

#include "shadowkit/core/image.h"
#include "shadowkit/raster/triangle_setup.h"
#include "testing/test_scenes.h"

namespace shadowkit {
namespace {

// Calls fn(triangle, x, y) for every pixel centre each set-up triangle owns, in triangle order.
template <class Fn>
void for_each_owned_pixel(const Scene& scene, const RasterProjection& view, Fn&& fn) {
  raster::setup_triangles(scene, view)
      .for_each([&](std::uint32_t, const raster::ScreenTriangle& t) {
        raster::SpanWalker walker(t, t.min_y);
        for (int y = t.min_y; y <= t.max_y; ++y, walker.next_row()) {
          int x0 = t.min_x, x1 = t.max_x;
          if (!walker.span(x0, x1)) continue;
          for (int x = x0; x <= x1; ++x) fn(t, x, y);
        }
      });
}

// How many triangles own each pixel centre (the fill rule, independent of depth).
Image<int> coverage(const Scene& scene, const RasterProjection& view) {
  Image<int> count(view.width, view.height, 0);
  for_each_owned_pixel(scene, view,
                       [&](const raster::ScreenTriangle&, int x, int y) { ++count.at(x, y); });
  return count;
}

// A z = 0 sheet of n x n quads with jittered inner vertices, split into triangles along
// alternating diagonals: many shared edges in every direction.
PolygonSoup jittered_sheet(int n, double half, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.35, 0.35);
  PolygonSoup s;
  const double step = 2 * half / n;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const bool inner = i > 0 && j > 0 && i < n && j < n;
      s.positions.push_back({-half + step * (i + (inner ? jitter(rng) : 0)),
                             -half + step * (j + (inner ? jitter(rng) : 0)), 0});
    }
  }
  auto v = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if ((i + j) % 2) {
        s.add_face({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
        s.add_face({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
      } else {
        s.add_face({v(i, j), v(i + 1, j), v(i, j + 1)});
        s.add_face({v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
      }
    }
  }
  return s;
}

// Vertices snap to fixed point as std::llround would: halves away from zero, and the
// doubles either side of each half to the nearer integer.
TEST(ScanConverter, SnappingRoundsAsLlround) {
  EXPECT_EQ(raster::round_to_integer(0.49999999999999994), 0);
  EXPECT_EQ(raster::round_to_integer(0.5), 1);
  EXPECT_EQ(raster::round_to_integer(-0.5), -1);
  EXPECT_EQ(raster::round_to_integer(-0.0), 0);
  EXPECT_EQ(raster::round_to_integer(4503599627370495.5), 4503599627370496);  // 2^52 - 1/2
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(-1e9, 1e9);
  for (int i = 0; i < 100000; ++i) {
    const double half = std::floor(coordinate(random)) + 0.5;
    for (const double x :
         {half, std::nextafter(half, -1e300), std::nextafter(half, 1e300), coordinate(random)}) {
      ASSERT_EQ(raster::round_to_integer(x), std::llround(x)) << std::hexfloat << x;
    }
  }
}

TEST(ScanConverter, SharedEdgesCoverEveryPixelExactlyOnce) {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    // The sheet is larger than the view: every pixel must be covered once, none twice.
    const Scene scene = testing::make_scene(testing::camera({0.1, -0.2, 5}, {0, 0, 0}, 160, 120),
                                            {}, {jittered_sheet(23, 6, seed)});
    const RasterProjection view = RasterProjection::from_camera(scene.camera, 1e-3);
    const Image<int> count = coverage(scene, view);
    int gaps = 0, doubles = 0;
    for (int c : count.pixels) gaps += c == 0, doubles += c > 1;
    EXPECT_EQ(gaps, 0) << "seed " << seed;
    EXPECT_EQ(doubles, 0) << "seed " << seed;
  }
}

TEST(ScanConverter, EdgesThroughPixelCentresAreOwnedOnce) {
  // An orthographic 8x8 view of [0,8]^2: vertices at pixel centres and corners, a fan of
  // triangles around a vertex exactly on a pixel centre, axis-aligned and diagonal edges
  // through pixel centres.
  PolygonSoup s;
  s.positions = {{0, 0, 0},   {8, 0, 0},   {8, 8, 0},   {0, 8, 0},  {3.5, 4.5, 0},
                 {3.5, 0, 0}, {8, 4.5, 0}, {3.5, 8, 0}, {0, 4.5, 0}};
  const std::uint32_t c = 4;
  s.add_face({0, 5, c});
  s.add_face({5, 1, c});
  s.add_face({1, 6, c});
  s.add_face({6, 2, c});
  s.add_face({2, 7, c});
  s.add_face({7, 3, c});
  s.add_face({3, 8, c});
  s.add_face({8, 0, c});
  const Scene scene = testing::make_scene(testing::camera({4, 4, 5}, {4, 4, 0}, 8, 8), {}, {s});
  const RasterProjection view =
      RasterProjection::orthographic_view({4, 4, 0}, {0, 0, -1}, {0, 1, 0}, 4, 4, 5, 8, 8);
  const Image<int> count = coverage(scene, view);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) EXPECT_EQ(count.at(x, y), 1) << x << "," << y;
  }
}

TEST(ScanConverter, NearPlaneClippingLeavesNoCracks) {
  // A ground sheet running far behind the camera: every triangle crossing the near plane
  // is clipped, and the clipped pieces must still tile the image below the horizon.
  PolygonSoup sheet = jittered_sheet(31, 50, 7);
  for (Vec3& p : sheet.positions) p = {p.x, 0, p.y};
  const Scene scene =
      testing::make_scene(testing::camera({0.3, 1, 0}, {0.3, 0.2, -5}, 120, 90, 100), {}, {sheet});
  const RasterProjection view = RasterProjection::from_camera(scene.camera, 0.05);
  const Image<int> count = coverage(scene, view);
  int doubles = 0, gaps_below_horizon = 0;
  for (int y = 0; y < view.height; ++y) {
    for (int x = 0; x < view.width; ++x) {
      doubles += count.at(x, y) > 1;
      // Rows well below the horizon see the sheet everywhere.
      if (y > 3 * view.height / 4) gaps_below_horizon += count.at(x, y) == 0;
    }
  }
  EXPECT_EQ(doubles, 0);
  EXPECT_EQ(gaps_below_horizon, 0);
}

// The edge tests, over every 8 x 8 block of random triangles' bounds: a block that
// may_own_pixel_in rejects holds no pixel centre the triangle owns, and one that
// owns_every_pixel_in accepts holds only owned ones. Of slivers, the first rejects most
// blocks; of wide triangles, the second accepts most of those they own whole.
TEST(ScanConverter, EdgeTestsBoundTheOwnedPixelsOfEachBlock) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.95, 0.95), thin(0.005, 0.05), wide(0.3, 0.9);
  PolygonSoup slivers;
  for (int i = 0; i < 240; ++i) {
    const Vec3 a{u(rng), u(rng), 0}, b{u(rng), u(rng), 0};
    const Vec3 off = (i < 200 ? thin(rng) : wide(rng)) * normalize(Vec3{a.y - b.y, b.x - a.x, 0});
    const auto v = std::uint32_t(slivers.positions.size());
    slivers.positions.insert(slivers.positions.end(), {a, b, b + off});
    slivers.add_face({v, v + 1, v + 2});
  }
  const Scene scene =
      testing::make_scene(testing::camera({0, 0, 3}, {0, 0, 0}, 256, 256, 40), {}, {slivers});
  const RasterProjection view = RasterProjection::from_camera(scene.camera, 1e-3);
  std::size_t sliver_blocks = 0, rejected = 0, whole = 0, accepted = 0;
  raster::setup_triangles(scene, view)
      .for_each([&](std::uint32_t, const raster::ScreenTriangle& t) {
        Image<int> owned((t.max_x - t.min_x) / 8 + 1, (t.max_y - t.min_y) / 8 + 1, 0);
        raster::SpanWalker walker(t, t.min_y);
        for (int y = t.min_y; y <= t.max_y; ++y, walker.next_row()) {
          int x0 = t.min_x, x1 = t.max_x;
          if (!walker.span(x0, x1)) continue;
          for (int x = x0; x <= x1; ++x) ++owned.at((x - t.min_x) / 8, (y - t.min_y) / 8);
        }
        const bool sliver = t.face < 200;
        for (int by = 0; by < owned.height; ++by) {
          for (int bx = 0; bx < owned.width; ++bx) {
            const int xa = t.min_x + 8 * bx, ya = t.min_y + 8 * by;
            const int xb = std::min(xa + 7, int(t.max_x)), yb = std::min(ya + 7, int(t.max_y));
            const int pixels = (xb - xa + 1) * (yb - ya + 1);
            sliver_blocks += sliver;
            whole += !sliver && owned.at(bx, by) == pixels;
            if (raster::owns_every_pixel_in(t, xa, xb, ya, yb)) {
              accepted += !sliver;
              ASSERT_EQ(owned.at(bx, by), pixels)
                  << "block " << bx << "," << by << " of " << t.face;
            }
            if (raster::may_own_pixel_in(t, xa, xb, ya, yb)) continue;
            rejected += sliver;
            ASSERT_EQ(owned.at(bx, by), 0) << "block " << bx << "," << by << " of " << t.face;
          }
        }
      });
  EXPECT_GT(sliver_blocks, 10000u);
  EXPECT_GT(rejected, sliver_blocks * 3 / 4) << rejected << " of " << sliver_blocks;
  EXPECT_GT(whole, 1000u);
  EXPECT_GT(accepted, whole * 3 / 4) << accepted << " of " << whole;
}

TEST(ScanConverter, NearestFaceWinsWithoutBackFaceCulling) {
  // Two squares facing away from each other; the nearer one hides the farther one from
  // both sides.
  const Scene scene = testing::make_scene(
      testing::camera({0, 5, 0.01}, {0, 0, 0}, 32, 32, 30), {},
      {testing::horizontal_quad(-1, 1, -1, 1, 0), testing::horizontal_quad(-1, 1, -1, 1, 1)});
  const ScanConverter sc(scene);
  const DepthFaceBuffer top = sc.rasterize(RasterProjection::from_camera(scene.camera, 1e-3), {});
  EXPECT_EQ(top.face[16 * 32 + 16], 1u);
  Scene below = scene;
  below.camera = testing::camera({0, -5, 0.01}, {0, 0, 0}, 32, 32, 30);
  const DepthFaceBuffer bottom =
      ScanConverter(below).rasterize(RasterProjection::from_camera(below.camera, 1e-3), {});
  EXPECT_EQ(bottom.face[16 * 32 + 16], 0u);
  EXPECT_NEAR(1.0 / bottom.depth_key[16 * 32 + 16], 5.0, 1e-3);  // view depth, off-axis pixel
}

// Every triangle but those of faces \p skip names depth-tested over the whole raster in
// triangle order, the first of equally near ones kept: what the tiles, their hierarchical
// depth and their nearest-first order must reproduce bit for bit.
DepthFaceBuffer in_triangle_order(const Scene& scene, const RasterProjection& view,
                                  const std::function<bool(std::uint32_t)>& skip = {}) {
  std::vector<double> key(std::size_t(view.width) * view.height, -INFINITY);
  std::vector<std::uint32_t> face(key.size(), kNoFace);
  for_each_owned_pixel(scene, view, [&](const raster::ScreenTriangle& t, int x, int y) {
    if (skip && skip(t.face)) return;
    const std::size_t i = std::size_t(y) * view.width + x;
    const double z = t.key_a * x + (t.key_b * y + t.key_c);
    if (z > key[i]) key[i] = z, face[i] = t.face;
  });
  DepthFaceBuffer out;
  out.width = view.width, out.height = view.height, out.face = face;
  for (double k : key) out.depth_key.push_back(float(k));
  return out;
}

// \p boxes random boxes seen at a low angle, several deep on most pixels, each as \p copies
// coincident objects one after another, and two coincident squares; looking at \p target.
// The last column of tiles is 11 pixels wide: a block of 8 and one of 3.
Scene random_boxes(int boxes, unsigned seed, Vec3 target = {0, 2, 0}, int copies = 1) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-10, 10), size(0.2, 1.5);
  std::vector<PolygonSoup> objects;
  for (int i = 0; i < boxes; ++i) {
    const Vec3 lo{u(rng), 0.5 * (u(rng) + 10), u(rng)};
    const PolygonSoup box = testing::box(lo, lo + Vec3{size(rng), size(rng), size(rng)});
    objects.insert(objects.end(), std::size_t(copies), box);
  }
  objects.push_back(testing::horizontal_quad(-30, 30, -30, 30, 0));
  objects.push_back(testing::horizontal_quad(-30, 30, -30, 30, 0));
  return testing::make_scene(testing::camera({0, 4, 25}, target, 203, 150, 50), {}, objects);
}

// What expect_drawn_as_in_triangle_order saw: pixels of the first coincident square, and the
// scan converter's tiles that show nothing.
struct Drawn {
  std::size_t ground = 0;
  int empty_tiles = 0;
};

// The scan converter's buffer of \p scene's view into \p tiles, checked pixel for pixel
// against its triangles drawn in triangle order without the far side of each box from the
// eye: its near side hides it. Drawn, it takes pixel centres along the silhouettes only,
// where snapped to 1/256 pixel it reaches past the near side (or ties with it on their
// shared edge).
void expect_as_in_triangle_order(const Scene& scene, const RasterProjection& view,
                                 DepthFaceBuffer& tiles) {
  tiles = ScanConverter(scene).rasterize(view, {});
  const DepthFaceBuffer reference = in_triangle_order(scene, view, [&](std::uint32_t f) {
    return scene.outward_solids().far_side_from(scene, f, view.eye);
  });
  for (std::size_t i = 0; i < tiles.face.size(); ++i) {
    ASSERT_EQ(tiles.face[i], reference.face[i]) << "pixel " << i;
    ASSERT_EQ(tiles.depth_key[i], reference.depth_key[i]) << "pixel " << i;
  }
}

// random_boxes, looking at \p target: the lower face id wins on the coincident squares, as
// the first in triangle order does.
void expect_drawn_as_in_triangle_order(int boxes, unsigned seed, Vec3 target, Drawn& drawn) {
  const Scene scene = random_boxes(boxes, seed, target);
  const RasterProjection view = RasterProjection::from_camera(scene.camera, 1e-3);
  DepthFaceBuffer tiles;
  expect_as_in_triangle_order(scene, view, tiles);
  if (::testing::Test::HasFatalFailure()) return;
  const DepthFaceBuffer every_face = in_triangle_order(scene, view);
  constexpr int kTile = ScanConverter::kTileSize;
  const int tiles_x = (view.width + kTile - 1) / kTile, tiles_y = (view.height + kTile - 1) / kTile;
  std::vector<char> shows(std::size_t(tiles_x * tiles_y), 0);
  std::size_t ground = 0, silhouette = 0;
  for (std::size_t i = 0; i < tiles.face.size(); ++i) {
    if (tiles.face[i] != every_face.face[i] || tiles.depth_key[i] != every_face.depth_key[i]) {
      ASSERT_TRUE(scene.outward_solids().far_side_from(scene, every_face.face[i], view.eye))
          << "pixel " << i;
      ++silhouette;
    }
    if (tiles.face[i] == kNoFace) continue;
    shows[i / view.width / kTile * tiles_x + i % view.width / kTile] = 1;
    ASSERT_NE(scene.object_of_face(tiles.face[i]), std::uint32_t(boxes + 1)) << "pixel " << i;
    ground += scene.object_of_face(tiles.face[i]) == std::uint32_t(boxes);
  }
  EXPECT_LT(silhouette, tiles.face.size() / 200);
  drawn = {ground, int(std::count(shows.begin(), shows.end(), 0))};
}

void expect_drawn_as_in_triangle_order(int boxes, unsigned seed) {
  Drawn drawn;
  expect_drawn_as_in_triangle_order(boxes, seed, {0, 2, 0}, drawn);
  EXPECT_GT(drawn.ground, 500u);  // the first of the coincident squares shows
}

TEST(ScanConverter, HiddenTrianglesDroppedWholeChangeNoPixel) {
  expect_drawn_as_in_triangle_order(300, 7);
}

// Every box twice: each pixel of a box ties between its copies, on spans of every length
// and column, and the first copy's face (the lower id) keeps it, as in triangle order.
TEST(ScanConverter, CoincidentCopiesKeepTheLowerFaceOnSpansOfEveryLength) {
  constexpr int kBoxes = 200;
  const Scene scene = random_boxes(kBoxes, 11, {0, 2, 0}, 2);
  const RasterProjection view = RasterProjection::from_camera(scene.camera, 1e-3);
  DepthFaceBuffer tiles;
  expect_as_in_triangle_order(scene, view, tiles);
  if (HasFatalFailure()) return;
  std::size_t first_copy = 0;
  for (std::size_t i = 0; i < tiles.face.size(); ++i) {
    if (tiles.face[i] == kNoFace) continue;
    const std::uint32_t object = scene.object_of_face(tiles.face[i]);
    if (object >= 2 * kBoxes) continue;  // the ground
    ASSERT_EQ(object % 2, 0u) << "pixel " << i;
    ++first_copy;
  }
  EXPECT_GT(first_copy, 2000u);
}

// rasterize_depth_tiles of \p scene's \p view against the full pass \p full: the tiles
// \p wanted marks (all when empty) and only those, each once with the full pass's keys;
// with \p storage, kept tiles drawn in storage of the test's own, asked once per tile.
void expect_depth_tiles_of_the_full_pass(const Scene& scene, const RasterProjection& view,
                                         const DepthFaceBuffer& full,
                                         const std::vector<std::uint8_t>& wanted, bool storage) {
  constexpr int kTile = ScanConverter::kTileSize;
  const int tiles_x = (view.width + kTile - 1) / kTile;
  const int tiles = tiles_x * ((view.height + kTile - 1) / kTile);
  const auto is_wanted = [&](std::size_t i) {
    const std::size_t t = i / view.width / kTile * tiles_x + i % view.width / kTile;
    return wanted.empty() || wanted[t];
  };
  std::vector<double> key(full.depth_key.size(), -INFINITY);
  std::vector<int> handed(full.depth_key.size(), 0);
  const auto tile_count = std::size_t(tiles);
  std::vector<std::vector<float>> kept(tile_count);
  std::vector<int> asked(tile_count, 0);
  std::size_t from_storage = 0;
  std::mutex mutex;
  ScanConverter::TileStorage keep_in;
  if (storage) {
    keep_in = [&](std::size_t t) {
      std::lock_guard lock(mutex);
      ++asked[t];
      kept[t].assign(std::size_t(kTile) * kTile, 0.0f);
      return kept[t].data();
    };
  }
  ScanConverter(scene).rasterize_depth_tiles(
      view, {},
      [&](const DepthTile& tile) {
        std::lock_guard lock(mutex);
        const std::size_t t = std::size_t(tile.y0 / kTile) * tiles_x + tile.x0 / kTile;
        from_storage += !kept[t].empty() && tile.depth_key == kept[t].data();
        for (int y = 0; y < tile.height; ++y) {
          for (int x = 0; x < tile.width; ++x) {
            const std::size_t i = std::size_t(tile.y0 + y) * view.width + tile.x0 + x;
            key[i] = tile.depth_key[y * tile.width + x];
            ++handed[i];
          }
        }
      },
      wanted, keep_in);
  std::size_t drawn = 0, left_out = 0;
  for (std::size_t i = 0; i < key.size(); ++i) {
    ASSERT_LE(handed[i], 1) << "pixel " << i;
    if (!is_wanted(i)) {
      ASSERT_EQ(handed[i], 0) << "pixel " << i;
      continue;
    }
    ASSERT_EQ(key[i], full.depth_key[i]) << "pixel " << i;  // both rounded to float
    drawn += full.face[i] != kNoFace;
    left_out += handed[i] == 0;
  }
  for (int t = 0; t < tiles; ++t) {
    ASSERT_LE(asked[std::size_t(t)], 1) << "tile " << t;
    if (asked[std::size_t(t)] == 1) {
      EXPECT_LT(t % tiles_x, tiles_x - 1);  // the last column of tiles is 11 pixels wide
    }
  }
  const std::size_t asked_tiles = std::size_t(std::count(asked.begin(), asked.end(), 1));
  EXPECT_EQ(from_storage, asked_tiles);
  const bool batches = scene.triangles().clusters.size() >= ScanConverter::kCulledClusters;
  if (storage && batches && wanted.empty()) {
    EXPECT_GT(asked_tiles, std::size_t(tiles / 2));
  }
  if (!batches) {
    EXPECT_EQ(asked_tiles, 0u);
  }
  if (wanted.empty()) {
    EXPECT_GT(drawn, key.size() / 10);
    if (scene.triangles().clusters.size() < 10) {
      EXPECT_GE(left_out, 64u * 64);  // a tile of sky at least
    }
  }
}

// A light's depth tiles hold the keys of the full pass, rounded to float, in the tiles that
// some triangle reaches, and only those, with one batch and with several; with a mask of
// wanted tiles (a checkerboard, one tile), only the wanted ones, with the same keys. Given
// storage for kept tiles, the pass asks for it once per full-width tile that several
// batches draw, and hands those tiles on from it.
TEST(ScanConverter, DepthTilesAreTheReachedTilesOfTheFullPass) {
  constexpr int kTile = ScanConverter::kTileSize;
  for (const int boxes : {3, 300, 4000}) {
    const Scene scene = random_boxes(boxes, 5);
    const RasterProjection view = RasterProjection::from_camera(scene.camera, 1e-3);
    const DepthFaceBuffer full = ScanConverter(scene).rasterize(view, {});
    const int tiles_x = (view.width + kTile - 1) / kTile;
    const int tiles = tiles_x * ((view.height + kTile - 1) / kTile);
    std::vector<std::uint8_t> checkerboard(std::size_t(tiles), 0), one(std::size_t(tiles), 0);
    for (int t = 0; t < tiles; ++t) checkerboard[t] = (t % tiles_x + t / tiles_x) % 2;
    one[std::size_t(tiles / 2)] = 1;
    for (const bool storage : {false, true}) {
      for (const std::vector<std::uint8_t>& wanted :
           {std::vector<std::uint8_t>{}, checkerboard, one}) {
        SCOPED_TRACE(std::to_string(boxes) + " boxes, " + std::to_string(wanted.size()) + " tiles" +
                     (storage ? ", kept in storage" : ""));
        expect_depth_tiles_of_the_full_pass(scene, view, full, wanted, storage);
        if (HasFatalFailure()) return;
      }
    }
  }
}

// Enough clusters in view for batches culled against the ones before them.
TEST(ScanConverter, HiddenClustersCulledInBatchesChangeNoPixel) {
  const int boxes = 4000;
  ASSERT_GT(boxes * 12 / TriangleClusters::kSize, ScanConverter::kCulledClusters * 5 / 4);
  expect_drawn_as_in_triangle_order(boxes, 11);
  // Looking up: the top tiles, which no batch reaches, are handed on as background.
  Drawn drawn;
  expect_drawn_as_in_triangle_order(boxes, 11, {0, 30, 0}, drawn);
  EXPECT_GE(drawn.empty_tiles, 2);
}

// The far side of a closed box is drawn where its near side cannot hide it: from inside the
// box, and where the near plane cuts the near side away.
TEST(ScanConverter, FarSideShowsFromInsideAndThroughTheNearPlane) {
  const RasterProjection inside_view = [] {
    const Camera c = testing::camera({0.2, 0.1, 0.3}, {1, 0, 0}, 40, 30, 60);
    return RasterProjection::from_camera(c, 1e-3);
  }();
  const Scene room = testing::make_scene(testing::camera({0.2, 0.1, 0.3}, {1, 0, 0}, 40, 30, 60),
                                         {}, {testing::box({-1, -1, -1}, {1, 1, 1})});
  ASSERT_EQ(room.outward_solids().size(), 1u);
  const DepthFaceBuffer walls = ScanConverter(room).rasterize(inside_view, {});
  EXPECT_EQ(std::count(walls.face.begin(), walls.face.end(), kNoFace), 0);

  // The eye 1e-4 outside the box's -x face, looking in: the near plane at 1e-3 cuts that face
  // away, and the +x face behind it fills the view.
  const Camera at_wall = testing::camera({-1.0001, 0, 0}, {1, 0, 0}, 40, 30, 60);
  const Scene box = testing::make_scene(at_wall, {}, {testing::box({-1, -1, -1}, {1, 1, 1})});
  const DepthFaceBuffer cut =
      ScanConverter(box).rasterize(RasterProjection::from_camera(at_wall, 1e-3), {});
  EXPECT_EQ(std::count(cut.face.begin(), cut.face.end(), kNoFace), 0);
  EXPECT_EQ(cut.face[15 * 40 + 20], 1u);  // +x
}

}  // namespace
}  // namespace shadowkit
