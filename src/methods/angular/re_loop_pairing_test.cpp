#include "re_loop_pairing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <tuple>

#include "loops_in_frame_testing.h"
#include "occluders.h"
#include "shadowkit/scene/scene_file.h"
#include "testing/test_scenes.h"

namespace shadowkit::angular {
namespace {

// Object 0 of a scene under light 0, its RE loops split into branches and paired over
// \p entries entries of its theta range.
struct Paired {
  Scene scene;
  LightFrame frame;
  FarSheets sheets;
  LoopsInFrame loops;
  ThetaQuantization q;
  std::vector<ThetaSlice> slices;
  SlicedMesh m;
  LoopBranches branches;
  std::vector<RePair> pairs;

  Paired(Scene s, int entries)
      : scene(std::move(s)),
        frame(scene.lights[0], scene.camera, scene.bounds().center()),
        sheets(occluding_sheets(scene, scene.lights[0])[0]),
        loops(scene.objects[0].mesh, sheets, frame),
        q(loops.quantization(entries)),
        slices(slices_of(q, frame.point_light())),
        m{scene.objects[0].mesh, sheets, loops.local, loops.theta, loops.hidden_id},
        branches(split_into_branches(m, loops.ridges, loops.loops, frame.point_light())),
        pairs(pair_branches(m, loops.ridges, branches, q, slices)) {}

