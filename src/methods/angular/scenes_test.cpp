#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "angular_method.h"
#include "shadowkit/core/error.h"
#include "shadowkit/scene/scene_file.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"

namespace shadowkit::angular {
namespace {

Scene reduced(Scene scene) {
  return testing::resized(std::move(scene), 480, 270);
}

// Worst interior mismatch (percent) of `angular` against `raytrace` over the lights.
double worst_interior_mismatch(const Scene& scene, const MethodOptions& options = {}) {
  return testing::worst_interior_mismatch(scene, "angular", options);
}

// An open half cylinder of thin strips, bulging toward the camera, lit from the side so
// that its terminator runs down the middle.
Scene open_half_cylinder() {
  PolygonSoup soup;
  constexpr int kStrips = 64;
  for (int i = 0; i <= kStrips; ++i) {
    const double a = std::numbers::pi * i / kStrips;
    soup.positions.push_back({std::cos(a), -1, std::sin(a)});
    soup.positions.push_back({std::cos(a), 1, std::sin(a)});
  }
  for (std::uint32_t i = 0; i < kStrips; ++i) {
    soup.add_face({2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1});
  }
  return testing::make_scene(testing::camera({0, 0.3, 4}, {0, 0, 0}, 320, 240),
                             {testing::point_light({-3, 2, 0.3})}, {soup});
}

// A convex surface never shadows itself: every other strip lies behind a strip's plane,
// where the ray to the light does not go. A pair cut at the entry's centre reaches half
// an entry past its strip onto the lit neighbour; it must not shadow it, however coarse R.
TEST(AngularScenes, AConvexOpenSurfaceDoesNotShadowItselfAtCoarseTheta) {
  const Scene scene = open_half_cylinder();
  for (const char* r : {"20", "99"}) {
    const MethodOptions options("angular", {{"resolution", r}});
    EXPECT_LE(worst_interior_mismatch(scene, options), 0.01) << r;
  }
}

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

// The light inside the room: the walls' pairs cover every phi, and on the walls theta
// changes along the scan lines every few pixels; a lit run goes on across its entry's block.
TEST(AngularScenes, ALitRunCrossesTheEntriesOfItsBlock) {
  const Scene scene = reduced(load_scene("room", {}));
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  AngularMethod angular({});
  testing::method_mask(angular, scene, vsb, 0);
  EXPECT_GT(testing::counter(angular, "theta_resolution"), 500);
  EXPECT_LT(testing::counter(angular, "lookup_calls") * 8, double(vsb.covered_count()));
  EXPECT_LE(worst_interior_mismatch(scene), 0.01);
}

// RE-loops paper, Sec. 3.2 as written (angular.pairing=paper) on its own objects: the coiled
// and the holed one pair without falling back to the walk; the hole-like one falls back in
// the band below its notch floor (re_loop_pairing_test.cpp). All shadow as the walk does.
TEST(AngularScenes, PaperPairingShadowsThePapersObjectsAsTheWalkDoes) {
  for (const char* spec : {"coil", "holed", "hole-like", "cubes:27"}) {
    const Scene scene = reduced(load_scene(spec, {}));
    const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
    AngularMethod walk({});
    AngularMethod paper(MethodOptions("angular", {{"pairing", "paper"}}));
    const ShadowMask a = testing::method_mask(walk, scene, vsb, 0);
    const ShadowMask b = testing::method_mask(paper, scene, vsb, 0);
    EXPECT_GT(testing::counter(paper, "paper_objects"), 0) << spec;
    EXPECT_GT(testing::counter(paper, "re_pairs"), 0) << spec;
    const double fallbacks = testing::counter(paper, "pairing_fallbacks");
    if (std::string(spec) == "hole-like") {
      EXPECT_GT(fallbacks, 0);
    } else {
      EXPECT_EQ(fallbacks, 0) << spec;
    }
    EXPECT_EQ(testing::counter(paper, "table_pairs"), testing::counter(walk, "table_pairs"))
        << spec;
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.size(); ++i) differ += a.pixels[i] != b.pixels[i];
    EXPECT_EQ(differ, 0u) << spec;
  }
}

TEST(AngularScenes, RejectsAResolutionThatIsNotAWholeNumber) {
  EXPECT_THROW(AngularMethod(MethodOptions("angular", {{"resolution", "2.5"}})), InputError);
  EXPECT_THROW(AngularMethod(MethodOptions("angular", {{"bias", "1"}})), InputError);
  EXPECT_THROW(AngularMethod(MethodOptions("angular", {{"saturated", "2"}})), InputError);
  EXPECT_THROW(AngularMethod(MethodOptions("angular", {{"resolution", "-1"}})), InputError);
  EXPECT_THROW(AngularMethod(MethodOptions("angular", {{"pairing", "peaks"}})), InputError);
}

}  // namespace
}  // namespace shadowkit::angular
