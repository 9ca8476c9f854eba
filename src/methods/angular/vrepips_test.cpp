#include "vrepips.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "loops_in_frame_testing.h"
#include "occluders.h"
#include "shadowkit/scene/scene_file.h"
#include "testing/test_scenes.h"

namespace shadowkit::angular {
namespace {

constexpr double kPi = std::numbers::pi;

// One closed RE loop through light-frame points, edge i from point i to point i + 1, all VREs.
struct Loop {
  std::vector<Vec3> local;
  std::vector<RidgeEdge> ridges;
  std::vector<RidgeEdgeLoop> loops;

  explicit Loop(std::vector<Vec3> points) : local(std::move(points)) {
    const auto n = std::uint32_t(local.size());
    loops.push_back({{}, true});
    for (std::uint32_t i = 0; i < n; ++i) {
      ridges.push_back({i, i, (i + 1) % n, 0, false});
      loops[0].edges.push_back(i);
    }
  }
};

Vec3 at(std::span<const Vec3> local, const RidgeEdge& re, double t) {
  return local[re.from] + (local[re.to] - local[re.from]) * t;
}

// The pieces of VREs of all the loops, each cut short of its ends so that the ends the split
// makes at a VREPIP, on the other VRE's projection, are not read as crossings.
std::vector<LoopPiece> vre_pieces(std::span<const RidgeEdge> ridges,
                                  const std::vector<SimpleLoop>& loops) {
  std::vector<LoopPiece> out;
  for (const SimpleLoop& loop : loops) {
    for (LoopPiece p : loop) {
      if (ridges[p.ridge].hidden_ridge) continue;
      const double inset = 1e-7 * (p.t1 - p.t0);
      p.t0 += inset, p.t1 -= inset;
      out.push_back(p);
    }
  }
  return out;
}

// Sec. 2.2's aim: after the split, no two VREs' pieces cross as the light sees them, within
// a loop or between loops. (Pieces of one edge lie on one line, where the orientation tests
// are rounding noise.)
int crossings_left(std::span<const Vec3> local, std::span<const RidgeEdge> ridges,
                   const std::vector<SimpleLoop>& loops, bool point_light) {
  const std::vector<LoopPiece> pieces = vre_pieces(ridges, loops);
  int n = 0;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const RidgeEdge& a = ridges[pieces[i].ridge];
    for (std::size_t j = i + 1; j < pieces.size(); ++j) {
      if (pieces[j].ridge == pieces[i].ridge) continue;
      const RidgeEdge& b = ridges[pieces[j].ridge];
      n += projections_cross(at(local, a, pieces[i].t0), at(local, a, pieces[i].t1),
                             at(local, b, pieces[j].t0), at(local, b, pieces[j].t1), point_light)
               .has_value();
    }
  }
  return n;
}

// Every ridge edge of the loops is traversed once: its pieces cover [0, 1] end to end.
void expect_each_ridge_once(std::span<const RidgeEdgeLoop> loops,
                            const std::vector<SimpleLoop>& split) {
  std::map<std::uint32_t, std::vector<std::pair<double, double>>> pieces;
  for (const SimpleLoop& loop : split) {
    for (const LoopPiece& p : loop) pieces[p.ridge].emplace_back(p.t0, p.t1);
  }
  std::size_t ridges = 0;
  for (const RidgeEdgeLoop& loop : loops) ridges += loop.edges.size();
  ASSERT_EQ(pieces.size(), ridges);
  for (auto& [ridge, list] : pieces) {
    std::ranges::sort(list);
    EXPECT_EQ(list.front().first, 0) << ridge;
    EXPECT_EQ(list.back().second, 1) << ridge;
    for (std::size_t i = 1; i < list.size(); ++i) EXPECT_EQ(list[i].first, list[i - 1].second);
  }
}

// How many times a loop goes around the light's +Z axis as the light sees it.
double turns_about_axis(std::span<const Vec3> local, std::span<const RidgeEdge> ridges,
                        const SimpleLoop& loop) {
  double angle = 0;
  for (const LoopPiece& p : loop) {
    const Vec3 a = at(local, ridges[p.ridge], p.t0), b = at(local, ridges[p.ridge], p.t1);
    angle += std::remainder(std::atan2(b.y, b.x) - std::atan2(a.y, a.x), 2 * kPi);
  }
  return angle / (2 * kPi);
}

TEST(Vrepips, ProjectionsCrossProperlyOnly) {
  // A light along +Z: the projection is (x, y).
  const auto cross = projections_cross({-1, 0, 1}, {1, 0, 1}, {0, -1, 3}, {0, 3, 5}, false);
  ASSERT_TRUE(cross);
  EXPECT_DOUBLE_EQ(cross->s, 0.5);
  EXPECT_DOUBLE_EQ(cross->t, 0.25);
  EXPECT_FALSE(projections_cross({-1, 0, 1}, {1, 0, 1}, {0, 0, 3}, {0, 3, 5}, false));   // touch
  EXPECT_FALSE(projections_cross({-1, 0, 1}, {1, 0, 1}, {0, 1, 3}, {0, 3, 5}, false));   // apart
  EXPECT_FALSE(projections_cross({-1, 0, 1}, {1, 0, 1}, {-2, 0, 3}, {0, 0, 5}, false));  // along
  // A point light at the origin: the rays, not the coordinates, decide.
  const auto far = projections_cross({-1, 0, 5}, {1, 0, 5}, {0, -2, 10}, {0, 2, 10}, true);
  ASSERT_TRUE(far);
  EXPECT_DOUBLE_EQ(far->s, 0.5);
  EXPECT_DOUBLE_EQ(far->t, 0.5);
  EXPECT_FALSE(projections_cross({-1, 0, 5}, {1, 0, 5}, {0, -1, -5}, {0, 1, -5}, true));  // behind
}

// Figs. 3 / 9 / 12: a loop coiled twice about a point light's axis, the second winding nearer
// the light and inside the first where it goes on outside it: in the projection
// r = 1 + cos(a / 2) / 2 over a in [0, 4 pi), which crosses itself once, at a = pi and 3 pi.
Loop coil(int n) {
  std::vector<Vec3> points;
  for (int k = 0; k < n; ++k) {
    const double a = 4 * kPi * (k + 0.5) / n;
    const double r = 1 + std::cos(a / 2) / 2, depth = 5 + std::sin(a / 2);
    points.push_back(Vec3{r * std::cos(a), r * std::sin(a), 1} * depth);
  }
  return Loop(points);
}

TEST(Vrepips, ACoilHasOneNearAndFarPairAndSplitsIntoTwoSimpleLoops) {
  const Loop c = coil(48);
  const Vrepips v = find_vrepips(c.local, c.ridges, c.loops, true);
  ASSERT_EQ(v.at.size(), 1u);
  ASSERT_EQ(v.points.size(), 2u);
  const Vrepip& near = v.points[v.at[0].vrepips[0]];
  const Vrepip& far = v.points[v.at[0].vrepips[1]];
  // a = 3 pi lies on edge 35 (a from 2.96 pi to 3.04 pi), nearer; a = pi on edge 11, farther.
  EXPECT_EQ(near.ridge, 35u);
  EXPECT_EQ(far.ridge, 11u);
  EXPECT_LT(near.depth, far.depth);
  EXPECT_NEAR(std::atan2(near.p.y, near.p.x), kPi, 1e-9);
  // Both on one ray from the light: the imaginary edge runs along it.
  EXPECT_NEAR(length(cross(normalize(near.p), normalize(far.p))), 0, 1e-12);

  const std::vector<SimpleLoop> split = split_at_vrepips(c.local, c.ridges, c.loops, v, true);
  ASSERT_EQ(split.size(), 2u);
  expect_each_ridge_once(c.loops, split);
  EXPECT_EQ(crossings_left(c.local, c.ridges, split, true), 0);
  // The external loop first (Sec. 2.2): from edge 0 to the far VREPIP on edge 11, across the
  // imaginary edge to the near one on edge 35 and on to the end; then the internal loop.
  ASSERT_EQ(split[0].size(), 25u);
  EXPECT_EQ(split[0][11].ridge, 11u);
  EXPECT_EQ(split[0][11].t1, far.t);
  EXPECT_EQ(split[0][12].ridge, 35u);
  EXPECT_EQ(split[0][12].t0, near.t);
  ASSERT_EQ(split[1].size(), 25u);
  EXPECT_EQ(split[1].front().ridge, 11u);
  EXPECT_EQ(split[1].front().t0, far.t);
  EXPECT_EQ(split[1].back().ridge, 35u);
  EXPECT_EQ(split[1].back().t1, near.t);
  // Each goes once around the light's axis; the coil went twice.
  for (const SimpleLoop& loop : split) {
    EXPECT_NEAR(std::abs(turns_about_axis(c.local, c.ridges, loop)), 1, 1e-9);
  }
}

// Sec. 2.1: only VREs' projections make VREPIPs.
TEST(Vrepips, AnHreCrossingIsNoVrepip) {
  Loop c = coil(48);
  c.ridges[35].hidden_ridge = true;
  EXPECT_TRUE(find_vrepips(c.local, c.ridges, c.loops, true).at.empty());
}

// Fig. 15: three VREs through one point (at depths 1, 2, 3 along a light on +Z), joined by
// three petals. At the point the halves alternate in and out, and each incoming VRE leaves on
// the one closest clockwise (Sec. 2.4): the loop comes apart into its three petals.
TEST(Vrepips, ThreeVrepipsAtOnePointSplitIntoThreeLoops) {
  auto dir = [](double degrees, double depth) {
    return Vec3{std::cos(degrees * kPi / 180), std::sin(degrees * kPi / 180), depth};
  };
  const Loop trefoil({dir(180, 1), dir(0, 1), dir(300, 2), dir(120, 2), dir(60, 3), dir(240, 3)});
  const Vrepips v = find_vrepips(trefoil.local, trefoil.ridges, trefoil.loops, false);
  ASSERT_EQ(v.at.size(), 1u);
  ASSERT_EQ(v.at[0].vrepips.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const Vrepip& p = v.points[v.at[0].vrepips[std::size_t(i)]];
    EXPECT_EQ(p.ridge, std::uint32_t(2 * i));  // nearest first
    EXPECT_NEAR(p.t, 0.5, 1e-12);
    EXPECT_DOUBLE_EQ(p.depth, i + 1);
  }
  const std::vector<SimpleLoop> split =
      split_at_vrepips(trefoil.local, trefoil.ridges, trefoil.loops, v, false);
  ASSERT_EQ(split.size(), 3u);
  expect_each_ridge_once(trefoil.loops, split);
  EXPECT_EQ(crossings_left(trefoil.local, trefoil.ridges, split, false), 0);
  // Arriving on edge 0, leave on edge 4; on 4, leave on 2; on 2, leave on 0.
  const std::vector<std::vector<std::uint32_t>> petals = {{0, 4, 5}, {0, 1, 2}, {2, 3, 4}};
  for (std::size_t i = 0; i < 3; ++i) {
    std::vector<std::uint32_t> ridges;
    for (const LoopPiece& p : split[i]) ridges.push_back(p.ridge);
    EXPECT_EQ(ridges, petals[i]);
  }
}

// Degenerate cases: a convex loop, a vertex touching another edge's projection, and edges
// overlapping along one line (at different depths) make no VREPIP; the split is the loop.
TEST(Vrepips, TouchingAndCollinearProjectionsAreNoVrepips) {
  const std::vector<std::vector<Vec3>> shapes = {
      {{0, 0, 1}, {4, 0, 1}, {4, 2, 1}, {0, 2, 1}},
      {{0, 0, 1}, {4, 0, 1}, {4, 2, 1}, {2, 0, 2}, {0, 2, 1}},
      {{0, 0, 1}, {4, 0, 1}, {4, 1, 1}, {3, 0, 2}, {1, 0, 2}, {0, 1, 1}},
  };
  for (const std::vector<Vec3>& shape : shapes) {
    const Loop loop(shape);
    const Vrepips v = find_vrepips(loop.local, loop.ridges, loop.loops, false);
    EXPECT_TRUE(v.at.empty());
    EXPECT_TRUE(v.points.empty());
    const std::vector<SimpleLoop> split =
        split_at_vrepips(loop.local, loop.ridges, loop.loops, v, false);
    ASSERT_EQ(split.size(), 1u);
    ASSERT_EQ(split[0].size(), shape.size());
    for (std::uint32_t i = 0; i < shape.size(); ++i) {
      EXPECT_EQ(split[0][i].ridge, i);
      EXPECT_EQ(split[0][i].t0, 0);
      EXPECT_EQ(split[0][i].t1, 1);
    }
  }
}

// Object 0 of a scene under light 0: its RE loops in the light's frame.
struct SceneLoops {
  Scene scene;
  LightFrame frame;
  FarSheets sheets;
  LoopsInFrame loops;
  Vrepips v;
  std::vector<SimpleLoop> split;