  int count(Turn::Kind kind) const {
    return int(
        std::ranges::count_if(branches.turns, [kind](const Turn& t) { return t.kind == kind; }));
  }
  // The loop that holds ridge edge \p re.
  std::size_t loop_of(std::uint32_t re) const {
    for (std::size_t l = 0; l < loops.loops.size(); ++l) {
      if (std::ranges::count(loops.loops[l].edges, re)) return l;
    }
    return loops.loops.size();
  }
  // The table pairs Sec. 3.3 makes of RePair \p p, and the fallbacks it needed.
  std::pair<std::vector<EntryPair>, std::size_t> filled(const RePair& p) const {
    SliceScratch scratch;
    std::vector<EntryPair> out;
    PairingStats stats;
    insert_hidden_edges(m, loops.ridges, hidden_edges(m.mesh, m.sheets), {&p, 1}, slices, scratch,
                        out, stats);
    return {out, stats.fallbacks};
  }
  // The far-sheet walk from \p p's begin.
  std::vector<EntryPair> walked(const RePair& p) const {
    SliceScratch scratch;
    std::vector<EntryPair> out;
    walk(m, slices[p.entry], loops.ridges[p.begin].face, p.from, scratch, out);
    return out;
  }
};

// Every pair's end is where the far sheet from its begin ends (the walk's last crossing),
// and Sec. 3.3's hidden edges, inserted by phi, give the walk's pairs face for face.
void expect_pairs_join_their_far_sheets(const Paired& paired) {
  ASSERT_FALSE(paired.pairs.empty());
  for (const RePair& p : paired.pairs) {
    ASSERT_GE(p.end, 0) << "entry " << p.entry;
    const std::vector<EntryPair> walk = paired.walked(p);
    ASSERT_FALSE(walk.empty());
    EXPECT_EQ(std::max(walk.back().phi_begin, walk.back().phi_end), p.to.phi) << p.entry;
    const auto [filled, fallbacks] = paired.filled(p);
    EXPECT_EQ(fallbacks, 0u) << "entry " << p.entry;
    ASSERT_EQ(filled.size(), walk.size()) << "entry " << p.entry;
    for (std::size_t i = 0; i < walk.size(); ++i) {
      EXPECT_EQ(filled[i].hidden, walk[i].hidden);
      EXPECT_EQ(filled[i].phi_begin, walk[i].phi_begin);
      EXPECT_EQ(filled[i].phi_end, walk[i].phi_end);
    }
  }
}

// The RePairs of entry \p k, by phi of their begins.
std::vector<RePair> in_entry(const std::vector<RePair>& pairs, std::uint32_t k) {
  std::vector<RePair> out;
  std::ranges::copy_if(pairs, std::back_inserter(out),
                       [k](const RePair& p) { return p.entry == k; });
  std::ranges::sort(out, {}, [](const RePair& p) { return p.from.phi; });
  return out;
}

// Figs. 3 / 22-24: the helical band's RE loop winds twice around as the light sees it. Its
// peaks start groups that merge at minima; where the two windings overlap, one entry holds
// two pairs of the same loop that interleave in phi (a b < g h < e f < j k of Fig. 22), and
// each pairs the ends of one layer of far sheet. No VREPIP split is needed (Sec. 3: the
// table avoids decomposing coiled loops).
TEST(RePairing, ACoiledLoopPairsEachLayerWithItself) {
  const Paired coil(load_scene("coil", {}), 300);
  ASSERT_EQ(coil.loops.loops.size(), 1u);
  EXPECT_GE(coil.count(Turn::peak), 2);
  EXPECT_EQ(coil.count(Turn::peak) + coil.count(Turn::hole_peak), coil.count(Turn::minimum));
  expect_pairs_join_their_far_sheets(coil);
  int interleaved = 0;
  for (int k = 0; k < coil.q.resolution; ++k) {
    const std::vector<RePair> at = in_entry(coil.pairs, std::uint32_t(k));
    for (std::size_t i = 0; i + 1 < at.size(); ++i) {
      interleaved += at[i + 1].from.phi < at[i].to.phi && at[i].to.phi < at[i + 1].to.phi;
    }
  }
  EXPECT_GT(interleaved, 10);
}

// Secs. 2.2 / 3.2: the house's garage roof under its sun. Where a branch going down passes
// one going up as the sun sees them, peak pairing joins crossings the far sheet does not (92
// of 349 pairs walked). Split at the two VREPIPs there, the loop's pieces pair by their peaks
// with 8 walked, and the split is kept; the table is the walk's, pair for pair.
TEST(RePairing, ASplitAtVrepipsIsKeptWhereItsPairsFallBackLess) {
  Scene scene = load_scene_file(std::string(SHADOWKIT_SOURCE_DIR) + "/examples/house.json", {});
  scene.objects = {scene.objects[25]};
  const Paired roof(std::move(scene), 300);
  SliceScratch scratch;
  std::vector<EntryPair> unsplit, split, walked;
  PairingStats before, after;
  insert_hidden_edges(roof.m, roof.loops.ridges, hidden_edges(roof.m.mesh, roof.m.sheets),
                      roof.pairs, roof.slices, scratch, unsplit, before);
  EXPECT_EQ(before.re_pairs, 349u);
  EXPECT_EQ(before.fallbacks, 92u);
  pair_re_loops(roof.m, roof.loops.ridges, roof.loops.loops, roof.q, roof.slices, scratch, split,
                after);
  EXPECT_EQ(after.vrepips, 2u);
  EXPECT_EQ(after.re_pairs, 349u);
  EXPECT_EQ(after.fallbacks, 8u);
  for (const RidgeEdgeLoop& loop : roof.loops.loops) {
    slice_loop(roof.m, roof.loops.ridges, loop, roof.q, roof.slices, scratch, walked);
  }
  const auto key = [](const EntryPair& p) {
    return std::tuple(p.entry, p.phi_begin, p.phi_end, p.hidden);
  };
  std::ranges::sort(split, {}, key);
  std::ranges::sort(walked, {}, key);
  ASSERT_EQ(split.size(), walked.size());
  for (std::size_t i = 0; i < split.size(); ++i) EXPECT_EQ(key(split[i]), key(walked[i])) << i;
}

// Where peak pairing needs no help the loops are not split: the coil's windings cross (four
// VREPIPs), and its peaks pair each layer with itself (Sec. 3.2, Fig. 22).
TEST(RePairing, LoopsWhosePairsAllJoinTheirFarSheetsAreNotSplit) {
  const Paired coil(load_scene("coil", {}), 300);
  SliceScratch scratch;
  std::vector<EntryPair> out;
  PairingStats stats;
  pair_re_loops(coil.m, coil.loops.ridges, coil.loops.loops, coil.q, coil.slices, scratch, out,
                stats);
  EXPECT_EQ(stats.fallbacks, 0u);
  EXPECT_EQ(stats.vrepips, 0u);
}

// Figs. 13 / 25: the frame's hole is a second loop, whose peak is hole-like (its branches go
// down then up from left to right). Its branches are inserted into the outer loop's pair:
// through the hole, shadow begins at the outer loop and ends at the hole's, then begins at
// the hole's and ends at the outer loop's.
TEST(RePairing, AHolesBranchesAreInsertedIntoThePairAroundIt) {
  const Paired holed(load_scene("holed", {}), 200);
  ASSERT_EQ(holed.loops.loops.size(), 2u);
  EXPECT_EQ(holed.count(Turn::hole_peak), 1);
  expect_pairs_join_their_far_sheets(holed);
  int through_hole = 0;
  for (int k = 0; k < holed.q.resolution; ++k) {
    const std::vector<RePair> at = in_entry(holed.pairs, std::uint32_t(k));
    if (at.size() != 2) continue;
    const auto outer = holed.loop_of(at[0].begin);
    const auto hole = 1 - outer;
    if (holed.loop_of(std::uint32_t(at[0].end)) != hole) continue;
    EXPECT_EQ(holed.loop_of(at[1].begin), hole);
    EXPECT_EQ(holed.loop_of(std::uint32_t(at[1].end)), outer);
    EXPECT_LT(at[0].to.phi, at[1].from.phi);  // the hole between the pairs
    ++through_hole;
  }
  EXPECT_GT(through_hole, 20);
}

// Figs. 26-27: the U whose notch faces the light. The arms' flat tops join equal adjacent
// peaks: each is one peak, the edge between them ignored, and each starts a group (one arm).
// Down to the notch floor the groups' pairs are the far sheet's. Below it, the floor's ridge
// edge (at constant theta, inside a branch) has carried one arm's end across the other arm's
// begin: the two groups' pairs interleave, while the far sheet joins each begin to the other
// end (one span inside the other). Sec. 3.3's hidden edges, inserted by phi, then do not lead
// face by face to the partner: those pairs are walked, and counted. At the minimum the groups
// merge into one pair, the far sheet's again.
TEST(RePairing, EqualAdjacentPeaksAreOnePeakAndAHoleLikeBandIsWalked) {
  const Paired u(load_scene("hole-like", {}), 200);
  ASSERT_EQ(u.loops.loops.size(), 1u);
  EXPECT_EQ(u.count(Turn::peak), 2);
  EXPECT_EQ(u.count(Turn::minimum), 2);
  std::size_t in_branches = 0;
  for (const Branch& b : u.branches.branches) in_branches += b.ridges.size();
  EXPECT_EQ(u.loops.ridges.size() - in_branches, 3u);  // the arms' tops and the base's bottom
  // The floor: the ridge edge at constant theta inside a branch.
  double floor = 0;
  for (const Branch& b : u.branches.branches) {
    for (const std::uint32_t i : b.ridges) {
      const RidgeEdge& re = u.loops.ridges[i];
      if (u.loops.theta[re.from] == u.loops.theta[re.to]) floor = u.loops.theta[re.from];
    }
  }
  ASSERT_NE(floor, 0);
  const double merge = u.branches.turns[2].theta;  // the higher minimum
  std::size_t walked = 0, most = 0;
  for (const RePair& p : u.pairs) {
    const std::vector<EntryPair> walk = u.walked(p);
    const auto [filled, fallbacks] = u.filled(p);
    ASSERT_EQ(filled.size(), walk.size());
    for (std::size_t i = 0; i < walk.size(); ++i) {
      EXPECT_EQ(filled[i].hidden, walk[i].hidden);
      EXPECT_EQ(filled[i].phi_end, walk[i].phi_end);
    }
    const bool joined = std::max(walk.back().phi_begin, walk.back().phi_end) == p.to.phi;
    EXPECT_EQ(fallbacks, joined ? 0u : 1u) << p.entry;
    if (joined) continue;
    ++walked;
    EXPECT_LT(p.theta, floor);
    EXPECT_GT(p.theta, merge);
  }
  for (int k = 0; k < u.q.resolution; ++k) most = std::max(most, in_entry(u.pairs, k).size());
  EXPECT_EQ(most, 2u);  // the two arms
  EXPECT_GT(walked, 0u);
}

// Fig. 27 sliced exactly at the equal adjacent peaks (a directional light, whose slices are
// Y = theta, holds both ends of each arm's top back edge exactly): the left peak is ignored,
// the right one kept with the left one's other edge, so each arm pairs its left top corner
// with its right one on the hidden back face.
TEST(RePairing, Fig27KeepsTheRightOfEqualAdjacentPeaks) {
  const std::vector<Vec3> outline = {{-2, 0, 0},  {2, 0, 0},    {2, 2, 0},  {1, 2, 0},
                                     {1, 0.5, 0}, {-1, 0.5, 0}, {-1, 2, 0}, {-2, 2, 0}};
  const Light light = Light::directional(normalize(Vec3{0, -1, -0.5}));
  const Camera camera = testing::camera({0, 0, 20}, {0, 0, 0}, 64, 48);
  Paired u(testing::make_scene(camera, {light}, {prism(outline)}), 1);
  const double peak = u.frame.local({-2, 2, -1}).y;
  ASSERT_EQ(u.frame.local({1, 2, -1}).y, peak);
  EXPECT_EQ(u.count(Turn::peak), 2);
  for (const Turn& t : u.branches.turns) {
    if (t.kind == Turn::minimum) continue;
    EXPECT_EQ(t.theta, peak);
    const double x = u.frame.local(u.scene.objects[0].mesh.vertices[t.vertex]).x;
    // The kept peak is the right one of its arm's two.
    EXPECT_TRUE(x == u.frame.local({-1, 2, -1}).x || x == u.frame.local({2, 2, -1}).x) << x;
  }
  u.q = {peak - 0.5, 1, 1, false};
  ASSERT_EQ(u.q.centre(0), peak);
  u.slices = {ThetaSlice::at(peak, false)};
  const std::vector<RePair> pairs =
      in_entry(pair_branches(u.m, u.loops.ridges, u.branches, u.q, u.slices), 0);
  ASSERT_EQ(pairs.size(), 2u);
  const double phi[4] = {u.frame.local({-2, 2, -1}).x, u.frame.local({-1, 2, -1}).x,
                         u.frame.local({1, 2, -1}).x, u.frame.local({2, 2, -1}).x};
  EXPECT_DOUBLE_EQ(pairs[0].from.phi, phi[0]);
  EXPECT_DOUBLE_EQ(pairs[0].to.phi, phi[1]);
  EXPECT_DOUBLE_EQ(pairs[1].from.phi, phi[2]);
  EXPECT_DOUBLE_EQ(pairs[1].to.phi, phi[3]);
}

// Sec. 3.3: a cube lit from a corner. Each pair of ridge edges is filled with the hidden
// edges between its ends, in duplicate: consecutive table pairs meet at bit-identical phi,
// each on its own hidden face, from the begin's crossing to the end's.
TEST(RePairing, HiddenEdgesAreInsertedInDuplicate) {
  const Paired cube(
      testing::make_scene(testing::camera({0, 0, 20}, {0, 0, 0}, 64, 48), {Light::point({3, 4, 5})},
                          {testing::box({-1, -1, -1}, {1, 1, 1})}),
      64);
  // A convex object's loop: one peak, one minimum, two branches.
  EXPECT_EQ(cube.count(Turn::peak), 1);
  EXPECT_EQ(cube.count(Turn::minimum), 1);
  EXPECT_EQ(cube.branches.branches.size(), 2u);
  int split = 0;
  for (const RePair& p : cube.pairs) {
    const auto [filled, fallbacks] = cube.filled(p);
    ASSERT_EQ(fallbacks, 0u);
    ASSERT_FALSE(filled.empty());
    EXPECT_EQ(filled.front().phi_begin, p.from.phi);
    EXPECT_EQ(filled.back().phi_end, p.to.phi);
    for (std::size_t i = 1; i < filled.size(); ++i) {
      EXPECT_EQ(filled[i].phi_begin, filled[i - 1].phi_end);
      EXPECT_NE(filled[i].hidden, filled[i - 1].hidden);
    }
    for (const EntryPair& e : filled) {
      EXPECT_LT(cube.m.mesh.planes[e.hidden].distance({3, 4, 5}), 0);  // hidden faces
    }
    split += filled.size() > 1;
  }
  EXPECT_GT(split, 10);
}

// Two loops touching at a vertex: two cubes of one mesh sharing a corner. The loops' turns
// and branches stay apart, and every pair joins its own far sheet.
TEST(RePairing, TouchingLoopsPairApart) {
  PolygonSoup two = testing::box({-1, -1, -1}, {0, 0, 0});
  two.append(testing::box({0, 0, 0}, {1, 1, 1}));
  const Paired touching(testing::make_scene(testing::camera({0, 0, 20}, {0, 0, 0}, 64, 48),
                                            {Light::point({0.3, 6, 0.2})}, {two}),
                        128);
  EXPECT_EQ(touching.count(Turn::peak), 2);
  EXPECT_EQ(touching.count(Turn::minimum), 2);
  expect_pairs_join_their_far_sheets(touching);
}

// A light in the planes of two faces of a box (as in the conformance scene
// lights-in-face-planes, whose rows pairing=paper also runs): those faces occlude nothing,
// and every pair still names ridge edges of the loop, in the slice's half-plane, and joins
// its far sheet.
TEST(RePairing, ALightInFacePlanesPairsTheLoopOfTheOtherFaces) {
  const Paired box(
      testing::make_scene(testing::camera({-6, 3, 3}, {0, 0.5, 0}, 64, 48),
                          {Light::point({-2, 1.2, 1})}, {testing::box({-1, 0, -1}, {1, 1.2, 1})}),
      64);
  for (const RePair& p : box.pairs) {
    EXPECT_LT(p.begin, box.loops.ridges.size());
    EXPECT_LT(p.end, std::int64_t(box.loops.ridges.size()));
    EXPECT_GT(p.from.rho, 0);
  }
  expect_pairs_join_their_far_sheets(box);
}

// The paper takes closed, consistently oriented objects: an open one (the Z-folded strip of
// Figs. 3 / 23) is left to the walk.
TEST(RePairing, AnOpenMeshIsLeftToTheWalk) {
  PolygonSoup z = testing::polygon({{-1, 2, 1}, {1, 2, 1}, {1, 2, -1}, {-1, 2, -1}});
  z.append(testing::polygon({{1, 2, 1}, {1, 1, 1}, {1, 1, -1}, {1, 2, -1}}));
  const Scene scene = testing::make_scene(testing::camera({0, 0, 20}, {0, 0, 0}, 64, 48),
                                          {Light::point({0, 4, 0})}, {z});
  const FarSheets sheets = occluding_sheets(scene, scene.lights[0])[0];
  const auto loops = chain_ridge_edge_loops(find_ridge_edges(scene.objects[0].mesh, sheets));
  EXPECT_FALSE(paper_pairing_applies(sheets, loops, false, false));
  const FarSheets solid = far_sheets(
      testing::make_scene(testing::camera({0, 0, 20}, {0, 0, 0}, 64, 48), {Light::point({0, 4, 0})},
                          {testing::box({-1, -1, -1}, {1, 1, 1})})
          .objects[0]
          .mesh,
      Light::point({0, 4, 0}), true);
  EXPECT_TRUE(paper_pairing_applies(solid, {}, false, false));
  EXPECT_FALSE(paper_pairing_applies(solid, {}, true, false));  // around the light
  EXPECT_FALSE(paper_pairing_applies(solid, {}, false, true));  // on the light's axis
}

}  // namespace
}  // namespace shadowkit::angular
