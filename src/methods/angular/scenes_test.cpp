#include <gtest/gtest.h>

#include <filesystem>

#include "../../testing/method_testing.h"
#include "../../testing/test_scenes.h"
#include "angular_method.h"
#include "shadowkit/core/error.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit {
namespace {

Scene reduced(Scene scene) {
  return testing::resized(std::move(scene), 480, 270);
}

// Worst interior mismatch (percent) of `angular` against `raytrace` over the lights.
double worst_interior_mismatch(const Scene& scene, const MethodOptions& options = {}) {
  return testing::worst_interior_mismatch(scene, "angular", options);
}

class AngularBuiltInScene : public ::testing::TestWithParam<const char*> {};

TEST_P(AngularBuiltInScene, AgreesWithTheReference) {
  EXPECT_LE(worst_interior_mismatch(reduced(load_scene(GetParam(), {}))), 0.2);
}

INSTANTIATE_TEST_SUITE_P(Angular, AngularBuiltInScene,
                         ::testing::Values("cubes:125", "tetra:3", "table", "three-lights",
                                           "square", "room", "coil", "holed", "hole-like"));

// Sec. 3 / Figs. 6-7: R trades quality for speed; the error falls as R grows.
TEST(AngularScenes, MismatchFallsAsTheThetaResolutionGrows) {
  const Scene scene = reduced(load_scene("table", {}));
  double previous = 100;
  for (const char* r : {"99", "299", "599"}) {
    const MethodOptions options("angular", {{"resolution", r}});
    const double mismatch = worst_interior_mismatch(scene, options);
    EXPECT_LT(mismatch, previous) << r;
    previous = mismatch;
  }
  EXPECT_GT(worst_interior_mismatch(scene, {"angular", {{"resolution", "99"}}}), 0.05);
}

// Sec. 10: dropping covered pairs shrinks the table and leaves the mask alone.
TEST(AngularScenes, TheSaturatedTableGivesTheSameMask) {
  const Scene scene = reduced(load_scene("tetra:3", {}));
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  AngularMethod saturated({});
  AngularMethod full(MethodOptions("angular", {{"saturated", "0"}}));
  const ShadowMask a = testing::method_mask(saturated, scene, vsb, 0);
  const ShadowMask b = testing::method_mask(full, scene, vsb, 0);
  EXPECT_GT(testing::counter(saturated, "saturated_pairs"), 0);
  EXPECT_LT(testing::counter(saturated, "table_pairs"), testing::counter(full, "table_pairs"));
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) differ += a.pixels[i] != b.pixels[i];
  EXPECT_EQ(differ, 0u);
}

// Sec. 7: one lookup serves a run of pixels.
TEST(AngularScenes, OneLookupServesManyPixels) {
  const Scene scene = reduced(load_scene("cubes:125", {}));
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  AngularMethod angular({});
  testing::method_mask(angular, scene, vsb, 0);
  const double lookups = testing::counter(angular, "lookup_calls");
  EXPECT_GT(lookups, 0);
  EXPECT_LT(lookups * 4, double(vsb.covered_count()));
}

TEST(AngularScenes, RejectsAResolutionThatIsNotAWholeNumber) {
  EXPECT_THROW(AngularMethod(MethodOptions("angular", {{"resolution", "2.5"}})), InputError);
  EXPECT_THROW(AngularMethod(MethodOptions("angular", {{"bias", "1"}})), InputError);
  EXPECT_THROW(AngularMethod(MethodOptions("angular", {{"saturated", "2"}})), InputError);
  EXPECT_THROW(AngularMethod(MethodOptions("angular", {{"resolution", "-1"}})), InputError);
}

TEST(AngularScenes, EveryExampleAgreesWithTheReference) {
  const std::filesystem::path dir = std::filesystem::path(SHADOWKIT_SOURCE_DIR) / "examples";
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    const Scene scene = reduced(load_scene_file(entry.path(), {}));
    EXPECT_LE(worst_interior_mismatch(scene), 0.2) << entry.path().filename();
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

}  // namespace
}  // namespace shadowkit