  explicit SceneLoops(Scene s)
      : scene(std::move(s)),
        frame(scene.lights[0], scene.camera, scene.bounds().center()),
        sheets(occluding_sheets(scene, scene.lights[0])[0]),
        loops(scene.objects[0].mesh, sheets, frame),
        v(find_vrepips(loops.local, loops.ridges, loops.loops, frame.point_light())),
        split(split_at_vrepips(loops.local, loops.ridges, loops.loops, v, frame.point_light())) {}

  bool all_vres(const SimpleLoop& loop) const {
    return std::ranges::none_of(
        loop, [&](const LoopPiece& p) { return loops.ridges[p.ridge].hidden_ridge; });
  }
  void expect_split() const {
    expect_each_ridge_once(loops.loops, split);
    EXPECT_EQ(crossings_left(loops.local, loops.ridges, split, frame.point_light()), 0);
    for (const PseudoIntersection& at : v.at) {
      ASSERT_EQ(at.vrepips.size(), 2u);
      EXPECT_LT(v.points[at.vrepips[0]].depth, v.points[at.vrepips[1]].depth);
    }
  }
};

// The built-in coil (Figs. 2b / 3): the helical band's loop winds twice as the light sees it.
TEST(Vrepips, TheCoilSceneSplitsAtItsVrepips) {
  const SceneLoops coil(load_scene("coil", {}));
  ASSERT_EQ(coil.loops.loops.size(), 1u);
  EXPECT_EQ(coil.v.at.size(), 2u);  // two crossings of 1.6 turns' outline, near and far each
  EXPECT_EQ(coil.v.points.size(), 4u);
  EXPECT_EQ(coil.split.size(), 3u);
  coil.expect_split();
}

// Fig. 13: the frame with a hole, the light looking through it. The hole's loop has VREPIPs;
// the split gives a loop of VREs only, the outline of what the light sees through.
TEST(Vrepips, AHoleTheLightLooksThroughHasALoopOfVresOnly) {
  Scene scene = load_scene("holed", {});
  // Off the hole's axis, so that the walls nearer the light hide from it (the built-in scene's
  // light is above the hole, which sees all four walls: no VREPIP).
  scene.lights[0] = Light::point({3, 9, 2});
  const SceneLoops holed(std::move(scene));
  ASSERT_EQ(holed.loops.loops.size(), 2u);
  EXPECT_EQ(holed.v.at.size(), 2u);
  holed.expect_split();
  // The outline, unsplit; the hole's loop in three: what the light sees through, of VREs
  // only, its four pieces joined at the two imaginary edges, and two corner loops, each with
  // the HRE of a wall shadowing its neighbour.
  ASSERT_EQ(holed.split.size(), 4u);
  EXPECT_TRUE(holed.all_vres(holed.split[0]));
  EXPECT_EQ(holed.split[0].size(), 6u);
  int through = 0, corners = 0;
  for (std::size_t i = 1; i < 4; ++i) {
    const SimpleLoop& loop = holed.split[i];
    if (!holed.all_vres(loop)) {
      corners += loop.size() == 3;
      continue;
    }
    ++through;
    EXPECT_EQ(loop.size(), 4u);
    for (const LoopPiece& p : loop) EXPECT_TRUE(p.t0 > 0 || p.t1 < 1);
  }
  EXPECT_EQ(through, 1);
  EXPECT_EQ(corners, 2);
}

// Fig. 14: the same frame under a light so low that it does not look through the hole: no
// VREPIP, and no loop of the hole of VREs only.
TEST(Vrepips, AHoleTheLightDoesNotLookThroughHasNoVrepip) {
  Scene scene = load_scene("holed", {});
  scene.lights[0] = Light::point({9, 2.5, 0.5});
  const SceneLoops holed(std::move(scene));
  ASSERT_EQ(holed.loops.loops.size(), 2u);
  EXPECT_TRUE(holed.v.at.empty());
  holed.expect_split();
  EXPECT_EQ(holed.split.size(), 2u);
  EXPECT_EQ(
      std::ranges::count_if(holed.split, [&](const SimpleLoop& l) { return holed.all_vres(l); }),
      1);
}

}  // namespace
}  // namespace shadowkit::angular
