#include <gtest/gtest.h>

#include <algorithm>

#include "shadowkit/scene/scene_file.h"
#include "svbsp_method.h"
#include "svbsp_test_support.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"

namespace shadowkit::svbsp {
namespace {

// The sub-objects that Crow's footprints find wholly in the shadow of nearer ones are
// shadowed whole without filtering: fewer pieces filtered, and the same lit area on every
// face.
TEST(SvbspScenes, FootprintsShadowPartsWholeAndKeepTheLitAreas) {
  for (const Light& light :
       {testing::point_light({3, 14, 5}), testing::directional_light({-0.3, -1, -0.2})}) {
    const Scene scene = testing::cube_block(light);
    SvbspMethod with({}), without({"svbsp", {{"footprints", "0"}}});
    for (SvbspMethod* m : {&with, &without}) {
      m->prepare(scene, {});
      m->build(scene, 0, {});
    }
    EXPECT_LT(testing::counter(with, "light_facing") + 30 * 3,
              testing::counter(without, "light_facing"))
        << int(light.type);  // more than 30 cubes, three faces each turned to the light
    const auto want = face_areas(without.fragments());
    for (const auto& [face, a] : face_areas(with.fragments())) {
      const double size = face_area(scene, face);
      EXPECT_NEAR(a.lit, want.at(face).lit, 1e-9 * size) << int(light.type) << " " << face;
    }
  }
}

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

// Two copies of one closed box at one spot, one corner raised 1e-6 so that three faces are
// planar only within the scene's tolerance: the pair casts exactly the one box's shadow and
// lights its faces as the one box does. Hazard: a copy's top, its corners off its plane by
// more than the plane tests' tolerance, cut by the other's plane and shadowed by it.
TEST(SvbspScenes, ACoincidentCopyOfNearlyPlanarFacesCastsNoMoreShadow) {
  PolygonSoup box = testing::box({-1, 0.2, -1}, {1, 1.2, 1});
  box.positions[7].y += 1e-6;
  for (const std::string paper : {"0", "1"}) {
    const testing::CopyDifference d = testing::coincident_copy_difference(
        [&] {
          return std::make_unique<SvbspMethod>(MethodOptions{"svbsp", {{"paper", paper}}});
        },
        box);
    EXPECT_EQ(d.differ, 0) << "paper " << paper;
    EXPECT_GT(d.lit_box, 1000);
  }
}

}  // namespace
}  // namespace shadowkit::svbsp
