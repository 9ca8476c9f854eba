// §5: the 1/2^n shading rule, the zigzag triangulation, the crack-free tessellation and the
// render with (§5.2) and without (§5.1) the cubic frame buffer.
#include "subpatch_render.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>

#include "crack_free_tessellation.h"
#include "frame_bound.h"
#include "shadowkit/core/error.h"
#include "shadowkit/core/palette.h"
#include "testing/test_scenes.h"

namespace shadowkit::voxel {
namespace {

TEST(CornerShading, HalvesTheDiffusePerShadowedCorner) {
  EXPECT_EQ(corner_shading(0).diffuse, 1.0);
  EXPECT_TRUE(corner_shading(0).highlight);
  EXPECT_EQ(corner_shading(1).diffuse, 0.5);
  EXPECT_EQ(corner_shading(2).diffuse, 0.25);
  EXPECT_EQ(corner_shading(3).diffuse, 0.125);
  for (int n = 1; n <= 3; ++n) EXPECT_FALSE(corner_shading(n).highlight) << n;
  EXPECT_EQ(corner_shading(4).diffuse, 0.0);  // ambient only
  EXPECT_FALSE(corner_shading(4).highlight);
}

// A polygon of a + b - 2 vertices: a + b - 4 triangles, never the duplicated corners of b.
TEST(Zigzag, TriangulatesThePolygonBetweenTwoChains) {
  for (std::size_t a = 3; a < 9; ++a) {
    for (std::size_t b = 3; b < 9; ++b) {
      const auto triangles = zigzag(a, b);
      EXPECT_EQ(triangles.size(), a + b - 4);
      std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
      for (const auto& t : triangles) {
        for (int k = 0; k < 3; ++k) {
          EXPECT_NE(t[k], a);          // b[0], the same point as a[0]
          EXPECT_NE(t[k], a + b - 1);  // b[last], the same point as a[last]
          ++directed[{t[k], t[(k + 1) % 3]}];
        }
      }
      // Consistently oriented: no directed edge twice.
      for (const auto& [edge, count] : directed) EXPECT_EQ(count, 1);
    }
  }
}

// Every edge of the tessellation of a closed surface is shared by exactly two triangles,
// walked once each way: no crack between subpatches of different levels or patches. Edges
// are compared by their end points' exact bits (shared points are evaluated once,
// PatchSet::point), and every triangle the tessellation keeps counts: a T-junction, or a
// triangle without area left out beside one that has its edge, is an open edge.
void expect_watertight(const Scene& scene, int resolution) {
  const PatchSet patches(scene);
  const VoxelGrid grid = make_grid(scene.bounds(), resolution);
  const SubpatchTessellation t = tessellate_subpatches(patches, grid, 26);
  ASSERT_EQ(t.leaf.size(), t.triangles.face_count());
  const auto key = [](Vec3 p) { return std::tuple{p.x, p.y, p.z}; };
  std::map<std::pair<std::tuple<double, double, double>, std::tuple<double, double, double>>, int>
      directed;
  for (std::size_t f = 0; f < t.triangles.face_count(); ++f) {
    const std::uint32_t* v = &t.triangles.indices[t.triangles.face_start[f]];
    for (int k = 0; k < 3; ++k) {
      ++directed[{key(t.triangles.positions[v[k]]), key(t.triangles.positions[v[(k + 1) % 3]])}];
    }
  }
  int open = 0;
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    open += count != 1 || reverse == directed.end() || reverse->second != 1;
  }
  EXPECT_EQ(open, 0) << "of " << directed.size() << " directed edges";
}

Scene polygon_scene(const std::vector<PolygonSoup>& soups) {
  return testing::make_scene(testing::camera({0, 0, 10}, {0, 0, 0}, 64, 48),
                             {testing::point_light({0, 10, 0})}, soups);
}

// A polygon triangle is the patch (a, b, c, c): the leaves at c are fanned, not zigzagged
// (crack_free_tessellation.cpp), or their side toward c misses its neighbour's points.
TEST(CrackFreeTessellation, ClosedPolygonMeshStaysClosed) {
  expect_watertight(polygon_scene({testing::box({-2.1, -1.3, -1.7}, {1.9, 2.2, 1.6})}), 32);
}

// The same box at tiny and huge coordinates: the grid is in voxels, the check in bits.
TEST(CrackFreeTessellation, TinyAndHugeBoxesStayClosed) {
  for (const double scale : {1e-6, 1e6}) {
    const Vec3 lo = Vec3{-2.1, -1.3, -1.7} * scale + Vec3{3, 0, 0} * scale;
    expect_watertight(polygon_scene({testing::box(lo, lo + Vec3{4.0, 3.5, 3.3} * scale)}), 16);
  }
}

// A pyramid over a skew (non-planar) quad: the quad is two triangles sharing a diagonal,
// which the two see from opposite corners (side 3 of one, side 0 of the other).
TEST(CrackFreeTessellation, SkewQuadDiagonalStaysClosed) {
  PolygonSoup pyramid;
  pyramid.positions = {{-2, 0, -2}, {2, 0.7, -2}, {2, 0, 2}, {-2, 0.9, 2}, {0.3, 3, 0.2}};
  pyramid.add_face({0, 1, 2, 3});
  for (std::uint32_t k = 0; k < 4; ++k) pyramid.add_face({(k + 1) % 4, k, 4});
  expect_watertight(polygon_scene({pyramid}), 32);
}

TEST(CrackFreeTessellation, CatmullClarkSurfaceStaysClosed) {
  Scene scene = testing::make_scene(testing::camera({0, 0, 10}, {0, 0, 0}, 64, 48),
                                    {testing::point_light({0, 10, 0})}, {});
  auto surface =
      SubdivisionSurface::build(testing::box({-2.3, -1.9, -2.1}, {2.2, 2.4, 1.8}), "cube");
  scene.objects.push_back({"cube", Mesh::build(surface->tessellate(4), "cube", {}), 0, surface});
  scene.finalize();
  expect_watertight(scene, 32);
}

struct Render {
  SubpatchImage image;
  std::size_t method_bytes;
};

MethodOptions offset_options(const std::string& resolution, const std::string& framebuffer) {
  return MethodOptions("voxel", {{"resolution", resolution},
                                 {"test", "offset"},
                                 {"bound", "scene"},
                                 {"framebuffer", framebuffer}});
}

Render render(const Scene& scene, const std::string& resolution, const std::string& framebuffer) {
  VoxelMethod method(offset_options(resolution, framebuffer));
  SubpatchImage image = make_subpatch_image(scene, method, {});
  return {std::move(image), method.memory_bytes()};
}

// Of all subpatch corners, the share whose shadow state the two modes decide differently,
// and the shadowed corners of the frame buffer mode.
struct CornerAgreement {
  double differing_pct = 0;
  std::size_t shadowed = 0;
};

CornerAgreement compare_modes(const Render& kept, const Render& streamed, std::size_t light) {
  const auto& a = kept.image.shadowed_corners(light);
  const auto& b = streamed.image.shadowed_corners(light);
  EXPECT_EQ(a.size(), b.size());  // the same recursion, the same subpatches in order
  CornerAgreement out;
  double differing = 0;
  for (std::size_t l = 0; l < std::min(a.size(), b.size()); ++l) {
    differing += std::abs(int(a[l]) - int(b[l]));
    out.shadowed += a[l];
  }
  out.differing_pct = 100 * differing / double(4 * std::max<std::size_t>(a.size(), 1));
  return out;
}

// A box on a ground lit from above at a slant. The modes decide a corner from different
// normals: the frame buffer decides a voxel once, for the subpatch corner in it that faces
// the light most; the streamed render moves each corner's voxel along its own subpatch's
// normal. They differ only in voxels where faces of different normals meet (the box's edges
// and its contact with the ground).
TEST(StreamedRender, AgreesWithTheFrameBufferRender) {
  const Scene scene = testing::make_scene(
      testing::camera({0, 3, 6}, {0, 0, 0}, 64, 48),
      {testing::point_light({2, 6, 1}), testing::directional_light({-0.4, -1, -0.2})},
      {testing::horizontal_quad(-3, 3, -3, 3, 0), testing::box({-0.7, 0, -0.6}, {0.8, 1.1, 0.5})});
  const Render kept = render(scene, "64", "1"), streamed = render(scene, "64", "0");
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const CornerAgreement agreement = compare_modes(kept, streamed, l);
    std::printf("light %zu: %zu shadowed corners, modes differ on %.3f%% of the corners\n", l,
                agreement.shadowed, agreement.differing_pct);
    EXPECT_GT(agreement.shadowed, 1000u);
    EXPECT_LE(agreement.differing_pct, 1.0);
  }
}

