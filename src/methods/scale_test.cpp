// The exact methods stay exact at scale: the 30,000-cube field, 360k triangles, against the
// ray-traced reference. The bars are the conformance table's (conformance_test.cpp); its
// scenes are small, and at 360k triangles the methods take other paths (depth-fail for one
// sub-object among thousands, casters dropped by Crow's footprints, a deep scene BSP).
#include <gtest/gtest.h>

#include <utility>

#include "shadowkit/raster/visible_surface.h"
#include "shadowkit/scene/generators.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"

namespace shadowkit {
namespace {

TEST(Scale, ThirtyThousandCubesStayExact) {
  const Scene scene = testing::resized(load_scene("cubes:30000", {}), 640, 360);
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  for (const auto& [method, bar] : {std::pair{"volume", 0.05}, {"svbsp", 0.05}, {"angular", 0.2}}) {
    for (const MaskComparison& c : testing::compare_with_reference(scene, vsb, method, {})) {
      EXPECT_LE(c.interior_pct(), bar) << method;
      EXPECT_GT(c.interior_pixels, 100000u) << method;  // most of the view: no small sample
    }
  }
}

}  // namespace
}  // namespace shadowkit
