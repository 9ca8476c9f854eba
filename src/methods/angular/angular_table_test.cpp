#include "angular_table.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <tuple>

#include "angular_lookup.h"
#include "angular_method.h"
#include "loop_slicer.h"
#include "loops_in_frame_testing.h"
#include "occluders.h"
#include "scan_line_run.h"
#include "shadowkit/methods/raytrace.h"
#include "shadowkit/scene/scene_file.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"

namespace shadowkit::angular {
namespace {

// A camera at the origin looking down -z: the light frame's axes are the world's axes with
// F = -z.
Camera straight_camera() {
  return testing::camera({0, 0, 0}, {0, 0, -1}, 64, 48);
}

TEST(LightFrame, AnglesFollowEquationsOneToThree) {
  const LightFrame frame(Light::point({1, 2, 3}), straight_camera(), {});
  const AngularPoint ahead = frame.angular({1, 2, 1});
  EXPECT_DOUBLE_EQ(ahead.r, 2);
  EXPECT_DOUBLE_EQ(ahead.theta, 0);
  EXPECT_DOUBLE_EQ(ahead.phi, 0);
  const AngularPoint p = frame.angular({1 + 1, 2 + 1, 3 - 1});  // X = Y = 1, F = 1
  EXPECT_NEAR(p.theta, std::atan(1.0), 1e-15);                  // eq. 2
  EXPECT_NEAR(p.phi, 1 / std::sqrt(2.0), 1e-15);  // tan(phi) within the theta half-plane
  // A line along the camera's right axis keeps theta (Sec. 3, Fig. 19).
  for (double x : {-5.0, 0.0, 7.0}) EXPECT_NEAR(frame.angular({x, 3, 2}).theta, p.theta, 1e-15);
  // Behind the light (F < 0) theta continues past pi/2: the second hemisphere of Sec. 11.2.
  EXPECT_GT(frame.angular({1, 3, 5}).theta, std::numbers::pi / 2);
}

// The sign of the frame's orientation: -1 for a left-handed one.
double handedness(const LightFrame& frame) {
  const Vec3 x = frame.local_direction({1, 0, 0}), y = frame.local_direction({0, 1, 0});
  return dot(cross(x, y), frame.local_direction({0, 0, 1}));
}

// A directional light's theta-planes hold its rays and the camera's right axis (Sec. 3: lines
// along it keep theta). Along that axis, and along -right, the light lies in every plane
// holding the axis: its theta-planes also hold the forward axis, and up crosses them.
TEST(LightFrame, ADirectionalLightsThetaPlanesHoldItsRays) {
  const LightFrame frame(Light::directional({0, -1, -1}), straight_camera(), {});
  EXPECT_NEAR(frame.angular({5, 1, 1}).theta, frame.angular({-3, 1, 1}).theta, 1e-15);
  EXPECT_NEAR(frame.angular({0, 0, 0}).theta, frame.angular(Vec3{0, -1, -1} * 4.0).theta, 1e-15);
  EXPECT_NEAR(handedness(frame), -1, 1e-15);  // as the point light's (right, up, forward)
  const Vec3 p{0.3, -0.7, 2};
  for (const Vec3 d : {Vec3{1, 0, 0}, Vec3{-1, 0, 0}}) {
    const LightFrame along(Light::directional(d), straight_camera(), {});
    const AngularPoint a = along.angular(p);
    EXPECT_NEAR(along.angular(p + d * 5.0).theta, a.theta, 1e-15);
    EXPECT_NEAR(along.angular(p + d * 5.0).r, a.r + 5, 1e-14);
    EXPECT_NEAR(along.angular(p + Vec3{0, 0, -3}).theta, a.theta, 1e-15);  // forward
    EXPECT_NEAR(std::abs(along.angular(p + Vec3{0, 1, 0}).theta - a.theta), 1, 1e-15);
    EXPECT_NEAR(handedness(along), -1, 1e-15);
  }
  // Within a tiny angle of the axis the theta-planes hold both again.
  const Vec3 near = normalize(Vec3{1, 1e-7, 0});
  const LightFrame beside(Light::directional(near), straight_camera(), {});
  EXPECT_NEAR(beside.angular(p + near * 5.0).theta, beside.angular(p).theta, 1e-14);
  EXPECT_NEAR(beside.angular(p + Vec3{7, 0, 0}).theta, beside.angular(p).theta, 1e-14);
}

// A square frame (a closed solid with a hole, Figs. 13 and 25) over the ground: the light
// looks through the hole, so the ground under it is lit and under the frame shadowed.
PolygonSoup square_frame(double inner, double outer, double y0, double y1) {
  PolygonSoup s;
  const double c[4] = {-outer, -inner, inner, outer};
  for (int layer = 0; layer < 2; ++layer) {
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) s.positions.push_back({c[i], layer ? y1 : y0, c[j]});
    }
  }
  const auto at = [](int layer, int i, int j) { return std::uint32_t(layer * 16 + j * 4 + i); };
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      if (i == 1 && j == 1) continue;  // the hole
      s.add_face({at(1, i, j + 1), at(1, i + 1, j + 1), at(1, i + 1, j), at(1, i, j)});
      s.add_face({at(0, i, j), at(0, i + 1, j), at(0, i + 1, j + 1), at(0, i, j + 1)});
    }
  }
  // Walls along the outer and inner rings, each a quad between consecutive ring vertices.
  const int outer_ring[12][2] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2},
                                 {3, 3}, {2, 3}, {1, 3}, {0, 3}, {0, 2}, {0, 1}};
  for (int k = 0; k < 12; ++k) {
    const auto* a = outer_ring[k];
    const auto* b = outer_ring[(k + 1) % 12];
    s.add_face({at(0, b[0], b[1]), at(0, a[0], a[1]), at(1, a[0], a[1]), at(1, b[0], b[1])});
  }
  const int inner_ring[4][2] = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
  for (int k = 0; k < 4; ++k) {
    const auto* a = inner_ring[k];
    const auto* b = inner_ring[(k + 1) % 4];
    s.add_face({at(0, a[0], a[1]), at(0, b[0], b[1]), at(1, b[0], b[1]), at(1, a[0], a[1])});
  }
  return s;
}