// Two 0.5 x 0.5 walls facing each other 0.1 apart, lit from above at a slant, and a small
// square 20 along the light beyond them: at M = 2048 a voxel is 0.01, the walls are 50
// voxels wide, and they project onto a thin band of the plane. Without the frame buffer
// the method keeps only that band, not the subpatches, the voxels' samples and the frame
// buffer (the tessellation drawn is the same in both modes).
TEST(StreamedRender, ResolutionTwoThousandFortyEightInLittleMemory) {
  const auto wall = [](double z) {
    return testing::polygon({{-0.25, 0, z}, {0.25, 0, z}, {0.25, 0.5, z}, {-0.25, 0.5, z}});
  };
  const Vec3 down_beam = normalize(Vec3{0, -1, 0.3});
  const Vec3 far = Vec3{0, 0.25, 0.05} + down_beam * 20;
  const Scene scene = testing::make_scene(
      testing::camera({0.4, 0.8, -1.2}, {0, 0.25, 0.05}, 64, 36),
      {testing::directional_light(down_beam)},
      {wall(0), wall(0.1),
       testing::horizontal_quad(-0.05, 0.05, far.z - 0.05, far.z + 0.05, far.y)});
  Render kept = render(scene, "2048", "1"), streamed = render(scene, "2048", "0");
  const CornerAgreement agreement = compare_modes(kept, streamed, 0);
  std::printf(
      "M = 2048: frame buffer %zu bytes, streamed %zu bytes; %zu shadowed corners, "
      "modes differ on %.3f%%\n",
      kept.method_bytes, streamed.method_bytes, agreement.shadowed, agreement.differing_pct);
  EXPECT_GT(agreement.shadowed, 5000u);
  EXPECT_LE(agreement.differing_pct, 0.1);  // flat squares: one normal per voxel
  EXPECT_LT(streamed.method_bytes * 20, kept.method_bytes);
  EXPECT_EQ(streamed.image.render(scene.camera).width, 64);
}

