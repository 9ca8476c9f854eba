#include "scene_bsp.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <map>

#include "convex_solids.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/scene/scene_file.h"
#include "svbsp_test_support.h"
#include "testing/test_scenes.h"

namespace shadowkit::svbsp {
namespace {

// Faces in the order the tree visits them from \p light.
std::vector<std::uint32_t> visit_order(const SceneBsp& bsp, const Light& light) {
  std::vector<std::uint32_t> faces;
  bsp.front_to_back(light, [&](NodePieces node) {
    for (const ConvexPolygon& p : node.pieces) faces.push_back(p.face);
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
    bsp.front_to_back(Light::point({0.3, 7, 0.2}), [&](NodePieces node) {
      for (const ConvexPolygon& p : node.pieces) sum[p.face] += area(p), ++pieces;
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
  // Jittered cubes: planes across an axis mostly run between them (about 3% of the faces
  // are split; a plane taken at random would split far more).
  for (const char* name : {"cubes:125", "cubes:1000"}) {
    const Scene scene = load_scene(name, {});
    const SceneBsp bsp = SceneBsp::build(scene);
    EXPECT_LT(bsp.split_count(), scene.face_count() / 20) << name;
    EXPECT_LT(bsp.depth(), 32u) << name;
  }
}

TEST(SceneBsp, TreeDoesNotDependOnThreads) {
  // Past kParallelGrain polygons, subtrees are built in parallel.
  const Scene scene = load_scene("cubes:512", {});
  const SceneBsp parallel = SceneBsp::build(scene);
  const SceneBsp serial = [&] {
    const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    return SceneBsp::build(scene);
  }();
  ASSERT_EQ(parallel.node_count(), serial.node_count());
  ASSERT_EQ(parallel.piece_count(), serial.piece_count());
  for (std::size_t i = 0; i < serial.piece_count(); ++i) {
    EXPECT_EQ(parallel.pieces()[i].face, serial.pieces()[i].face) << i;
    EXPECT_EQ(parallel.pieces()[i].vertices, serial.pieces()[i].vertices) << i;
  }
  const Light light = scene.lights[0];
  EXPECT_EQ(visit_order(parallel, light), visit_order(serial, light));
}

Scene coplanar_squares(int count, double spacing) {
  std::vector<PolygonSoup> squares;
  for (int i = 0; i < count; ++i) {
    squares.push_back(testing::horizontal_quad(i * spacing, i * spacing + 1, 0, 1, 0));
  }
  return testing::make_scene(testing::camera({0, 5, 9}, {0, 0, 0}, 64, 48),
                             {testing::point_light({0, 10, 0})}, squares);
}

TEST(SceneBsp, CoplanarPolygonsShareOneNodeOrAreSeparatedWithoutSplits) {
  // Twenty squares in one plane, more than the face-plane candidates. Stacked on one
  // another, no plane across an axis leaves a whole square on each side: one node holds
  // them all. Side by side, planes through the gaps separate them and cut none.
  const SceneBsp stacked = SceneBsp::build(coplanar_squares(20, 0));
  EXPECT_EQ(stacked.node_count(), 1u);
  EXPECT_EQ(stacked.piece_count(), 20u);
  const SceneBsp apart = SceneBsp::build(coplanar_squares(20, 2));
  EXPECT_EQ(apart.piece_count(), 20u);
  EXPECT_EQ(apart.split_count(), 0u);
  EXPECT_EQ(visit_order(apart, Light::point({0, 10, 0})).size(), 20u);
}

TEST(SceneBsp, ConvexSolidsStayWholeOneLeafEach) {
  // The cubes stand apart in their slots: planes through the gaps and their faces part them,
  // so each one is one leaf holding its six faces and nothing else.
  const Scene scene = load_scene("cubes:125", {});
  const ConvexSolids solids(scene, scene.outward_solids());
  ASSERT_EQ(solids.size(), 125u);
  const SceneBsp bsp = SceneBsp::build(scene, &solids);
  EXPECT_EQ(bsp.solid_count(), 125u);
  std::map<std::int32_t, int> leaves;
  bsp.front_to_back(scene.lights[0], [&](NodePieces node) {
    if (node.solid < 0) return;
    ++leaves[node.solid];
    EXPECT_EQ(node.pieces.size(), 6u);
    for (const ConvexPolygon& p : node.pieces) EXPECT_EQ(solids.solid_of(p.face), node.solid);
  });
  EXPECT_EQ(leaves.size(), 125u);
}

TEST(SceneBsp, EmptySceneHasNoNode) {
  const Scene scene = testing::make_scene(testing::camera({0, 5, 9}, {0, 0, 0}, 64, 48),
                                          {testing::point_light({0, 10, 0})}, {});
  const SceneBsp bsp = SceneBsp::build(scene);
  EXPECT_EQ(bsp.node_count(), 0u);
  EXPECT_EQ(bsp.piece_count(), 0u);
  EXPECT_TRUE(visit_order(bsp, Light::point({0, 10, 0})).empty());
}

Scene ball(bool inward, const Light& light) {
  const Camera cam = testing::camera({0, 5, 9}, {0, 0, 0}, 64, 48);
  return testing::make_scene(cam, {light}, {inward ? inside_out(sphere(8, 6)) : sphere(8, 6)});
}

TEST(SceneBsp, AConvexOrConcavePatchIsOneClusterWithoutSplits) {
  for (const bool inward : {false, true}) {
    const SceneBsp bsp = SceneBsp::build(ball(inward, Light::point({0, 5, 0})));
    EXPECT_EQ(bsp.node_count(), 1u) << inward;
    EXPECT_EQ(bsp.split_count(), 0u) << inward;
    EXPECT_EQ(bsp.piece_count(), 48u) << inward;
    // Without clusters (paper=1), a node per plane.
    const SceneBsp planes = SceneBsp::build(ball(inward, Light::point({0, 5, 0})), nullptr, false);
    EXPECT_GT(planes.node_count(), 8u) << inward;
  }
}

TEST(SceneBsp, AClusterGivesThePiecesTurnedToTheLightFirstOneByOne) {
  for (const bool inward : {false, true}) {
    for (const Light& light : {Light::point({0, 5, 0}), Light::point({3, -4, 1}),
                               Light::point({0, 0.2, 0}), Light::directional({1, -2, 0.5})}) {
      const Scene scene = ball(inward, light);
      const SceneBsp bsp = SceneBsp::build(scene);
      // Turned to the light: the light in front of the surface's outer side.
      std::vector<bool> turned;
      bsp.front_to_back(light, [&](NodePieces node) {
        ASSERT_EQ(node.pieces.size(), 1u);
        const double side = light_side(scene.face_plane(node.pieces[0].face), light);
        turned.push_back(inward ? side < 0 : side > 0);
      });
      ASSERT_EQ(turned.size(), 48u);
      EXPECT_TRUE(std::is_sorted(turned.rbegin(), turned.rend())) << inward;
    }
  }
}

TEST(SceneBsp, CoincidentFacesMakeNoClusterAndComeTogether) {
  // Two faces in one plane may overlap: one node hands both over at once.
  const Camera cam = testing::camera({0, 5, 9}, {0, 0, 0}, 64, 48);
  const Scene scene = testing::make_scene(
      cam, {testing::point_light({0, 10, 0})},
      {testing::horizontal_quad(-1, 1, -1, 1, 0), testing::horizontal_quad(-0.5, 1.5, -1, 1, 0)});
  std::vector<std::size_t> sizes;
  SceneBsp::build(scene).front_to_back(
      Light::point({0, 10, 0}), [&](NodePieces node) { sizes.push_back(node.pieces.size()); });
  EXPECT_EQ(sizes, std::vector<std::size_t>{2});
}

TEST(SceneBsp, CopiesOfAFacePlanarOnlyWithinToleranceComeTogether) {
  // A quad whose fourth corner lies 1e-6 off the plane of the other three is one face (planar
  // within the scene's tolerance); its corners lie off its plane either way. Its coincident
  // copy lies in that plane as much as it does: one node, not a copy cut by the other's plane
  // and shadowed by it.
  const Camera cam = testing::camera({0, 5, 9}, {0, 0, 0}, 64, 48);
  const PolygonSoup quad = testing::polygon({{-1, 0, 1}, {1, 0, 1}, {1, 1e-6, -1}, {-1, 0, -1}});
  const Scene scene = testing::make_scene(cam, {testing::point_light({0, 10, 0})}, {quad, quad});
  for (const bool clusters : {false, true}) {
    const SceneBsp bsp = SceneBsp::build(scene, nullptr, clusters);
    std::vector<std::size_t> sizes;
    bsp.front_to_back(Light::point({0, 10, 0}),
                      [&](NodePieces node) { sizes.push_back(node.pieces.size()); });
    EXPECT_EQ(sizes, std::vector<std::size_t>{2}) << "clusters " << clusters;
    EXPECT_EQ(bsp.split_count(), 0u);
  }
}

}  // namespace
}  // namespace shadowkit::svbsp
