#include <gtest/gtest.h>

#include <algorithm>

#include "shadowkit/scene/scene_file.h"
#include "svbsp_method.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"

namespace shadowkit::svbsp {
namespace {

// §6's shadowed-fragments-only mode draws the shadowed fragments over the lit faces: the
// same mask from fewer fragments, but for pixel centres on snapped slivers of an outline.
TEST(SvbspScenes, ShadowedFragmentsOnlyGiveTheSameMasks) {
  for (const char* name : {"table", "three-lights", "room"}) {
    const Scene scene = testing::resized(load_scene(name, {}), 320, 180);
    const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
    SvbspMethod both({}), shadowed({"svbsp", {{"shadowed_only", "1"}}});
    both.prepare(scene, {});
    shadowed.prepare(scene, {});
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
      const ShadowMask expected = testing::light_mask(both, scene, vsb, l);
      const ShadowMask got = testing::light_mask(shadowed, scene, vsb, l);
      std::size_t differing = 0;
      for (std::size_t i = 0; i < got.pixels.size(); ++i) {
        differing += got.pixels[i] != expected.pixels[i];
      }
      // Only centres that no fragment of their face owns may differ: where a cut point on
      // the face's outline snaps off it (1/256 pixel), a sliver of the face has no fragment.
      EXPECT_LE(differing, got.pixels.size() / 10000) << name << " L" << l;
      EXPECT_LT(shadowed.fragments().size(), both.fragments().size()) << name << " L" << l;
      EXPECT_TRUE(std::none_of(shadowed.fragments().begin(), shadowed.fragments().end(),
                               [](const svbsp::Fragment& f) { return f.lit; }));
    }
  }
}

}  // namespace
}  // namespace shadowkit::svbsp