// Polygon boxes (12 patches each) and a Catmull-Clark box on a ground, in front of and
// behind each other from the camera.
Scene boxes_scene() {
  std::vector<PolygonSoup> soups{testing::horizontal_quad(-4, 4, -4, 4, 0)};
  for (int k = 0; k < 4; ++k) {
    const Vec3 lo{-2.5 + 1.3 * k, 0, -1.5 + 0.9 * k};
    soups.push_back(testing::box(lo, lo + Vec3{0.9, 0.6 + 0.3 * k, 0.8}));
  }
  Scene scene = testing::make_scene(
      testing::camera({1, 4, 7}, {0, 0.5, 0}, 160, 120),
      {testing::point_light({2, 6, 1}), testing::directional_light({-0.4, -1, -0.2})}, soups);
  auto surface = SubdivisionSurface::build(testing::box({-1, 0, 1}, {0.4, 1.2, 2.2}), "cube");
  scene.objects.push_back({"cube", Mesh::build(surface->tessellate(3), "cube", {}), 0, surface});
  scene.finalize();
  return scene;
}

// §5.1's still render draws the tessellation batch by batch and composites by depth: the
// picture of drawing it at once (the same triangles, the earlier batch winning a tie as the
// lower triangle index does in one pass), but where two batches' surfaces tie only in the
// float depth of the visible-surface buffer, which one pass breaks in double.
TEST(StillRender, BatchesGiveTheImageOfOnePass) {
  const Scene scene = boxes_scene();
  Render whole = render(scene, "64", "0");
  const Image<Rgb8> one_pass = whole.image.render(scene.camera);
  for (const std::size_t batch_triangles : {std::size_t(100), std::size_t(3000)}) {
    VoxelMethod method(offset_options("64", "0"));
    const StillImage still = render_still(scene, method, {}, batch_triangles);
    EXPECT_EQ(still.triangles, whole.image.triangle_count());
    EXPECT_GT(still.batches, 2u) << batch_triangles;
    ASSERT_EQ(still.image.pixels.size(), one_pass.pixels.size());
    std::size_t differing = 0, background = 0;
    for (std::size_t i = 0; i < one_pass.pixels.size(); ++i) {
      differing += !(one_pass.pixels[i] == still.image.pixels[i]);
      background += one_pass.pixels[i] == kBackground;
    }
    std::printf("%zu batches: %zu of %zu pixels differ from one pass\n", still.batches, differing,
                one_pass.pixels.size());
    EXPECT_LE(differing, 3u);
    EXPECT_LT(background, one_pass.pixels.size() / 2);  // the scene fills the picture
    EXPECT_GT(background, 0u);
  }
}

