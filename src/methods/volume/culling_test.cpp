#include <gtest/gtest.h>

#include <cmath>

#include "contour_edges.h"
#include "shadow_polygon.h"
#include "shadowkit/raster/visible_surface.h"
#include "shadowkit/scene/sub_objects.h"
#include "testing/method_testing.h"
#include "testing/test_scenes.h"
#include "volume_culling.h"
#include "volume_method.h"

namespace shadowkit::volume {
namespace {

// Two boxes in one mesh, an open square and a bow tie of two triangles sharing one vertex.
Scene parts_scene() {
  PolygonSoup boxes = testing::box({-3, 1, -1}, {-1, 3, 1});
  boxes.append(testing::box({1, 1, -1}, {3, 2, 1}));
  PolygonSoup bow_tie;
  bow_tie.positions = {{0, 0, 0}, {1, 0, 1}, {1, 0, -1}, {-1, 0, 1}, {-1, 0, -1}};
  bow_tie.add_face({0, 1, 2});
  bow_tie.add_face({0, 4, 3});
  return testing::make_scene(testing::camera({0, 5, 9}, {0, 0, 0}, 64, 48),
                             {testing::point_light({0, 8, 0})},
                             {boxes, testing::horizontal_quad(-1, 1, -1, 1, 4), bow_tie});
}

TEST(SubObjects, AreTheEdgeConnectedPartsOfEachObject) {
  const Scene scene = parts_scene();
  const SubObjects parts = SubObjects::of(scene);
  // Two boxes; the square; the bow tie's triangles share a vertex but no edge: two parts.
  ASSERT_EQ(parts.size(), 5u);
  EXPECT_EQ(parts.faces(0).size(), 6u);
  EXPECT_EQ(parts.faces(1).size(), 6u);
  EXPECT_EQ(parts.faces(2).size(), 1u);
  EXPECT_EQ(parts.of_face[6], 1u);
  EXPECT_EQ(parts.bounds[1].lo, (Vec3{1, 1, -1}));
  EXPECT_EQ(parts.bounds[1].hi, (Vec3{3, 2, 1}));
  EXPECT_EQ(parts.corners(0).size(), 8u);  // a box's vertices
  EXPECT_EQ(parts.corners(3).size(), 3u);  // a triangle's
  for (std::uint32_t f = 0; f < scene.face_count(); ++f) {
    const auto faces = parts.faces(parts.of_face[f]);
    EXPECT_NE(std::find(faces.begin(), faces.end(), f), faces.end()) << f;
  }
}

const Reach kReach{1e3, {{-100, -100, -100}, {100, 100, 100}}};

Bounds3 point_box(Vec3 p, double half = 0) {
  return {p - Vec3{1, 1, 1} * half, p + Vec3{1, 1, 1} * half};
}

TEST(ShadowFrustum, HoldsWhatTheBoxShadowsAndMissesTheRest) {
  // A unit cube centred at height 2 under a point light at height 6: its shadow on the
  // ground y = 0 is the square |x|, |z| < 6 / 7, where its top face (at 2.5) projects.
  const Bounds3 cube{{-0.5, 1.5, -0.5}, {0.5, 2.5, 0.5}};
  const Light light = Light::point({0, 6, 0});
  const ShadowFrustum frustum(cube, light, kReach);
  EXPECT_FALSE(frustum.misses(point_box({0, 0, 0})));
  EXPECT_FALSE(frustum.misses(point_box({0.8, 0, 0.8})));
  EXPECT_TRUE(frustum.misses(point_box({1.0, 0, 1.0})));  // outside |x| < 6 / 7
  EXPECT_TRUE(frustum.misses(point_box({0, 4, 0})));      // between the light and the cube
  EXPECT_TRUE(frustum.misses(point_box({5, 0, 0}, 1)));
  EXPECT_FALSE(frustum.misses(point_box({5, 0, 0}, 4.5)));
  EXPECT_TRUE(frustum.misses(Bounds3{}));  // an empty receiver
}

TEST(ShadowFrustum, CutsByACasterPlanesMakeAConvexCastersVolumeExact) {
  // A tetrahedron inside the unit cube: its box's frustum holds points its own volume does
  // not; cut by its faces' and shadow polygons' planes, it misses them.
  PolygonSoup tetra;
  tetra.positions = {{-0.5, 1.5, -0.5}, {0.5, 1.5, -0.5}, {0, 1.5, 0.5}, {0, 2.5, 0}};
  tetra.add_face({0, 2, 1});
  tetra.add_face({0, 1, 3});
  tetra.add_face({1, 2, 3});
  tetra.add_face({2, 0, 3});
  const Mesh mesh = Mesh::build(tetra, "tetra", {});
  const Light light = Light::point({0, 6, 0});
  ShadowFrustum frustum(mesh.bounds(), light, kReach);
  const Vec3 corner_shadow{0.75, 0, 0.75};  // under the box's corner, beside the tetrahedron
  EXPECT_FALSE(frustum.misses(point_box(corner_shadow)));
  for (const ContourEdge& e : find_contour_edges(mesh, light)) {
    frustum.cut(mesh.vertices, side_plane(mesh, e, light));
  }
  for (const Plane& p : mesh.planes) frustum.cut(mesh.vertices, p);
  EXPECT_TRUE(frustum.misses(point_box(corner_shadow)));
  EXPECT_FALSE(frustum.misses(point_box({0, 0, 0})));
  EXPECT_FALSE(frustum.misses(point_box({0, 2, 0})));  // inside the tetrahedron
  // A plane with corners on both sides, or with the light on the corners' side, cuts nothing.
  frustum.cut(mesh.vertices, {{1, 0, 0}, 0});
  frustum.cut(mesh.vertices, {{0, 1, 0}, -1});  // y = 1: corners and light above it
  EXPECT_FALSE(frustum.misses(point_box({0.1, 0, 0.1})));
}

TEST(ShadowFrustum, DegenerateLightsAndScales) {
  const Bounds3 cube{{-0.5, 1.5, -0.5}, {0.5, 2.5, 0.5}};
  // The light inside the box: everything may be shadowed.
  EXPECT_FALSE(
      ShadowFrustum(cube, Light::point({0, 2, 0}), kReach).misses(point_box({50, 50, 50})));
  // The light in the plane of the box's top face.
  const ShadowFrustum level(cube, Light::point({3, 2.5, 0}), kReach);
  EXPECT_FALSE(level.misses(point_box({-2, 1.5, 0})));
  EXPECT_TRUE(level.misses(point_box({-2, 4, 0})));
  // A directional light: the box swept along it.
  const ShadowFrustum sun(cube, Light::directional({1, -1, 0}), kReach);
  EXPECT_FALSE(sun.misses(point_box({2, 0, 0})));
  EXPECT_TRUE(sun.misses(point_box({-2, 0, 0})));
  // Tiny and huge coordinates: the same picture scaled.
  for (double s : {1e-6, 1e6}) {
    const Bounds3 scaled{cube.lo * s, cube.hi * s};
    const Reach reach{1e3 * s, {Vec3{-100, -100, -100} * s, Vec3{100, 100, 100} * s}};
    const ShadowFrustum f(scaled, Light::point(Vec3{0, 6, 0} * s), reach);
    EXPECT_FALSE(f.misses(point_box(Vec3{0.8, 0, 0.8} * s))) << s;
    EXPECT_TRUE(f.misses(point_box(Vec3{1.0, 0, 1.0} * s))) << s;
  }
}

TEST(ShadowFrusta, OnlySubObjectsGivenRoomHoldAFrustum) {
  const Bounds3 cube{{-0.5, 1.5, -0.5}, {0.5, 2.5, 0.5}};
  ShadowFrusta frusta;
  frusta.assign({0, 1, 0, 1});
  EXPECT_EQ(frusta.size(), 4u);
  frusta[1] = ShadowFrustum(cube, Light::point({0, 6, 0}), kReach);
  frusta[3] = ShadowFrustum(cube, Light::directional({1, -1, 0}), kReach);
  EXPECT_FALSE(frusta[1].misses(point_box({0.8, 0, 0.8})));
  EXPECT_FALSE(frusta[3].misses(point_box({2, 0, 0})));
  EXPECT_TRUE(frusta[1].misses(point_box({2, 0, 2})));
  // The others give the empty region, which shadows nothing.
  for (std::size_t k : {0u, 2u}) {
    EXPECT_TRUE(frusta[k].misses(point_box({0.8, 0, 0.8}, 100))) << k;
    EXPECT_TRUE(frusta[k].volume_planes().empty()) << k;
  }
}

// Crow's footprints (shadowed_sub_objects) drop casters without changing the picture.
TEST(Culling, FootprintsDropCastersWithoutChangingThePicture) {
  for (const Light& light :
       {testing::point_light({3, 14, 5}), testing::directional_light({-0.3, -1, -0.2})}) {
    const Scene scene = testing::cube_block(light);
    VolumeMethod m({});
    const VisibleSurfaceBuffer vsb = render_visible_surfaces(scene, {});
    testing::method_mask(m, scene, vsb, 0);
    EXPECT_GT(testing::counter(m, "shadowed_sub_objects"), 30) << int(light.type);
    EXPECT_LE(testing::worst_interior_mismatch(scene, "volume"), 0.05) << int(light.type);
  }
}

}  // namespace
}  // namespace shadowkit::volume