// The table of light 0 of \p scene at resolution \p r.
AngularTable table_of(const Scene& scene, int r) {
  const LightFrame frame(scene.lights[0], scene.camera, {});
  return AngularTable::build(scene, frame, occluding_sheets(scene, scene.lights[0]), {r, false});
}

// The entry whose slice holds world point \p p.
int entry_at(const Scene& scene, const AngularTable& table, Vec3 p) {
  const LightFrame frame(scene.lights[0], scene.camera, {});
  const ThetaQuantization& q = table.theta();
  return q.entry(q.index(frame.angular(p).theta));
}

// tan(phi) of world point \p p (the point light's phi as pairs keep it).
double phi_at(const Scene& scene, Vec3 p) {
  return LightFrame(scene.lights[0], scene.camera, {}).angular(p).phi;
}

std::uint32_t face_of(const AngularTable& table, const AngularPair& pair) {
  return table.hidden(pair.hidden).face;
}

// Straight down the light's -Y axis at the slices: a camera looking along -z at the origin,
// so that phi = x / |y - 4| for a point light at (0, 4, 0).
Camera front_camera() {
  return testing::camera({0, 0, 20}, {0, 0, 0}, 64, 48);
}

// Figs. 3 / 4(a) / 23: a strip folded into a Z (an open mesh: a two-sided thin solid) whose
// upper and lower parts overlap as seen from the light. Its one RE loop is coiled; each
// crossing is paired along the far sheet, so the two overlapping spans stay apart (pairing
// the upper span's begin with the lower span's begin would make a hole between them).
TEST(Pairing, ACoiledLoopKeepsOverlappingSpansApart) {
  PolygonSoup z = testing::polygon({{-1, 2, 1}, {1, 2, 1}, {1, 2, -1}, {-1, 2, -1}});
  z.append(testing::polygon({{1, 2, 1}, {1, 1, 1}, {1, 1, -1}, {1, 2, -1}}));
  z.append(testing::polygon({{1, 1, 1}, {-0.5, 1, 1}, {-0.5, 1, -1}, {1, 1, -1}}));
  const Scene scene = testing::make_scene(front_camera(), {Light::point({0, 4, 0})}, {z});
  const AngularTable table = table_of(scene, 64);
  const auto pairs = table.entry(entry_at(scene, table, {0, 1.5, 0}));
  ASSERT_EQ(pairs.size(), 3u);  // upper part, fold, lower part: one hidden face each
  std::map<std::uint32_t, AngularPair> by_face;
  for (const AngularPair& p : pairs) by_face[face_of(table, p)] = p;
  ASSERT_EQ(by_face.size(), 3u);
  const AngularPair upper = by_face[0], fold = by_face[1], lower = by_face[2];
  // The slice is the entry's centre, near (not at) the plane z = 0.
  EXPECT_NEAR(upper.phi_begin, phi_at(scene, {-1, 2, 0}), 1e-4);
  EXPECT_NEAR(upper.phi_end, phi_at(scene, {1, 2, 0}), 1e-4);
  EXPECT_NEAR(lower.phi_begin, phi_at(scene, {-0.5, 1, 0}), 1e-4);
  EXPECT_NEAR(lower.phi_end, phi_at(scene, {1, 1, 0}), 1e-4);
  // The fold's far sheet (its outside) joins the lower part's underside: its pair starts
  // where the lower one ends (the hidden edge inserted in duplicate) and reaches the upper
  // part's end.
  EXPECT_EQ(fold.phi_begin, lower.phi_end);
  EXPECT_NEAR(fold.phi_end, upper.phi_end, 1e-4);
  EXPECT_LT(upper.phi_begin, lower.phi_begin);  // overlapping spans of one loop
}

