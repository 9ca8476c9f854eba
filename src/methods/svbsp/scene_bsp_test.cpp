#include "scene_bsp.h"

#include <gtest/gtest.h>

#include <map>

#include "shadowkit/scene/scene_file.h"
#include "testing/test_scenes.h"

namespace shadowkit::svbsp {
namespace {

// Faces in the order the tree visits them from \p light.
std::vector<std::uint32_t> visit_order(const SceneBsp& bsp, const Light& light) {
  std::vector<std::uint32_t> faces;
  bsp.front_to_back(light, [&](std::span<const ConvexPolygon> pieces) {
    for (const ConvexPolygon& p : pieces) faces.push_back(p.face);
  });
  return faces;
}

Scene three_layers() {
  const Camera cam = testing::camera({0, 5, 9}, {0, 0, 0}, 64, 48);
  return testing::make_scene(
      cam, {testing::point_light({0, 10, 0})},
      {testing::horizontal_quad(-3, 3, -3, 3, 1), testing::horizontal_quad(-2, 2, -2, 2, 2),
       testing::horizontal_quad(-1, 1, -1, 1, 3)});
}

TEST(SceneBsp, OrdersParallelLayersFromEitherSide) {
  const Scene scene = three_layers();
  const SceneBsp bsp = SceneBsp::build(scene);
  EXPECT_EQ(visit_order(bsp, Light::point({0, 10, 0})), (std::vector<std::uint32_t>{2, 1, 0}));
  EXPECT_EQ(visit_order(bsp, Light::point({0, -10, 0})), (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(visit_order(bsp, Light::directional({0.2, -1, 0})),
            (std::vector<std::uint32_t>{2, 1, 0}));
  EXPECT_EQ(visit_order(bsp, Light::directional({0, 1, 0.3})),
            (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(SceneBsp, PiecesOfEveryFaceSumToItsArea) {
  for (const char* name : {"tetra:3", "table", "room"}) {
    const Scene scene = load_scene(name, {});
    const SceneBsp bsp = SceneBsp::build(scene);
    std::map<std::uint32_t, double> sum;
    std::size_t pieces = 0;
    bsp.front_to_back(Light::point({0.3, 7, 0.2}), [&](std::span<const ConvexPolygon> ps) {
      for (const ConvexPolygon& p : ps) sum[p.face] += area(p), ++pieces;
    });
    EXPECT_EQ(pieces, bsp.piece_count()) << name;
    ASSERT_EQ(sum.size(), scene.face_count()) << name;
    for (const auto& [face, a] : sum) {
      const SceneObject& o = scene.objects[scene.object_of_face(face)];
      EXPECT_NEAR(a, o.mesh.areas[scene.local_face(face)], 1e-9 * (1 + a)) << name << " " << face;
    }
  }
}

TEST(SceneBsp, RootChoiceKeepsSplitsLowOnACubeField) {
  // Jittered cubes: a plane taken at random would split far more polygons.
  const Scene scene = load_scene("cubes:125", {});
  const SceneBsp bsp = SceneBsp::build(scene);
  EXPECT_LT(bsp.split_count(), scene.face_count() / 2);
  EXPECT_LT(bsp.depth(), 64u);
}

}  // namespace
}  // namespace shadowkit::svbsp
