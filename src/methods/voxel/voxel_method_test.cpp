// The voxel method: the paper's Fig. 1 case, degenerate input, coincident copies, the bound
// on subpatches and bad options. Its masks against raytrace are rows of the conformance table.
#include "voxel_method.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "shadowkit/core/error.h"
#include "shadowkit/scene/scene_file.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"

namespace shadowkit::voxel {
namespace {

MethodOptions voxel_options(std::map<std::string, std::string> values) {
  return MethodOptions("voxel", std::move(values));
}

// Fraction of the covered pixels of \p object that \p method lights.
double lit_fraction(ShadowMethod& method, const Scene& scene, std::uint32_t object) {
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  const ShadowMask mask = testing::method_mask(method, scene, vsb, 0);
  double lit = 0, covered = 0;
  for (std::size_t i = 0; i < mask.pixels.size(); ++i) {
    if (vsb.object(i) != object) continue;
    covered += 1;
    lit += mask.pixels[i] == kMaskLit;
  }
  return covered > 0 ? lit / covered : -1;
}

// Fig. 1: a plane lit at a grazing angle (3 degrees). Every point of it is lit; a depth
// image without bias puts most of it in shadow, the voxel tests do not.
TEST(VoxelFigure1, APlaneLitAtAGrazingAngleStaysLit) {
  const Scene scene = testing::make_scene(testing::camera({0, 6, 12}, {0, 0, 0}, 160, 90),
                                          {testing::directional_light({1, -0.0524, 0.2})},
                                          {testing::horizontal_quad(-10, 10, -10, 10, 0)});
  for (const char* test : {"topology", "offset"}) {
    VoxelMethod voxel(voxel_options({{"resolution", "128"}, {"test", test}}));
    EXPECT_GE(lit_fraction(voxel, scene, 0), 0.999) << test;
  }
  const auto shadow_map = make_method(
      "shadowmap",
      MethodOptions("shadowmap", {{"resolution", "256"}, {"bias", "0"}, {"slope_bias", "0"}}));
  EXPECT_LT(lit_fraction(*shadow_map, scene, 0), 0.9);
}

// A point light in the ground's plane: the ground is shadowed (contract condition 1), the
// square above it lit on top.
TEST(VoxelDegenerate, LightInAFacesPlane) {
  const Scene scene = testing::square_over_plane(testing::camera({0, 6, 8}, {0, 0, 0}, 160, 90),
                                                 testing::point_light({3, 0, 0}));
  VoxelMethod voxel(voxel_options({{"resolution", "64"}}));
  EXPECT_EQ(lit_fraction(voxel, scene, 0), 0.0);
}

// Ten copies of a box on one spot: a triangle with the corners of an earlier one is one
// surface, voxelized once, so the copies cost what one box costs and shadow as it does.
TEST(VoxelCoincidentObjects, CopiesCostWhatOneCosts) {
  const auto boxes = [](int copies) {
    std::vector<PolygonSoup> soups{testing::horizontal_quad(-3, 3, -3, 3, 0)};
    for (int i = 0; i < copies; ++i) soups.push_back(testing::box({-0.5, 0, -0.5}, {0.5, 1, 0.5}));
    return testing::make_scene(
        testing::camera({1, 4, 5}, {0, 0, 0}, 160, 90),
        {testing::point_light({1, 3, 1}), testing::directional_light({1, -2, 1})}, soups);
  };
  const Scene one = boxes(1), ten = boxes(10);
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(one, {});
  for (std::size_t light = 0; light < one.lights.size(); ++light) {
    VoxelMethod a(voxel_options({{"resolution", "64"}})), b(voxel_options({{"resolution", "64"}}));
    const ShadowMask mask_one = testing::method_mask(a, one, vsb, light);
    const ShadowMask mask_ten = testing::method_mask(b, ten, vsb, light);
    EXPECT_EQ(mask_one.pixels, mask_ten.pixels) << light;
    EXPECT_EQ(testing::counter(a, "subpatches"), 13'505) << light;
    EXPECT_EQ(testing::counter(b, "subpatches"), 13'505) << light;
    EXPECT_EQ(testing::counter(b, "voxels"), 4'509) << light;
    EXPECT_EQ(testing::counter(b, "blocker_records"), testing::counter(a, "blocker_records"));
    EXPECT_EQ(b.memory_bytes(), a.memory_bytes()) << light;
  }
}

// Pixels where \p mask says \p wrong and \p reference does not, inside a 3x3 neighbourhood
// that is uniform in the reference and everywhere else right: isolated specks, not the
// stair steps of a shadow edge.
int specks(const ShadowMask& reference, const ShadowMask& mask, std::uint8_t wrong) {
  int count = 0;
  for (int y = 1; y + 1 < reference.height; ++y) {
    for (int x = 1; x + 1 < reference.width; ++x) {
      const std::size_t i = std::size_t(y) * reference.width + x;
      if (mask.pixels[i] != wrong || reference.pixels[i] == wrong) continue;
      bool isolated = true;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const std::size_t j = i + std::size_t(dy * reference.width + dx);
          isolated = isolated && reference.pixels[j] == reference.pixels[i] &&
                     (j == i || mask.pixels[j] == reference.pixels[j]);
        }
      }
      count += isolated;
    }
  }
  return count;
}

// Shadowed voxels of \p method's frame buffer none of whose 26 neighbours is shadowed: a
// dark speck on a lit surface in voxel-render's image.
int isolated_shadowed_voxels(const VoxelMethod& method) {
  const CubicFrameBuffer& buffer = method.frame_buffer();
  const VoxelKeys keys(method.grid().dims);
  std::set<std::uint64_t> seen;
  int count = 0;
  for (const Subpatch& leaf : method.subpatches()) {
    for (const GridPoint& corner : leaf.corner) {
      const VoxelIndex v = voxel_floor(corner.vec());
      if (buffer.state(v) != VoxelState::shadowed || !seen.insert(keys.key(v)).second) continue;
      int shadowed_around = 0;
      for (int dz = -1; dz <= 1; ++dz) {
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            shadowed_around +=
                buffer.state({v[0] + dx, v[1] + dy, v[2] + dz}) == VoxelState::shadowed;
          }
        }
      }
      count += shadowed_around == 1;
    }
  }
  return count;
}

// §4.2 on the paper's Fig. 5 objects (examples/subdivision.json). A sample on the curved
// surface lies below the flat side of a coarser neighbouring subpatch where the surface is
// concave (the torus's inner side): tested from the surface, as the paper writes it, its ray
// hits that chord a few thousandths of a voxel away, and the voxel is shadowed alone among
// lit ones (16 at M = 256). The few dark specks left at M = 512 lie on
// terminators, where the limit surface the voxels sample and the tessellation raytrace sees
// turn from the light at slightly different places.
TEST(VoxelSpecks, TopologyTestLeavesNoneOnTheFigure5Objects) {
  const Scene scene = load_scene_file(
      std::filesystem::path(SHADOWKIT_SOURCE_DIR) / "examples" / "subdivision.json", {});
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  const auto raytrace = make_method("raytrace", {});
  const ShadowMask reference = testing::method_mask(*raytrace, scene, vsb, 0);
  for (const auto& [resolution, most_dark_specks] : {std::pair{"256", 0}, std::pair{"512", 3}}) {
    VoxelMethod voxel(voxel_options({{"resolution", resolution}}));
    const ShadowMask mask = testing::method_mask(voxel, scene, vsb, 0);
    EXPECT_EQ(isolated_shadowed_voxels(voxel), 0) << resolution;
    EXPECT_LE(specks(reference, mask, kMaskShadow), most_dark_specks) << resolution;
    EXPECT_LE(specks(reference, mask, kMaskLit), 3) << resolution;
  }
  // As the paper writes it (voxel.paper=1: every hit from the sample on), they are back.
  VoxelMethod paper(voxel_options({{"resolution", "256"}, {"paper", "1"}}));
  testing::method_mask(paper, scene, vsb, 0);
  EXPECT_GT(isolated_shadowed_voxels(paper), 10);
}

// One subpatch more than voxel.max_subpatches allows is refused in prepare(), with the
// scene, the resolution and the bound named, and nothing kept; exactly as many are not.
TEST(VoxelSubpatchBound, RefusesOneSubpatchTooMany) {
  const Scene scene = testing::square_over_plane(testing::camera({0, 6, 8}, {0, 0, 0}, 160, 90),
                                                 testing::point_light({0, 4, 0}));
  for (const char* framebuffer : {"1", "0"}) {
    const auto options = [&](const std::string& bound) {
      return voxel_options({{"resolution", "64"},
                            {"test", "offset"},
                            {"framebuffer", framebuffer},
                            {"max_subpatches", bound}});
    };
    VoxelMethod exact(options("9314"));
    EXPECT_NO_THROW(exact.prepare(scene, {})) << framebuffer;
    VoxelMethod over(options("9313"));
    EXPECT_THAT([&] { over.prepare(scene, {}); },
                ::testing::ThrowsMessage<InputError>(::testing::StrEq(
                    "scene 'test': the voxel method at voxel.resolution=64 makes more than "
                    "9313 subpatches (voxel.max_subpatches); lower voxel.resolution or raise "
                    "voxel.max_subpatches")))
        << framebuffer;
    EXPECT_TRUE(over.subpatches().empty()) << framebuffer;
    EXPECT_EQ(over.frame_buffer().memory_bytes(), 0u) << framebuffer;
  }
  VoxelMethod counted(voxel_options({{"resolution", "64"}}));
  counted.prepare(scene, {});
  counted.build(scene, 0, {});
  EXPECT_EQ(testing::counter(counted, "subpatches"), 9'314);
}

TEST(VoxelOptions, BadValuesAreInputErrors) {
  EXPECT_THROW(VoxelMethod(voxel_options({{"resolution", "300"}})), InputError);
  EXPECT_THROW(VoxelMethod(voxel_options({{"resolution", "8"}})), InputError);
  EXPECT_THROW(VoxelMethod(voxel_options({{"resolution", "4096"}})), InputError);
  EXPECT_THROW(VoxelMethod(voxel_options({{"adjacency", "8"}})), InputError);
  EXPECT_THROW(VoxelMethod(voxel_options({{"test", "ray"}})), InputError);
  EXPECT_THROW(VoxelMethod(voxel_options({{"bound", "all"}})), InputError);
  EXPECT_THROW(VoxelMethod(voxel_options({{"bias", "1"}})), InputError);
  EXPECT_THROW(VoxelMethod(voxel_options({{"max_subpatches", "0"}})), InputError);
  EXPECT_THROW(VoxelMethod(voxel_options({{"paper", "2"}})), InputError);
  EXPECT_THROW(VoxelMethod(voxel_options({{"max_subpatches", "2.5"}})), InputError);
  EXPECT_THROW(VoxelMethod(voxel_options({{"max_subpatches", "268435457"}})), InputError);
  EXPECT_NO_THROW(VoxelMethod(voxel_options({{"resolution", "512"},
                                             {"adjacency", "6"},
                                             {"test", "offset"},
                                             {"bound", "scene"},
                                             {"paper", "1"}})));
}

}  // namespace
}  // namespace shadowkit::voxel