// Figs. 13 / 25: a square frame, a closed solid with a hole, lit from above: the slice
// through the hole crosses the outer and the hole's RE loops; the direction constraint makes
// shadow begin at the outer loop and end at the hole's, so no pair holds the hole.
TEST(Pairing, AHoleEndsTheSpanAtItsOwnLoop) {
  const Scene scene =
      testing::make_scene(front_camera(), {Light::point({0, 4, 0})}, {square_frame(1, 2, 1.5, 2)});
  const AngularTable table = table_of(scene, 64);
  EXPECT_EQ(table.loop_stats().loops, 2);
  const auto pairs = table.entry(entry_at(scene, table, {0, 1.5, 0}));
  ASSERT_FALSE(pairs.empty());
  for (const AngularPair& p : pairs) {
    EXPECT_TRUE(p.phi_end <= phi_at(scene, {-1, 1.5, 0}) + 1e-4 ||
                p.phi_begin >= phi_at(scene, {1, 1.5, 0}) - 1e-4)
        << p.phi_begin << " " << p.phi_end;
  }
  // The hidden outer walls and bottoms: from the top of each outer wall to the hole's rim.
  double covered = 0;
  for (const AngularPair& p : pairs) covered += p.phi_end - p.phi_begin;
  EXPECT_NEAR(covered, 2 * (phi_at(scene, {2, 2, 0}) - phi_at(scene, {1, 1.5, 0})), 1e-3);
}

// Figs. 26 / 27: a U-shaped solid (a hole-like notch between two arms, whose tops are equal
// adjacent peaks of its RE loop) lit from straight above: the slice through the notch gives
// one span whose depth is the far sheet (outer walls and bottom, exact faces), so the notch
// floor in front of it stays lit while the ground beyond it is shadowed.
TEST(Pairing, AHoleLikeNotchIsOneSpanWithTheFarSheetsDepth) {
  const std::vector<Vec3> u = {{-2, 0, 0},  {2, 0, 0},    {2, 2, 0},  {1, 2, 0},
                               {1, 0.5, 0}, {-1, 0.5, 0}, {-1, 2, 0}, {-2, 2, 0}};
  const Scene scene = testing::make_scene(front_camera(), {Light::point({0, 6, 0})}, {prism(u)});
  ASSERT_TRUE(scene.objects[0].mesh.closed());
  ASSERT_TRUE(scene.objects[0].mesh.consistently_oriented());
  const AngularTable table = table_of(scene, 64);
  std::vector<AngularPair> pairs;
  for (const AngularPair& p : table.entry(entry_at(scene, table, {0, 1, 0}))) pairs.push_back(p);
  std::sort(pairs.begin(), pairs.end(),
            [](const AngularPair& a, const AngularPair& b) { return a.phi_begin < b.phi_begin; });
  ASSERT_EQ(pairs.size(), 3u);  // left outer wall, bottom, right outer wall
  EXPECT_NEAR(pairs[0].phi_begin, phi_at(scene, {-2, 2, 0}), 1e-4);
  EXPECT_EQ(pairs[1].phi_begin, pairs[0].phi_end);
  EXPECT_EQ(pairs[2].phi_begin, pairs[1].phi_end);
  EXPECT_NEAR(pairs[2].phi_end, phi_at(scene, {2, 2, 0}), 1e-4);
  const HiddenFace& bottom = table.hidden(pairs[1].hidden);
  const LightFrame frame(scene.lights[0], scene.camera, {});
  EXPECT_FALSE(bottom.behind(frame.local({0, 0.5, 0}), 1e-9));  // the notch floor
  EXPECT_TRUE(bottom.behind(frame.local({0, -1, 0}), 1e-9));    // the ground under it
}

