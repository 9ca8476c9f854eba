#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <string>

#include "contour_edges.h"
#include "eye_count.h"
#include "shadow_polygon.h"
#include "shadowkit/core/error.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"
#include "volume_method.h"

namespace shadowkit::volume {
namespace {

// faces_between_eye_and_light over all of \p mesh's faces.
std::optional<int> mesh_eye_count(const Mesh& mesh, Vec3 eye, const Light& light) {
  std::vector<std::uint32_t> faces(mesh.face_count());
  std::iota(faces.begin(), faces.end(), 0u);
  return faces_between_eye_and_light(mesh, faces, mesh.bounds(), eye, light);
}

// The side polygons' jumps for the open square of square_over_plane seen from \p eye.
std::vector<int> square_jumps(Vec3 eye) {
  const Mesh square = Mesh::build(testing::horizontal_quad(-1, 1, -1, 1, 1), "square", {});
  const Light light = Light::point({0, 4, 0});
  const Reach reach{100, {}};  // no bounding box: polygons unclipped
  std::vector<int> jumps;
  for (const ContourEdge& e : find_contour_edges(square, light)) {
    PolygonCorners corners;
    const auto p = side_polygon(square, e, light, reach, eye, false, corners);
    EXPECT_TRUE(p.has_value());
    jumps.push_back(p->jump);
  }
  std::sort(jumps.begin(), jumps.end());
  return jumps;
}

TEST(Counting, EyeBesideAVolumeSeesTwoFrontAndTwoBackFacingShadowPolygons) {
  EXPECT_EQ(square_jumps({9, 3, 1}), (std::vector<int>{-1, -1, 1, 1}));
}

TEST(Counting, EyeInsideAVolumeSeesOnlyBackFacingShadowPolygons) {
  // Crow: "if the frontmost shadow surface is back-facing, everything before it is in
  // shadow": the eye starts at count 1, and every polygon it looks through takes 1 away.
  const Vec3 eye{0.2, 0.5, -0.3};
  EXPECT_EQ(square_jumps(eye), (std::vector<int>{-1, -1, -1, -1}));
  const Mesh square = Mesh::build(testing::horizontal_quad(-1, 1, -1, 1, 1), "square", {});
  EXPECT_EQ(mesh_eye_count(square, eye, Light::point({0, 4, 0})), 1);
}

TEST(Counting, EyeCountTellsWhenItCannotTell) {
  const Mesh square = Mesh::build(testing::horizontal_quad(-1, 1, -1, 1, 1), "square", {});
  // The way to the light passes through the square's edge.
  EXPECT_FALSE(mesh_eye_count(square, {1, 0, 0}, Light::point({1, 4, 0})));
  EXPECT_EQ(mesh_eye_count(square, {3, 0, 0}, Light::point({0, 4, 0})), 0);
}

TEST(Counting, EyeCountOverALargePartIsCountedInParallelAlike) {
  // Two layers of 130 x 130 quads, 33,800 faces: more than a task's share, so the faces are
  // counted in parallel runs. The way up to the light crosses both layers, or runs along an
  // edge of each, where the count cannot be told.
  PolygonSoup layers;
  for (const double y : {1.0, 2.0}) {
    for (int i = 0; i < 130; ++i) {
      for (int j = 0; j < 130; ++j) {
        layers.append(testing::horizontal_quad(-6.5 + 0.1 * i, -6.4 + 0.1 * i, -6.5 + 0.1 * j,
                                               -6.4 + 0.1 * j, y));
      }
    }
  }
  const Mesh mesh = Mesh::build(layers, "layers", {});
  ASSERT_GT(mesh.face_count(), 30000u);
  EXPECT_EQ(mesh_eye_count(mesh, {0.33, 0, 0.27}, Light::point({0.33, 9, 0.27})), 2);
  EXPECT_EQ(mesh_eye_count(mesh, {0.33, 0, 0.27}, Light::point({0.33, 1.5, 0.27})), 1);
  EXPECT_FALSE(mesh_eye_count(mesh, {-6.5 + 0.1 * 70, 0, 0.27}, Light::point({0.5, 9, 0.27})));
}

Scene square_scene(Vec3 eye, Vec3 look_at) {
  return testing::square_over_plane(testing::camera(eye, look_at, 160, 120),
                                    testing::point_light({0, 4, 0}));
}

double depth_fail_sub_objects(const Scene& scene, const MethodOptions& options = {}) {
  VolumeMethod m(options);
  m.prepare(scene, {});
  m.build(scene, 0, {});
  return testing::counter(m, "depth_fail_sub_objects");
}

TEST(Counting, EyeInsideAShadowVolumeCountsDepthPassFromTheEyesCount) {
  // The camera under the square, in its shadow, looking across the ground.
  const Scene scene = square_scene({0.3, 0.4, 0.2}, {4, 0, 3});
  EXPECT_EQ(depth_fail_sub_objects(scene), 0);
  EXPECT_LE(testing::worst_interior_mismatch(scene, "volume"), 0.05);
  EXPECT_LE(testing::worst_interior_mismatch(scene, "volume", {"volume", {{"count", "fail"}}}),
            0.05);
}

TEST(Counting, TilesNoShadowPolygonReachesKeepTheEyesCount) {
  // The camera under the square looks down at ground wholly in its shadow: the volume's
  // polygons all lie outside the view, so no tile counts any, and every count is the eye's.
  const Scene scene = square_scene({0, 0.5, 0}, {0.3, 0, 0.1});
  const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
  VolumeMethod m({});
  const ShadowMask mask = testing::method_mask(m, scene, vsb, 0);
  EXPECT_EQ(testing::counter(m, "fill"), 0);
  std::size_t covered = 0;
  for (std::size_t i = 0; i < mask.pixels.size(); ++i) {
    if (!vsb.covered(i)) continue;
    ++covered;
    ASSERT_EQ(mask.pixels[i], kMaskShadow) << "pixel " << i;
  }
  EXPECT_EQ(covered, mask.pixels.size());
}

TEST(Counting, NearPlaneCuttingAShadowVolumeSwitchesToDepthFail) {
  // The eye on the shadow polygon of the square's edge x = 1 (the plane through the light
  // and that edge): the near plane cuts it, and the square's volume is counted depth-fail.
  const Plane plane{normalize(Vec3{3, 1, 0}), -4 / length(Vec3{3, 1, 0})};
  const Vec3 on_plane{1.25, 0.25, 0.1};
  ASSERT_NEAR(plane.distance(on_plane), 0, 1e-12);
  const Scene scene = square_scene(on_plane, {3, 0, 2});
  EXPECT_EQ(depth_fail_sub_objects(scene), 1);
  EXPECT_LE(testing::worst_interior_mismatch(scene, "volume"), 0.05);
}

TEST(Counting, NearPlaneCuttingAFaceSwitchesToDepthFail) {
  // The eye 1e-7 outside a closed box's face x = 1, looking in: the near plane (2.6e-7 in
  // front of it) cuts the face away, and the view shows the box's inside without the eye's
  // count changing. Inside, everything is lit by a light in the box and shadowed by one
  // outside it.
  const Camera cam = testing::camera({1 + 1e-7, 1.5, 0.3}, {-1, 1.2, 0}, 64, 48);
  for (const Vec3 light : {Vec3{0, 1.5, 0}, Vec3{3, 5, 2}}) {
    const Scene scene = testing::make_scene(cam, {testing::point_light(light)},
                                            {testing::box({-1, 0.5, -1}, {1, 2.5, 1})});
    const std::uint8_t inside = light.x < 1 ? kMaskLit : kMaskShadow;
    EXPECT_EQ(depth_fail_sub_objects(scene), 1);
    const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
    VolumeMethod m({});
    const ShadowMask mask = testing::method_mask(m, scene, vsb, 0);
    EXPECT_EQ(std::count(mask.pixels.begin(), mask.pixels.end(), inside), 64 * 48) << light.x;
    EXPECT_LE(testing::worst_interior_mismatch(scene, "volume"), 0.05) << light.x;
  }
}

TEST(Counting, FacesAndShadowPolygonsWhosePlanesAloneNearTheEyeKeepDepthPass) {
  // 1e-6 above the square's plane (the near plane reaches 2e-6), but 5 away from the square.
  const Scene beside = square_scene({6, 1 + 1e-6, 0.3}, {0, 0, 0});
  EXPECT_EQ(depth_fail_sub_objects(beside), 0);
  EXPECT_LE(testing::worst_interior_mismatch(beside, "volume"), 0.05);
  // On the plane through the light and the square's edge x = 1, between them: off the edge's
  // shadow polygon, which begins at the edge.
  const Vec3 above{0.5, 2.5, 0.1};
  const Plane side{normalize(Vec3{3, 1, 0}), -4 / length(Vec3{3, 1, 0})};
  ASSERT_NEAR(side.distance(above), 0, 1e-12);
  const Scene between = square_scene(above, {3, 0, 2});
  EXPECT_EQ(depth_fail_sub_objects(between), 0);
  EXPECT_LE(testing::worst_interior_mismatch(between, "volume"), 0.05);
}

// The side polygon of the square's edge from (1, 1, -1) to (1, 1, 1), whichever way it runs.
bool edge_polygon_near(const Light& light, Vec3 p, double radius) {
  const Mesh square = Mesh::build(testing::horizontal_quad(-1, 1, -1, 1, 1), "square", {});
  for (const ContourEdge& e : find_contour_edges(square, light)) {
    const Vec3 a = square.vertices[e.from], b = square.vertices[e.to];
    if (a.x == 1 && b.x == 1) return side_polygon_near(square, e, light, p, radius);
  }
  ADD_FAILURE() << "no contour edge along x = 1";
  return true;
}

TEST(Counting, SidePolygonNearAPointIsTheHalfPlanesTest) {
  // A point light at (0, 4, 0): the polygon runs from the edge down and out, between the
  // rays from the light through the edge's ends; its plane is 3x + y = 4.
  const Light point = Light::point({0, 4, 0});
  EXPECT_TRUE(edge_polygon_near(point, {1.25, 0.25, 0.1}, 1e-3));          // on it
  EXPECT_TRUE(edge_polygon_near(point, {1.25, 0.2505, 0.1}, 1e-3));        // just off it
  EXPECT_FALSE(edge_polygon_near(point, {1.25, 0.26, 0.1}, 1e-3));         // off its plane
  EXPECT_FALSE(edge_polygon_near(point, {0.5, 2.5, 0.1}, 1e-3));           // short of the edge
  EXPECT_FALSE(edge_polygon_near(point, {1.25, 0.25, 1.3}, 1e-3));         // past a ray's side
  EXPECT_FALSE(edge_polygon_near(point, {1.25, 0.25, -1.3}, 1e-3));        // past the other
  EXPECT_TRUE(edge_polygon_near(point, {1.25, 0.25, 1.25 + 5e-4}, 1e-3));  // near that ray
  // Straight down: the polygon is the strip x = 1, y < 1, |z| <= 1.
  const Light down = Light::directional({0, -1, 0});
  EXPECT_TRUE(edge_polygon_near(down, {1, -50, 0.9}, 1e-3));
  EXPECT_TRUE(edge_polygon_near(down, {1, 1.0005, 0}, 1e-3));
  EXPECT_FALSE(edge_polygon_near(down, {1, 1.01, 0}, 1e-3));
  EXPECT_FALSE(edge_polygon_near(down, {1, -50, 1.01}, 1e-3));
  EXPECT_FALSE(edge_polygon_near(down, {1.01, -50, 0}, 1e-3));
}

TEST(Counting, ForcedDepthPassAndDepthFailAgreeWithTheReference) {
  const Scene scene = square_scene({0, 9, 6}, {0, 0, 0});
  EXPECT_EQ(depth_fail_sub_objects(scene, {"volume", {{"count", "pass"}}}), 0);
  EXPECT_EQ(depth_fail_sub_objects(scene, {"volume", {{"count", "fail"}}}), 2);
  for (const char* mode : {"pass", "fail"}) {
    EXPECT_LE(testing::worst_interior_mismatch(scene, "volume", {"volume", {{"count", mode}}}),
              0.05)
        << mode;
  }
}

// With the camera in the ground's plane no count at the eye exists: a forced depth-pass
// refuses the light (it once stopped on a failed check), and auto counts depth-fail.
// The error of a forced depth-pass building light 0 of \p scene; empty if it builds.
std::string forced_pass_refusal(const Scene& scene) {
  VolumeMethod pass({"volume", {{"count", "pass"}}});
  pass.prepare(scene, {});
  try {
    pass.build(scene, 0, {});
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(Counting, ForcedDepthPassRefusesAnEyeWithoutACount) {
  const Scene scene = square_scene({0, 0, 6}, {0, 1, 0});
  EXPECT_EQ(forced_pass_refusal(scene),
            "option 'volume.count': pass needs the count at the eye, which object 'object0' "
            "leaves undefined (the camera lies in one of its face planes, or its ray to "
            "the light grazes an edge); use auto or fail");
  EXPECT_EQ(depth_fail_sub_objects(scene), 1);
}

// Where many sub-objects leave the eye's count undefined, a forced depth-pass names the first
// of them, whichever thread meets which first (sub-objects are made in parallel chunks).
TEST(Counting, ForcedDepthPassNamesTheFirstObjectWithoutACount) {
  std::vector<PolygonSoup> objects;
  for (int i = 0; i < 200; ++i) {
    // Boxes 70 and 130 stand on y = 0, the camera's height; the others float.
    const double y = i == 70 || i == 130 ? 0.0 : 0.5;
    const Vec3 lo{(i % 20) * 0.5 - 5, y, -(i / 20) * 0.5 - 2};
    objects.push_back(testing::box(lo, lo + Vec3{0.3, 0.3, 0.3}));
  }
  const Scene scene = testing::make_scene(testing::camera({0, 0, 6}, {0, 1, 0}, 64, 48),
                                          {testing::point_light({0, 9, 0})}, objects);
  for (int run = 0; run < 5; ++run) {
    EXPECT_THAT(forced_pass_refusal(scene), ::testing::HasSubstr("object 'object70'"));
  }
}

}  // namespace
}  // namespace shadowkit::volume