// Pixels where \p reference shows geometry and \p image shows background.
std::size_t lost_pixels(const Image<Rgb8>& image, const Image<Rgb8>& reference) {
  std::size_t lost = 0;
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    lost += !(reference.pixels[i] == kBackground) && image.pixels[i] == kBackground;
  }
  return lost;
}

std::size_t covered_pixels(const Image<Rgb8>& image) {
  return std::size_t(std::count_if(image.pixels.begin(), image.pixels.end(),
                                   [](Rgb8 p) { return !(p == kBackground); }));
}

// §5.2: a new view needs no new shadow work. A camera near a wide ground sees a wedge of it;
// turned a quarter around its target it sees another wedge, outside the bound of the first
// view. A frame buffer made for both views draws the turned view with every pixel a frame
// buffer made for the turned view alone draws; one made for the first view alone refuses the
// turned view rather than drop the wedge.
TEST(FrameBufferImage, ATurnedViewLosesNoGeometry) {
  const Scene scene = testing::make_scene(testing::camera({0, 2, 5}, {0, 0, 0}, 96, 64),
                                          {testing::point_light({2, 6, 1})},
                                          {testing::horizontal_quad(-20, 20, -20, 20, 0),
                                           testing::box({-0.5, 0, -0.5}, {0.5, 1, 0.5})});
  Camera turned = scene.camera;
  turned.position = {5, 2, 0};
  Scene turned_scene = scene;
  turned_scene.camera = turned;
  const MethodOptions settings("voxel", {{"resolution", "64"}});
  const Context ctx;
  const Image<Rgb8> fresh = FrameBufferImage(turned_scene, settings, ctx).render(turned);
  FrameBufferImage both(scene, settings, ctx, {turned});
  const Image<Rgb8> kept = both.render(turned);
  EXPECT_GT(covered_pixels(fresh), fresh.pixels.size() / 2);
  EXPECT_EQ(lost_pixels(kept, fresh), 0u);
  EXPECT_EQ(lost_pixels(fresh, kept), 0u);

  FrameBufferImage first_only(scene, settings, ctx);
  EXPECT_GT(covered_pixels(first_only.render(scene.camera)), 0u);
  EXPECT_THROW(first_only.render(turned), InputError);
  // A view that sees nothing needs nothing; the scene's box serves every view.
  EXPECT_EQ(covered_pixels(first_only.render(testing::camera({0, 2, 25}, {0, 2, 40}, 32, 24))), 0u);
  const MethodOptions whole("voxel", {{"resolution", "64"}, {"bound", "scene"}});
  EXPECT_EQ(lost_pixels(FrameBufferImage(scene, whole, ctx).render(turned), fresh), 0u);
}

// A scene the camera does not see: every batch draws nothing, the picture is background.
TEST(StillRender, SceneBehindTheCameraLeavesTheBackground) {
  Scene scene = boxes_scene();
  scene.camera = testing::camera({0, 1, 20}, {0, 1, 40}, 32, 24);
  VoxelMethod method(offset_options("32", "0"));
  const StillImage still = render_still(scene, method, {}, 200);
  EXPECT_GT(still.batches, 2u);
  const auto drawn = std::count_if(still.image.pixels.begin(), still.image.pixels.end(),
                                   [](Rgb8 p) { return !(p == kBackground); });
  EXPECT_EQ(drawn, 0);
}

}  // namespace
}  // namespace shadowkit::voxel