// Fig. 27: the U-shaped solid under a directional light tilted towards -z, sliced exactly at
// the height of its arms' top back edges. Each edge joins two equal adjacent peaks of the RE
// loop and lies in the slice (exactly: a directional slice is Y = theta, and both ends have
// the same Y). As in the papers, the edge between the peaks crosses nothing and the peaks
// pair with each other: one pair per arm, from its left peak to its right one, on the hidden
// back face; the notch between the arms holds nothing.
TEST(Pairing, EqualAdjacentPeaksPairWithEachOther) {
  const std::vector<Vec3> u = {{-2, 0, 0},  {2, 0, 0},    {2, 2, 0},  {1, 2, 0},
                               {1, 0.5, 0}, {-1, 0.5, 0}, {-1, 2, 0}, {-2, 2, 0}};
  const Light light = Light::directional(normalize(Vec3{0, -1, -0.5}));
  const Scene scene = testing::make_scene(front_camera(), {light}, {prism(u)});
  const Mesh& mesh = scene.objects[0].mesh;
  const LightFrame frame(light, scene.camera, {});
  const FarSheets sheets = far_sheets(mesh, light, true);
  std::vector<Vec3> local;
  std::vector<double> theta;
  for (const Vec3& v : mesh.vertices)
    local.push_back(frame.local(v)), theta.push_back(local.back().y);
  std::vector<std::uint32_t> hidden_id(mesh.face_count());
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f) hidden_id[f] = f;
  const std::vector<RidgeEdge> ridges = find_ridge_edges(mesh, sheets);
  const std::vector<RidgeEdgeLoop> loops = chain_ridge_edge_loops(ridges);
  ASSERT_EQ(loops.size(), 1u);

  const double peak_theta = frame.local({-2, 2, -1}).y;
  const ThetaSlice peak = ThetaSlice::at(peak_theta, false);
  ASSERT_EQ(frame.local({-1, 2, -1}).y, peak_theta);  // equal adjacent peaks, exactly
  ASSERT_EQ(frame.local({1, 2, -1}).y, peak_theta);
  const ThetaQuantization one_entry{-1e3, 2e3, 1, false};
  const SlicedMesh sliced{mesh, sheets, local, theta, hidden_id};
  SliceScratch scratch;
  std::vector<EntryPair> out;
  slice_loop(sliced, ridges, loops[0], one_entry, {&peak, 1}, scratch, out);

  ASSERT_EQ(out.size(), 2u);
  std::sort(out.begin(), out.end(),
            [](const EntryPair& a, const EntryPair& b) { return a.phi_begin < b.phi_begin; });
  const double phi[4] = {frame.local({-2, 2, -1}).x, frame.local({-1, 2, -1}).x,
                         frame.local({1, 2, -1}).x, frame.local({2, 2, -1}).x};
  EXPECT_DOUBLE_EQ(out[0].phi_begin, phi[0]);
  EXPECT_DOUBLE_EQ(out[0].phi_end, phi[1]);
  EXPECT_DOUBLE_EQ(out[1].phi_begin, phi[2]);
  EXPECT_DOUBLE_EQ(out[1].phi_end, phi[3]);
  for (const EntryPair& p : out) {
    EXPECT_NEAR(mesh.planes[p.hidden].normal.z, -1, 1e-12);  // the back face
  }
}

// Sec. 5: with hidden edges inserted in duplicate, a cube lit from a corner gives, in the
// slice through its far corner, one pair per hidden face crossed, meeting exactly at the
// hidden edges: the depth inside the span is the hidden faces' own.
TEST(Pairing, HiddenEdgesSplitASpanIntoExactFaces) {
  const Scene scene = testing::make_scene(front_camera(), {Light::point({3, 4, 5})},
                                          {testing::box({-1, -1, -1}, {1, 1, 1})});
  const AngularTable table = table_of(scene, 256);
  const auto pairs = table.entry(entry_at(scene, table, {-1, -1, -1}));
  ASSERT_GE(pairs.size(), 2u);
  std::vector<AngularPair> sorted(pairs.begin(), pairs.end());
  std::sort(sorted.begin(), sorted.end(),
            [](const AngularPair& a, const AngularPair& b) { return a.phi_begin < b.phi_begin; });
  for (std::size_t i = 1; i < sorted.size(); ++i) {
    EXPECT_EQ(sorted[i].phi_begin, sorted[i - 1].phi_end);  // bit-identical: no crack
    EXPECT_NE(face_of(table, sorted[i]), face_of(table, sorted[i - 1]));
  }
  for (const AngularPair& p : sorted) {
    EXPECT_LT(scene.face_plane(face_of(table, p)).distance({3, 4, 5}), 0);  // hidden
  }
}

