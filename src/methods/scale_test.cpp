// The exact methods stay exact at scale: the 30,000-cube field (360k triangles) and the
// Catmull-Clark torus knot of examples/knot-600k.json (584k), against the ray-traced
// reference. The bars are the conformance table's (conformance_test.cpp); its
// scenes are small, and at 360k triangles the methods take other paths (depth-fail for one
// sub-object among thousands, casters dropped by Crow's footprints, a deep scene BSP).
#include <gtest/gtest.h>

#include <filesystem>
#include <utility>

#include "shadowkit/raster/visible_surface.h"
#include "shadowkit/scene/generators.h"
#include "shadowkit/scene/scene_file.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"

namespace shadowkit {
namespace {

void expect_exact(const Scene& scene) {
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  for (const auto& [method, bar] : {std::pair{"volume", 0.05}, {"svbsp", 0.05}, {"angular", 0.2}}) {
    for (const MaskComparison& c : testing::compare_with_reference(scene, vsb, method, {})) {
      EXPECT_LE(c.interior_pct(), bar) << method;
      EXPECT_GT(c.interior_pixels, 50000u) << method;  // much of the view: no small sample
    }
  }
}

TEST(Scale, ThirtyThousandCubesStayExact) {
  expect_exact(testing::resized(load_scene("cubes:30000", {}), 640, 360));
}

TEST(Scale, TheKnotOfHalfAMillionTrianglesStaysExact) {
  const Scene scene = load_scene_file(
      std::filesystem::path(SHADOWKIT_SOURCE_DIR) / "examples" / "knot-600k.json", {});
  ASSERT_GT(scene.triangles().triangles.size(), 500000u);
  expect_exact(testing::resized(scene, 640, 360));
}

}  // namespace
}  // namespace shadowkit
