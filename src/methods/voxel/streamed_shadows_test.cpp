// §5.1 (voxel.framebuffer=0): the streamed masks against the frame buffer's and raytrace's,
// its memory, a resolution the frame buffer mode cannot afford, and its options.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>
#include <string>

#include "shadowkit/core/error.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"
#include "voxel_method.h"

namespace shadowkit::voxel {
namespace {

using testing::worst_interior_mismatch;

MethodOptions offset_options(const std::string& resolution, const std::string& framebuffer) {
  return MethodOptions(
      "voxel", {{"resolution", resolution}, {"test", "offset"}, {"framebuffer", framebuffer}});
}

// Percent of the covered pixels where the two modes' masks differ, worst light.
double modes_disagreement_pct(const Scene& scene, const std::string& resolution) {
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  double worst = 0;
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    VoxelMethod kept(offset_options(resolution, "1")), streamed(offset_options(resolution, "0"));
    const ShadowMask a = testing::method_mask(kept, scene, vsb, l);
    const ShadowMask b = testing::method_mask(streamed, scene, vsb, l);
    double covered = 0, differing = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
      covered += a.pixels[i] != kMaskBackground;
      differing += a.pixels[i] != b.pixels[i];
    }
    worst = std::max(worst, covered > 0 ? 100 * differing / covered : 0.0);
  }
  return worst;
}

class StreamedBuiltInScene : public ::testing::TestWithParam<const char*> {};

// The modes differ only where a voxel holds surfaces of different normals: the frame
// buffer decides the voxel once, from its sample facing the light most; the streamed mode
// moves each visible point along its own face's normal. That is at edges and contact
// lines, a thin band of pixels. (Each mode against raytrace: the conformance table.)
TEST_P(StreamedBuiltInScene, AgreesWithTheFrameBuffer) {
  const Scene scene = testing::resized(load_scene(GetParam(), {}), 240, 135);
  const double disagreement = modes_disagreement_pct(scene, "128");
  std::printf("%s: modes differ on %.3f%%\n", GetParam(), disagreement);
  EXPECT_LE(disagreement, 1.5);
}

INSTANTIATE_TEST_SUITE_P(Voxel, StreamedBuiltInScene,
                         ::testing::Values("square", "cubes:125", "tetra:3", "three-lights"),
                         [](const ::testing::TestParamInfo<const char*>& param_info) {
                           std::string name = param_info.param;
                           for (char& ch : name) {
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           }
                           return name;
                         });

std::size_t memory_after_build(const Scene& scene, const MethodOptions& options) {
  VoxelMethod method(options);
  method.prepare(scene, {});
  method.build(scene, 0, {});
  return method.memory_bytes();
}

TEST(StreamedShadows, KeepsOnlyTheProjectionPlane) {
  const Scene scene = testing::resized(load_scene("square", {}), 80, 45);
  const std::size_t kept = memory_after_build(scene, offset_options("256", "1"));
  const std::size_t streamed = memory_after_build(scene, offset_options("256", "0"));
  std::printf("M = 256: frame buffer %zu bytes, streamed %zu bytes\n", kept, streamed);
  EXPECT_LT(streamed * 4, kept);
}

// Three 0.5 x 0.5 squares spread over 20 units: at M = 2048 a voxel is 0.01, so the
// squares are small in voxels while the grid is far too big to store densely. The caster
// at height 0.3 shadows the floor square under a slanted directional light.
TEST(StreamedShadows, ResolutionTwoThousandFortyEight) {
  const Scene scene = testing::make_scene(testing::camera({0, 2, 1.5}, {0, 0, 0}, 160, 90),
                                          {testing::directional_light({1, -1, 0.3})},
                                          {testing::horizontal_quad(-0.5, 0.5, -0.5, 0.5, 0),
                                           testing::horizontal_quad(-0.2, 0.2, -0.2, 0.2, 0.3),
                                           testing::horizontal_quad(19.5, 20, -0.25, 0.25, 0)});
  const MethodOptions options(
      "voxel",
      {{"resolution", "2048"}, {"test", "offset"}, {"framebuffer", "0"}, {"bound", "scene"}});
  VoxelMethod method(options);
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  const ShadowMask mask = testing::method_mask(method, scene, vsb, 0);
  EXPECT_EQ(testing::counter(method, "resolution"), 2048);
  EXPECT_GT(std::count(mask.pixels.begin(), mask.pixels.end(), kMaskShadow), 200);
  const double mismatch = worst_interior_mismatch(scene, "voxel", options);
  std::printf("M = 2048: %zu bytes, mismatch %.3f%%\n", method.memory_bytes(), mismatch);
  EXPECT_LE(mismatch, 0.5);
}

TEST(StreamedShadows, TheTopologyTestIsAnInputError) {
  EXPECT_THROW(VoxelMethod(MethodOptions("voxel", {{"framebuffer", "0"}})), InputError);
  EXPECT_THROW(VoxelMethod(MethodOptions("voxel", {{"test", "offset"}, {"framebuffer", "2"}})),
               InputError);
  EXPECT_NO_THROW(VoxelMethod(offset_options("2048", "0")));
}

}  // namespace
}  // namespace shadowkit::voxel