TEST(AngularTable, AHoleLetsTheLightThroughAndDepthIsExactInsideSpans) {
  const Scene scene = testing::make_scene(
      testing::camera({0, 10, 1}, {0, 0, 0}, 160, 120), {Light::point({0.2, 6, 0.1})},
      {testing::horizontal_quad(-8, 8, -8, 8, 0), square_frame(1, 2, 1.5, 2)});
  ASSERT_TRUE(scene.objects[1].mesh.closed());
  ASSERT_TRUE(scene.objects[1].mesh.consistently_oriented());
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  AngularMethod angular({});
  const auto reference = raytrace::make_method({});
  const ShadowMask mask = testing::method_mask(angular, scene, vsb, 0);
  const MaskComparison c =
      compare_masks(testing::method_mask(*reference, scene, vsb, 0), mask, vsb.object_ids());
  EXPECT_EQ(c.interior_mismatched, 0u);
  int hole = 0, under_frame = 0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (!vsb.covered(i) || vsb.object(i) != 0) continue;
    const Vec3 p = vsb.point(i);
    if (std::max(std::abs(p.x), std::abs(p.z)) < 0.5)
      hole += mask.pixels[i] == kMaskLit ? 1 : -1000;
    const double ring = std::max(std::abs(p.x - 0.1 / 3), std::abs(p.z));
    if (ring > 2.0 && ring < 2.3) under_frame += mask.pixels[i] == kMaskShadow ? 1 : -1000;
  }
  EXPECT_GT(hole, 20);
  EXPECT_GT(under_frame, 20);
  EXPECT_GT(testing::counter(angular, "re_loops"), 1);  // outer and hole loops
}

// The hidden-face index of global face \p face: the first pair cut from it.
std::uint32_t hidden_of(const AngularTable& table, std::uint32_t face) {
  for (int k = 0; k < table.theta().resolution; ++k) {
    for (const AngularPair& p : table.entry(k)) {
      if (table.hidden(p.hidden).face == face) return p.hidden;
    }
  }
  ADD_FAILURE() << "no pair of face " << face;
  return 0;
}

// The exact test of a grazed query (angular_lookup.h): an L-shaped face, one non-convex
// hexagon at height 1, blocks the ground under its arms, not under its notch, and nothing
// above it; for a point light (rays spreading from above one arm) and a directional one.
TEST(AngularTable, AFaceBlocksExactlyThePointsBehindItsOwnOutline) {
  PolygonSoup l_shape;
  l_shape.positions = {{0, 1, 0}, {2, 1, 0}, {2, 1, 1}, {1, 1, 1}, {1, 1, 2}, {0, 1, 2}};
  l_shape.add_face({0, 1, 2, 3, 4, 5});
  struct Case {
    Light light;
    Vec3 under_arm, under_notch;
  };
  const Case cases[] = {
      {Light::point({0.5, 5, 0.5}),
       {1.5, 0, 0.5},
       {1.5, 0, 1.5}},  // meet y = 1 at (1.3, 0.5), (1.3, 1.3)
      {Light::directional(normalize(Vec3{0.1, -1, 0.1})), {1.6, 0, 0.6}, {1.6, 0, 1.6}}};
  for (const Case& c : cases) {
    const Scene scene =
        testing::make_scene(testing::camera({1, 6, 6}, {1, 0, 1}, 160, 120), {c.light},
                            {testing::horizontal_quad(-8, 8, -8, 8, 0), l_shape});
    const LightFrame frame(c.light, scene.camera, scene.bounds().center());
    const AngularTable table =
        AngularTable::build(scene, frame, occluding_sheets(scene, c.light), {});
    const std::uint32_t l_face = hidden_of(table, 1);
    const bool point = c.light.type == Light::Type::point;
    const double tolerance = 1e-9;
    EXPECT_TRUE(table.blocks(l_face, frame.local(c.under_arm), point, tolerance));
    EXPECT_FALSE(table.blocks(l_face, frame.local(c.under_notch), point, tolerance));
    EXPECT_FALSE(
        table.blocks(l_face, frame.local(c.under_arm + Vec3{0, 1.5, 0}), point, tolerance));
    EXPECT_FALSE(table.blocks(l_face, frame.local({3, 0, 0.5}), point, tolerance));  // beside
  }
}

