#include <gtest/gtest.h>

#include <set>

#include "control_meshes.h"
#include "shadowkit/scene/subdivision.h"

namespace shadowkit {
namespace {

const Context kQuiet{0, [](const std::string&) {}};

// Six times the enclosed volume: positive when the faces point outward.
double signed_volume(const PolygonSoup& soup) {
  double v = 0;
  for (std::size_t f = 0; f < soup.face_count(); ++f) {
    const Vec3 a = soup.positions[soup.indices[soup.face_start[f]]];
    for (std::uint32_t k = soup.face_start[f] + 1; k + 1 < soup.face_start[f + 1]; ++k) {
      v += dot(a, cross(soup.positions[soup.indices[k]], soup.positions[soup.indices[k + 1]]));
    }
  }
  return v;
}

TEST(Tessellation, ClosedControlMeshesGiveClosedOutwardMeshes) {
  for (const PolygonSoup& control :
       {test::cube_control(), test::pyramid_control(), test::torus_control()}) {
    const auto surface = SubdivisionSurface::build(control, "test");
    for (int segments : {1, 2, 5}) {
      const PolygonSoup soup = surface->tessellate(segments);
      EXPECT_EQ(soup.face_count(), surface->patch_count() * segments * segments * 2);
      const Mesh mesh = Mesh::build(soup, "test", kQuiet);
      EXPECT_EQ(mesh.face_count(), soup.face_count());  // nothing welded or dropped
      EXPECT_TRUE(mesh.closed());
      EXPECT_TRUE(mesh.consistently_oriented());
      EXPECT_GT(signed_volume(soup), 0);
    }
  }
}

TEST(Tessellation, SharedPointsAreEvaluatedOnceAndDistinct) {
  // Cube after one step: 26 vertices, 48 edges, 24 patches; each shared point stored once.
  const auto surface = SubdivisionSurface::build(test::cube_control(), "cube");
  const int n = 4;
  const PolygonSoup soup = surface->tessellate(n);
  EXPECT_EQ(soup.positions.size(), std::size_t(26 + 48 * (n - 1) + 24 * (n - 1) * (n - 1)));
  std::set<std::tuple<double, double, double>> distinct;
  for (const Vec3& p : soup.positions) distinct.insert({p.x, p.y, p.z});
  EXPECT_EQ(distinct.size(), soup.positions.size());
  // Euler characteristic 2 of the sphere-like cube: V - E + F with E = 3F / 2.
  EXPECT_EQ(std::int64_t(soup.positions.size()) - std::int64_t(soup.face_count()) / 2, 2);
}

TEST(Tessellation, PointsLieOnTheLimitSurfaceAndFacesKnowTheirPatch) {
  const auto surface = SubdivisionSurface::build(test::fan_control(5), "fan");
  std::vector<std::uint32_t> face_patch{99};  // stale contents are replaced
  const PolygonSoup soup = surface->tessellate(2, &face_patch);
  ASSERT_EQ(face_patch.size(), soup.face_count());
  for (std::uint32_t patch = 0; patch < surface->patch_count(); ++patch) {
    for (int k = 0; k < 8; ++k) EXPECT_EQ(face_patch[patch * 8 + std::uint32_t(k)], patch);
  }
  // Patch 0's centre is grid point (1, 1) of a 2-segment tessellation.
  const Vec3 centre = surface->evaluate(0, 0.5, 0.5).position;
  EXPECT_EQ(std::count(soup.positions.begin(), soup.positions.end(), centre), 1);
}

TEST(Tessellation, OpenControlMeshKeepsItsBoundary) {
  const auto surface = SubdivisionSurface::build(test::fan_control(5), "fan");
  const Mesh mesh = Mesh::build(surface->tessellate(3), "fan", kQuiet);
  EXPECT_TRUE(mesh.manifold());
  EXPECT_TRUE(mesh.consistently_oriented());
  EXPECT_EQ(mesh.boundary_edge_count(), 10u * 3);  // ten control boundary edges
  for (const Plane& plane : mesh.planes) EXPECT_GT(plane.normal.z, 0);  // faces +z like the fan
}

TEST(Tessellation, TinyAndHugeCoordinatesStayClosed) {
  for (double scale : {1e-9, 1e12}) {
    const auto surface = SubdivisionSurface::build(test::scaled(test::torus_control(), scale), "t");
    const Mesh mesh = Mesh::build(surface->tessellate(3), "torus", kQuiet);
    EXPECT_TRUE(mesh.closed());
    EXPECT_EQ(mesh.face_count(), 24u * 9 * 2);
  }
}

}  // namespace
}  // namespace shadowkit
