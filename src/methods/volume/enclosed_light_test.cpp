#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>

#include "shadowkit/scene/mesh_io.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"
#include "volume_method.h"

namespace shadowkit::volume {
namespace {

// A point light inside a closed mesh: the mesh has no contour edges, and its shadow volume
// is all space outside it (Crow Sec. VII: the faces facing the light bound it alone).

const PolygonSoup kGround = testing::horizontal_quad(-10, 10, -10, 10, 0);

// The closed box [-1, 1] x [0.5, 2.5] x [-1, 1], floating over the ground.
PolygonSoup floating_box() {
  return testing::box({-1, 0.5, -1}, {1, 2.5, 1});
}

// The same box without its +x face: the light escapes through the hole.
PolygonSoup box_open_at_plus_x() {
  const PolygonSoup closed = floating_box();
  PolygonSoup open;
  open.positions = closed.positions;
  for (std::size_t f = 0; f < closed.face_count(); ++f) {
    if (f == 1) continue;  // the +x face
    open.add_face({closed.indices.begin() + closed.face_start[f],
                   closed.indices.begin() + closed.face_start[f + 1]});
  }
  return open;
}

// \p soup with every position scaled by \p s and moved by \p offset.
PolygonSoup placed(PolygonSoup soup, double s, Vec3 offset) {
  for (Vec3& p : soup.positions) p = p * s + offset;
  return soup;
}

const Light kLightInBox = testing::point_light({0.1, 1.5, -0.2});
const Camera kOutside = testing::camera({6, 5, 8}, {0, 1, 0}, 160, 120);

// The ground, the closed box and the light in it, everything scaled by \p s.
Scene box_over_ground(const Camera& cam, double s = 1) {
  Camera scaled = cam;
  scaled.position = cam.position * s;
  scaled.look_at = cam.look_at * s;
  return testing::make_scene(scaled, {testing::point_light(kLightInBox.position * s)},
                             {placed(kGround, s, {}), placed(floating_box(), s, {})});
}

struct Mask {
  VisibleSurfaceBuffer vsb;
  ShadowMask mask;
  double contour_edges = 0;
};

Mask volume_mask(const Scene& scene, const MethodOptions& options = {}) {
  Mask m{render_visible_surfaces(scene, {}), {}};
  VolumeMethod method(options);
  m.mask = testing::method_mask(method, scene, m.vsb, 0);
  m.contour_edges = testing::counter(method, "contour_edges");
  return m;
}

// How many ground pixels (object 0) the mask gives \p value, and how many others.
std::pair<int, int> ground_pixels(const Mask& m, std::uint8_t value,
                                  const std::function<bool(Vec3)>& where = {}) {
  int with = 0, without = 0;
  for (std::size_t i = 0; i < m.mask.size(); ++i) {
    if (!m.vsb.covered(i) || m.vsb.object(i) != 0) continue;
    if (where && !where(m.vsb.point(i))) continue;
    (m.mask.pixels[i] == value ? with : without)++;
  }
  return {with, without};
}

TEST(EnclosedLight, ClosedBoxShadowsEverythingOutsideIt) {
  const Scene scene = box_over_ground(kOutside);
  const Mask m = volume_mask(scene);
  EXPECT_EQ(m.contour_edges, 4);  // the ground's rim: the box's faces all turn away
  const auto [shadowed, lit] = ground_pixels(m, kMaskShadow);
  EXPECT_GT(shadowed, 5000);
  EXPECT_EQ(lit, 0);
  EXPECT_LE(testing::worst_interior_mismatch(scene, "volume"), 0.05);
}

TEST(EnclosedLight, ClosedBoxShadowsEverythingOutsideItCountedDepthFail) {
  const Scene scene = box_over_ground(kOutside);
  const MethodOptions fail{"volume", {{"count", "fail"}}};
  EXPECT_EQ(ground_pixels(volume_mask(scene, fail), kMaskShadow).second, 0);
  EXPECT_LE(testing::worst_interior_mismatch(scene, "volume", fail), 0.05);
}

TEST(EnclosedLight, EyeInsideTheBoxWithTheLightSeesEverythingLit) {
  const Scene scene = box_over_ground(testing::camera({0.6, 2.2, 0.7}, {-1, 1, -1}, 160, 120));
  const Mask m = volume_mask(scene);
  // The box's inside fills the view.
  EXPECT_EQ(std::count(m.mask.pixels.begin(), m.mask.pixels.end(), kMaskLit), 160 * 120);
  EXPECT_LE(testing::worst_interior_mismatch(scene, "volume"), 0.05);
}

TEST(EnclosedLight, ClosedBoxShadowsAtTinyAndHugeScales) {
  for (const double s : {1e-3, 1e4}) {
    const Scene scene = box_over_ground(kOutside, s);
    EXPECT_EQ(ground_pixels(volume_mask(scene), kMaskShadow).second, 0) << s;
    EXPECT_LE(testing::worst_interior_mismatch(scene, "volume"), 0.05) << s;
  }
}

TEST(EnclosedLight, ClosedNonConvexPebbleShadowsEverythingOutsideIt) {
  // The pebble (about 0.52 x 0.28 x 0.52, squashed, with dents) scaled by 4 over the ground.
  const PolygonSoup pebble = placed(
      read_mesh_file(std::filesystem::path(SHADOWKIT_SOURCE_DIR) / "examples/models/pebble.obj", {})
          .soup,
      4, {0, 1.5, 0});
  const Scene scene =
      testing::make_scene(kOutside, {testing::point_light({0.05, 1.45, 0.1})}, {kGround, pebble});
  const auto [shadowed, lit] = ground_pixels(volume_mask(scene), kMaskShadow);
  EXPECT_GT(shadowed, 5000);
  EXPECT_EQ(lit, 0);
  EXPECT_LE(testing::worst_interior_mismatch(scene, "volume"), 0.05);
}

// An L-shaped prism, closed: the L [0, 2] x [0, 1] + [0, 1] x [1, 2] in x, z, between heights
// 0.5 and 1.5. Not convex: its inner corner faces lie in the planes x = 1 and z = 1.
PolygonSoup l_prism() {
  PolygonSoup s;
  const double corners[6][2] = {{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}};
  for (const double y : {0.5, 1.5}) {
    for (const auto& c : corners) s.positions.push_back({c[0], y, c[1]});
  }
  s.add_face({0, 5, 4, 3, 2, 1});    // bottom, normal -y
  s.add_face({6, 7, 8, 9, 10, 11});  // top, normal +y
  for (std::uint32_t k = 0; k < 6; ++k) {
    const std::uint32_t next = (k + 1) % 6;
    s.add_face({k, next, next + 6, k + 6});
  }
  return s;
}

TEST(EnclosedLight, LightInsideANonConvexMeshInThePlaneOfAFace) {
  // The light in the plane z = 1 of the inner face from (1, 1) to (2, 1): that face casts
  // nothing, and its neighbours' edges along it become contour edges of weight 1 whose
  // shadow polygons lie in its plane. Everything outside the prism is still in shadow.
  const Scene scene =
      testing::make_scene(kOutside, {testing::point_light({0.5, 1, 1})}, {kGround, l_prism()});
  const Mask m = volume_mask(scene);
  EXPECT_EQ(m.contour_edges, 8);  // the ground's rim and the edges around that face
  const auto [shadowed, lit] = ground_pixels(m, kMaskShadow);
  EXPECT_GT(shadowed, 5000);
  EXPECT_EQ(lit, 0);
  EXPECT_LE(testing::worst_interior_mismatch(scene, "volume"), 0.05);
}

TEST(EnclosedLight, OpenBoxLetsTheLightOutThroughItsHole) {
  // Light at (0, 1.5, 0): rays through the missing +x face (y in [0.5, 2.5], |z| <= 1 at
  // x = 1) reach the ground where x >= 1.5 and |z| <= x.
  const Scene scene =
      testing::make_scene(testing::camera({8, 7, 3}, {0, 0, 0}, 160, 120),
                          {testing::point_light({0, 1.5, 0})}, {kGround, box_open_at_plus_x()});
  const Mask m = volume_mask(scene);
  EXPECT_EQ(m.contour_edges, 8);  // the ground's rim and the hole's
  const auto in_wedge = [](Vec3 p) { return p.x > 1.6 && std::abs(p.z) < p.x - 0.1; };
  const auto [lit, wrong_lit] = ground_pixels(m, kMaskLit, in_wedge);
  EXPECT_GT(lit, 1000);
  EXPECT_EQ(wrong_lit, 0);
  const auto outside = [](Vec3 p) { return p.x < 1.4 || std::abs(p.z) > p.x + 0.1; };
  const auto [shadowed, wrong_shadowed] = ground_pixels(m, kMaskShadow, outside);
  EXPECT_GT(shadowed, 1000);
  EXPECT_EQ(wrong_shadowed, 0);
  EXPECT_LE(testing::worst_interior_mismatch(scene, "volume"), 0.05);
}

}  // namespace
}  // namespace shadowkit::volume