// The exact shadow of one face along a scan line (angular_lookup.h), for the L-shaped face
// above: from a point within it, every point up to the end is blocked by the face, and just
// past a finite end the run is out of it (passed the face's plane or a plane swept through a
// side, the kernel's boundary for the non-convex L); no end from a point it does not block.
TEST(AngularLookup, ARunStaysInTheExactShadowOfOneFaceUpToItsEnd) {
  PolygonSoup l_shape;
  l_shape.positions = {{0, 1, 0}, {2, 1, 0}, {2, 1, 1}, {1, 1, 1}, {1, 1, 2}, {0, 1, 2}};
  l_shape.add_face({0, 1, 2, 3, 4, 5});
  for (const Light& light :
       {Light::point({0.5, 5, 0.5}), Light::directional(normalize(Vec3{0.1, -1, 0.1}))}) {
    const Scene scene =
        testing::make_scene(testing::camera({1, 6, 6}, {1, 0, 1}, 160, 120), {light},
                            {testing::horizontal_quad(-8, 8, -8, 8, 0), l_shape});
    const LightFrame frame(light, scene.camera, scene.bounds().center());
    const AngularTable table =
        AngularTable::build(scene, frame, occluding_sheets(scene, light), {});
    const std::uint32_t l_face = hidden_of(table, 1);
    const bool point = light.type == Light::Type::point;
    LookupQuery query;
    query.depth_tolerance = 1e-9;
    std::size_t blocked = 0, ends = 0;
    for (int row = 0; row < 120; row += 3) {
      const ScanLineRun run(frame, scene.camera, {{0, 1, 0}, 0}, row);
      for (int c = 0; c < 160; ++c) {
        query.local = run.local(c);
        query.column = c;
        const std::optional<double> end = exact_shadow_end(table, frame, run, query, l_face);
        if (!table.blocks(l_face, query.local, point, 1e-9)) {
          EXPECT_FALSE(end) << row << " " << c;
          continue;
        }
        ++blocked;
        if (!end) continue;  // outside the kernel
        ++ends;
        ASSERT_GT(*end, c);
        const double last = std::min(*end, 1000.0);
        for (const double t : {0.25, 0.5, 0.75, 0.999}) {
          EXPECT_TRUE(table.blocks(l_face, run.local(c + t * (last - c)), point, 1e-9));
        }
        if (*end > 1000) continue;
        query.local = run.local(*end + 0.01);
        query.column = *end + 0.01;
        EXPECT_FALSE(exact_shadow_end(table, frame, run, query, l_face)) << row << " " << c;
      }
    }
    EXPECT_GT(ends, 50u);
    EXPECT_GT(blocked, ends);  // under the arms, outside the kernel
  }
}

