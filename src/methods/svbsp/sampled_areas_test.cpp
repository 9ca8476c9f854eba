// Per-polygon shadowed areas against an independent estimate: stratified points on a
// polygon, each tested with an Embree shadow ray (testing/sampled_shadow.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "multi_light.h"
#include "shadowkit/methods/raytrace.h"
#include "shadowkit/scene/scene_file.h"
#include "svbsp_test_support.h"
#include "testing/sampled_shadow.h"

namespace shadowkit::svbsp {
namespace {

// The faces a light shadows partly, most evenly split first: where an error would show.
std::vector<std::uint32_t> partly_shadowed(const std::map<std::uint32_t, FaceAreas>& a,
                                           std::size_t count) {
  std::vector<std::pair<double, std::uint32_t>> split;
  for (const auto& [face, areas] : a) {
    const double share = std::min(areas.lit, areas.shadowed) / (areas.lit + areas.shadowed);
    if (share > 1e-3) split.push_back({share, face});
  }
  std::sort(split.rbegin(), split.rend());
  std::vector<std::uint32_t> faces;
  for (std::size_t i = 0; i < std::min(count, split.size()); ++i) faces.push_back(split[i].second);
  return faces;
}

class SampledAreas : public ::testing::TestWithParam<const char*> {};

TEST_P(SampledAreas, ShadowedAreasAgreeWithin0_5PercentOfThePolygon) {
  const Scene scene = load_scene(GetParam(), {});
  const raytrace::ShadowRays rays(scene);
  const MultiLightFragments multi = generate_multi_light_shadows(SceneBsp::build(scene), scene);
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const auto areas = face_areas(multi.fragments, l);
    const std::vector<std::uint32_t> faces = partly_shadowed(areas, 4);
    ASSERT_FALSE(faces.empty()) << "light " << l;
    for (const std::uint32_t face : faces) {
      const double total = face_area(scene, face);
      const double sampled = testing::sampled_shadowed_fraction(scene, rays, face, scene.lights[l]);
      EXPECT_NEAR(areas.at(face).shadowed / total, sampled, 0.005)
          << GetParam() << " light " << l << " face " << face;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Svbsp, SampledAreas, ::testing::Values("square", "table", "three-lights"));

}  // namespace
}  // namespace shadowkit::svbsp
