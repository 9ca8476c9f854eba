#include <gtest/gtest.h>

#include "shadow_generator.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit::svbsp {
namespace {

// The cells filled in parallel give the fragments one tree gives, bit for bit, in the same
// order, and a tree of as many nodes.
void expect_same_as_one_tree(const std::string& name, GeneratorSettings settings) {
  SCOPED_TRACE(name);
  const Scene scene = load_scene(name, {});
  const SceneBsp bsp = SceneBsp::build(scene);
  const Light& light = scene.lights[0];
  ShadowGenerator probe(scene, light, settings);
  probe.divide(bsp.pieces());
  ASSERT_GE(probe.tree().cell_count(), 8u);  // else both are one tree

  const ShadowedWhole far_side = far_side_of(scene, light);
  settings.cells_in_parallel = true;
  const LightFragments cells = generate_shadows(bsp, scene, light, settings, far_side);
  settings.cells_in_parallel = false;
  const LightFragments one = generate_shadows(bsp, scene, light, settings, far_side);
  EXPECT_EQ(cells.svbsp_nodes, one.svbsp_nodes);
  EXPECT_EQ(cells.light_facing, one.light_facing);
  ASSERT_EQ(cells.fragments.size(), one.fragments.size());
  std::size_t lit = 0;
  for (std::size_t i = 0; i < one.fragments.size(); ++i) {
    const ConvexPolygon& a = cells.fragments[i].polygon;
    const ConvexPolygon& b = one.fragments[i].polygon;
    ASSERT_EQ(cells.fragments[i].lit, one.fragments[i].lit) << i;
    ASSERT_EQ(a.face, b.face) << i;
    ASSERT_TRUE(a.vertices == b.vertices) << i;
    ASSERT_TRUE(a.edge_in_tree == b.edge_in_tree) << i;
    lit += one.fragments[i].lit;
  }
  // Both verdicts, and pieces cut by the cells' planes, are there to compare.
  EXPECT_GT(lit, one.fragments.size() / 20);
  EXPECT_LT(lit, one.fragments.size());
}

TEST(CellsInParallel, GiveTheFragmentsOfOneTreeUnderAPointLight) {
  expect_same_as_one_tree("cubes:2000", {});
}

TEST(CellsInParallel, GiveTheFragmentsOfOneTreeUnderTheSun) {
  expect_same_as_one_tree("terrain:120", {});
}

TEST(CellsInParallel, GiveTheFragmentsOfOneTreeWithoutMergesOrWholePieces) {
  GeneratorSettings settings;
  settings.merge_siblings = false;
  settings.whole_pieces = false;
  settings.skip_edges_in_tree = false;
  expect_same_as_one_tree("cubes:2000", settings);
}

TEST(CellsInParallel, GiveTheFragmentsOfOneTreeForOneSidedSurfaces) {
  GeneratorSettings settings;
  settings.two_sided = false;
  expect_same_as_one_tree("terrain:120", settings);
}

}  // namespace
}  // namespace shadowkit::svbsp