// A gently curved sheet of n x n cells, two triangles each, over [0, 2]^2 about height 1.
PolygonSoup bumpy_sheet(int n) {
  PolygonSoup sheet;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double x = 2.0 * i / n, z = 2.0 * j / n;
      sheet.positions.push_back({x, 1 + 0.1 * std::sin(3 * x) * std::cos(2 * z), z});
    }
  }
  const auto v = [n](int i, int j) { return std::uint32_t(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      sheet.add_face({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
      sheet.add_face({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
    }
  }
  return sheet;
}

// The far sheet of an open, curved grid above a ground: every inner edge joins the two faces
// it bounds both ways (AngularTable::across) and the border bounds the sheet. From any of its
// faces, the walk across its hidden edges reaches the one face that blocks a point of the
// ground under it; from the ground beside it, and from above it, it finds none.
TEST(AngularLookup, AWalkOnTheFarSheetFindsTheFaceThatBlocksThePoint) {
  constexpr int kCells = 3;
  for (const Light& light :
       {Light::point({1.2, 5, 0.8}), Light::directional(normalize(Vec3{0.15, -1, 0.1}))}) {
    const Scene scene =
        testing::make_scene(testing::camera({1, 6, 6}, {1, 0, 1}, 160, 120), {light},
                            {testing::horizontal_quad(-8, 8, -8, 8, 0), bumpy_sheet(kCells)});
    const LightFrame frame(light, scene.camera, scene.bounds().center());
    const AngularTable table =
        AngularTable::build(scene, frame, occluding_sheets(scene, light), {});
    std::vector<std::uint32_t> sheet;  // the grid's occluding faces, by hidden id
    for (std::uint32_t i = 0; i < table.hidden_count(); ++i) {
      if (table.hidden(i).face >= 1) sheet.push_back(i);
    }
    ASSERT_EQ(sheet.size(), std::size_t(2 * kCells * kCells));
    std::size_t border = 0;
    for (const std::uint32_t i : sheet) {
      for (const std::uint32_t next : table.across(i)) {
        if (next == kNoFace) {
          ++border;
          continue;
        }
        EXPECT_TRUE(std::ranges::count(table.across(next), i) == 1) << i << " " << next;
      }
    }
    EXPECT_EQ(border, std::size_t(4 * kCells));
    const bool point = light.type == Light::Type::point;
    LookupQuery query;
    query.depth_tolerance = 1e-9;
    std::size_t found = 0, beside = 0;
    for (double x = -0.43; x < 2.6; x += 0.13) {
      for (double z = -0.41; z < 2.6; z += 0.11) {
        query.local = frame.local({x, 0, z});
        std::vector<std::uint32_t> blocking;
        for (const std::uint32_t i : sheet) {
          if (table.blocks(i, query.local, point, query.depth_tolerance)) blocking.push_back(i);
        }
        ASSERT_LE(blocking.size(), 1u) << x << " " << z;
        for (const std::uint32_t start : {sheet.front(), sheet[sheet.size() / 2], sheet.back()}) {
          const std::optional<std::uint32_t> face = blocker_on_sheet(table, frame, query, start);
          EXPECT_EQ(face, blocking.empty() ? std::nullopt : std::optional(blocking[0]))
              << x << " " << z << " from " << start;
        }
        (blocking.empty() ? beside : found)++;
        query.local = frame.local({x, 1.5, z});  // above the sheet
        EXPECT_FALSE(blocker_on_sheet(table, frame, query, sheet.front())) << x << " " << z;
      }
    }
    EXPECT_GT(found, 150u);
    EXPECT_GT(beside, 150u);
  }
}

// \p b has the same entries as \p a, pair for pair and bit for bit.
void expect_same_table(const AngularTable& a, const AngularTable& b) {
  EXPECT_EQ(b.pair_count(), a.pair_count());
  EXPECT_EQ(b.saturated_count(), a.saturated_count());
  ASSERT_EQ(b.theta().resolution, a.theta().resolution);
  for (int k = 0; k < a.theta().resolution; ++k) {
    const auto x = a.entry(k), y = b.entry(k);
    ASSERT_EQ(x.size(), y.size()) << "entry " << k;
    ASSERT_EQ(a.wide(k).size(), b.wide(k).size()) << "entry " << k;
    for (std::size_t i = 0; i < x.size(); ++i) {
      EXPECT_EQ(x[i].phi_begin, y[i].phi_begin);
      EXPECT_EQ(x[i].phi_end, y[i].phi_end);
      EXPECT_EQ(x[i].reach, y[i].reach);
      EXPECT_EQ(x[i].hidden, y[i].hidden);
    }
  }
}

// The loops are sliced in fixed chunks whose lists are scattered in chunk order, so every
// entry gets its pairs in the same order, and the same table, however many threads slice.
TEST(AngularTable, TheTableDoesNotDependOnTheNumberOfThreads) {
  const Scene scene = load_scene("cubes:300", {});  // 301 loops, 19 per chunk
  const LightFrame frame(scene.lights[0], scene.camera, scene.bounds().center());
  const auto build = [&](int threads) {
    return tbb::task_arena(threads).execute([&] {
      return AngularTable::build(scene, frame, occluding_sheets(scene, scene.lights[0]), {});
    });
  };
  const AngularTable one = build(1), two = build(2);
  ASSERT_GT(one.pair_count(), 10000u);
  EXPECT_GT(one.saturated_count(), 1000u);
  expect_same_table(one, two);
  for (int k = 0; k < one.theta().resolution; ++k) {
    // Step 1.7: the narrow pairs sorted by phi_begin, each reach the running maximum end.
    const auto narrow = one.narrow(k);
    for (std::size_t i = 1; i < narrow.size(); ++i) {
      EXPECT_LE(narrow[i - 1].phi_begin, narrow[i].phi_begin);
      EXPECT_EQ(narrow[i].reach, std::max(narrow[i - 1].reach, narrow[i].phi_end));
    }
  }
}

// Saturation only drops pairs: per entry, the saturated table's pairs are the unsaturated
// one's, less as many as it counts.
TEST(AngularTable, SaturationOnlyDropsPairs) {
  const Scene scene = load_scene("cubes:300", {});
  const LightFrame frame(scene.lights[0], scene.camera, scene.bounds().center());
  const auto sheets = occluding_sheets(scene, scene.lights[0]);
  const AngularTable saturated = AngularTable::build(scene, frame, sheets, {0, true});
  const AngularTable all = AngularTable::build(scene, frame, sheets, {0, false});
  ASSERT_EQ(saturated.theta().resolution, all.theta().resolution);
  EXPECT_GT(saturated.saturated_count(), 1000u);
  EXPECT_EQ(all.saturated_count(), 0u);
  EXPECT_EQ(saturated.pair_count() + saturated.saturated_count(), all.pair_count());
  using Key = std::tuple<double, double, std::uint32_t>;
  for (int k = 0; k < all.theta().resolution; ++k) {
    std::vector<Key> kept, every;
    for (const AngularPair& p : saturated.entry(k))
      kept.emplace_back(p.phi_begin, p.phi_end, p.hidden);
    for (const AngularPair& p : all.entry(k)) every.emplace_back(p.phi_begin, p.phi_end, p.hidden);
    std::ranges::sort(kept);
    std::ranges::sort(every);
    EXPECT_TRUE(std::ranges::includes(every, kept)) << "entry " << k;
  }
}

// Every pair of a block's entries lies within its face's one pair of the block, and the
// block holds no other face: a point no block pair shadows is lit in all its entries. Only
// a light inside the scene (the room's) gets blocks.
TEST(AngularTable, ABlockSpansThePairsOfItsEntriesFaceByFace) {
  const auto build = [](const Scene& scene) {
    const LightFrame frame(scene.lights[0], scene.camera, scene.bounds().center());
    return AngularTable::build(scene, frame, occluding_sheets(scene, scene.lights[0]), {});
  };
  EXPECT_TRUE(build(load_scene("cubes:300", {})).blocks().start.empty());
  const AngularTable table = build(load_scene("room", {}));
  const int r = table.theta().resolution;
  ASSERT_GT(r, 3 * kBlockEntries);
  ASSERT_NE(r % kBlockEntries, 0);  // the last block is shorter
  const PairLists& blocks = table.blocks();
  ASSERT_EQ(blocks.start.size(), std::size_t((r + kBlockEntries - 1) / kBlockEntries + 1));
  std::size_t spans = 0;
  for (int b = 0; b + 1 < int(blocks.start.size()); ++b) {
    std::map<std::uint32_t, AngularPair> span;  // per face, the hull of its entries' pairs
    for (int k = b * kBlockEntries; k < std::min(r, (b + 1) * kBlockEntries); ++k) {
      for (const AngularPair& p : table.entry(k)) {
        const auto [it, first] = span.try_emplace(p.hidden, p);
        it->second.phi_begin = std::min(it->second.phi_begin, p.phi_begin);
        it->second.phi_end = std::max(it->second.phi_end, p.phi_end);
      }
    }
    ASSERT_EQ(blocks.list(b).size(), span.size()) << "block " << b;
    for (const AngularPair& p : blocks.list(b)) {
      ASSERT_TRUE(span.count(p.hidden)) << "block " << b;
      EXPECT_EQ(p.phi_begin, span[p.hidden].phi_begin);
      EXPECT_EQ(p.phi_end, span[p.hidden].phi_end);
    }
    const auto narrow = blocks.narrow(b);
    for (std::size_t i = 1; i < narrow.size(); ++i) {
      EXPECT_LE(narrow[i - 1].phi_begin, narrow[i].phi_begin);
      EXPECT_EQ(narrow[i].reach, std::max(narrow[i - 1].reach, narrow[i].phi_end));
    }
    spans += span.size();
  }
  EXPECT_LT(spans, table.pair_count() / 2);  // a face's pairs in several entries become one
  EXPECT_TRUE(blocks.list(-1).empty());
}

// Buffers left by a larger table (longer lists, more pairs) change nothing in the next one.
TEST(AngularTable, BuffersOfAnEarlierBuildLeaveTheTableAsItWas) {
  const auto build = [](const Scene& scene, AngularTableBuffers* buffers) {
    const LightFrame frame(scene.lights[0], scene.camera, scene.bounds().center());
    return AngularTable::build(scene, frame, occluding_sheets(scene, scene.lights[0]), {}, buffers);
  };
  const Scene large = load_scene("cubes:300", {}), small = load_scene("tetra:4", {});
  AngularTableBuffers buffers;
  const AngularTable first = build(large, &buffers);
  EXPECT_EQ(buffers.unsorted.size(), first.pair_count() + first.saturated_count());
  const AngularTable reused = build(small, &buffers), fresh = build(small, nullptr);
  ASSERT_GT(fresh.pair_count(), 100u);
  expect_same_table(fresh, reused);
  expect_same_table(first, build(large, &buffers));
}

}  // namespace
}  // namespace shadowkit::angular
