#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
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

std::set<std::tuple<double, double, double>> distinct_points(const PolygonSoup& soup) {
  std::set<std::tuple<double, double, double>> distinct;
  for (const Vec3& p : soup.positions) distinct.insert({p.x, p.y, p.z});
  return distinct;
}

TEST(Tessellation, SharedPointsAreEvaluatedOnceAndDistinct) {
  // Cube after one step: 26 vertices, 48 edges, 24 patches; each shared point stored once.
  const auto surface = SubdivisionSurface::build(test::cube_control(), "cube");
  const int n = 4;
  const PolygonSoup soup = surface->tessellate(n);
  EXPECT_EQ(soup.positions.size(), std::size_t(26 + 48 * (n - 1) + 24 * (n - 1) * (n - 1)));
  EXPECT_EQ(distinct_points(soup).size(), soup.positions.size());
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

// A pinhole camera's view from \p eye: 720 rows over a 45 degree field, no lights.
ViewTolerance view_from(Vec3 eye) {
  ViewTolerance view;
  view.eye = eye;
  view.pixel_at_unit_distance = 2 * std::tan(M_PI / 8) / 720;
  return view;
}

// Seen from near one side, the patches there take more segments than those far off; sides
// between them take the finer count, and the coarser cells along them are fanned, so the
// mesh stays closed and outward, with every point on the limit surface.
TEST(ViewTessellation, MixedSegmentsStayClosedAndOutward) {
  for (const auto& [control, eye] : {std::pair{test::cube_control(), Vec3{0.05, 0.1, 0.6}},
                                     {test::torus_control(), Vec3{2, 1, 0.5}}}) {
    const auto surface = SubdivisionSurface::build(control, "test");
    const ViewTessellation t = surface->tessellate_for_view(view_from(eye), 1 << 22);
    EXPECT_FALSE(t.coarsened);
    EXPECT_EQ(t.triangles_asked, t.soup.face_count());
    EXPECT_GE(t.finest, 4);
    EXPECT_LT(t.soup.face_count(), surface->patch_count() * t.finest * t.finest * 2);
    const Mesh mesh = Mesh::build(t.soup, "test", kQuiet);
    EXPECT_EQ(mesh.face_count(), t.soup.face_count());
    EXPECT_TRUE(mesh.closed());
    EXPECT_TRUE(mesh.consistently_oriented());
    EXPECT_GT(signed_volume(t.soup), 0);
  }
}

// The point of triangle (a, b, c) nearest \p p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 nearest_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a, bp = p - b, cp = p - c;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap), d3 = dot(ab, bp), d4 = dot(ac, bp);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d1 <= 0 && d2 <= 0) return a;
  if (d3 >= 0 && d4 <= d3) return b;
  if (d6 >= 0 && d5 <= d6) return c;
  const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  if (va <= 0 && d4 >= d3 && d5 >= d6) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  return a + ab * (vb / (va + vb + vc)) + ac * (vc / (va + vb + vc));
}

double distance_to(const PolygonSoup& soup, Vec3 p) {
  double best = INFINITY;
  for (std::size_t f = 0; f < soup.face_count(); ++f) {
    const std::uint32_t* v = &soup.indices[soup.face_start[f]];
    best =
        std::min(best, length(p - nearest_on_triangle(p, soup.positions[v[0]], soup.positions[v[1]],
                                                      soup.positions[v[2]])));
  }
  return best;
}

// The limit surface at random points lies within half a pixel of the tessellation for the
// view (the cells are held to it at their centres and side midpoints, and measure 0.32 pixel
// here), where the uniform 8 x 8 of the same torus, seen from close, is more than a pixel off.
TEST(ViewTessellation, TheLimitSurfaceStaysWithinHalfAPixel) {
  const auto surface = SubdivisionSurface::build(test::torus_control(), "torus");
  const ViewTolerance view = view_from({0.5, 3, 0.2});
  const PolygonSoup soup = surface->tessellate_for_view(view, std::size_t(1) << 22).soup;
  const PolygonSoup uniform = surface->tessellate(8);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> share(0, 1);
  double worst = 0, worst_uniform = 0;
  for (int k = 0; k < 200; ++k) {
    const auto patch = std::uint32_t(k % surface->patch_count());
    const Vec3 q = surface->evaluate(patch, share(random), share(random)).position;
    const double pixel = view.pixel_at_unit_distance * length(q - view.eye);
    worst = std::max(worst, distance_to(soup, q) / pixel);
    worst_uniform = std::max(worst_uniform, distance_to(uniform, q) / pixel);
  }
  std::printf("the limit surface within %.3f pixels of the view's tessellation, %.3f of 8 x 8\n",
              worst, worst_uniform);
  EXPECT_LE(worst, 0.5);
  EXPECT_GT(worst_uniform, 1.0);
}

TEST(ViewTessellation, NearerEyesAskForMoreAndAFarEyeForOneCell) {
  const auto surface = SubdivisionSurface::build(test::torus_control(), "torus");
  std::size_t previous = 0;
  for (const double distance : {400.0, 40.0, 8.0, 4.0}) {
    const ViewTessellation t =
        surface->tessellate_for_view(view_from({0, distance, 0}), std::size_t(1) << 22);
    EXPECT_GE(t.soup.face_count(), previous) << distance;
    previous = t.soup.face_count();
  }
  // So far off that a patch is below half a pixel: one cell each, the uniform tessellation.
  const ViewTessellation far = surface->tessellate_for_view(view_from({0, 1e6, 0}), 1 << 22);
  EXPECT_EQ(far.finest, 1);
  const PolygonSoup one = surface->tessellate(1);
  EXPECT_EQ(far.soup.face_count(), one.face_count());
  EXPECT_EQ(distinct_points(far.soup), distinct_points(one));
}

// The widest facet, in pixels, along the tessellation's own terminator for a point light:
// the sides between a face turned toward the light and one turned from it.
double widest_terminator_facet(const PolygonSoup& soup, const ViewTolerance& view, Vec3 light) {
  const auto corner = [&](std::size_t f, int k) {
    return soup.positions[soup.indices[soup.face_start[f] + std::uint32_t(k)]];
  };
  std::vector<bool> lit(soup.face_count());
  std::vector<double> width(soup.face_count());
  for (std::size_t f = 0; f < soup.face_count(); ++f) {
    const Vec3 a = corner(f, 0), b = corner(f, 1), c = corner(f, 2);
    lit[f] = dot(cross(b - a, c - a), light - a) > 0;
    const double pixel = view.pixel_at_unit_distance * length((a + b + c) / 3.0 - view.eye);
    width[f] = std::max({length(b - a), length(c - b), length(a - c)}) / pixel;
  }
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> first_face;
  double widest = 0;
  for (std::size_t f = 0; f < soup.face_count(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t p = soup.indices[soup.face_start[f] + std::uint32_t(k)];
      const std::uint32_t q = soup.indices[soup.face_start[f] + std::uint32_t((k + 1) % 3)];
      const auto [it, first] = first_face.try_emplace(std::minmax(p, q), f);
      if (!first && lit[it->second] != lit[f]) {
        widest = std::max({widest, width[it->second], width[f]});
      }
    }
  }
  return widest;
}

// Cells are split where the view needs them and nowhere else: along the terminator of a
// light they are a pixel across, while the rest of the torus, seen from close, keeps cells
// many pixels wide; a whole patch at the finest cells would take many times the triangles.
TEST(ViewTessellation, CellsArePixelSizedOnlyAlongTheTerminator) {
  const auto surface = SubdivisionSurface::build(test::torus_control(), "torus");
  ViewTolerance view = view_from({1, 6, 0.4});
  const Vec3 light{-2, 1, 4};
  view.point_lights.push_back(light);
  const ViewTessellation t = surface->tessellate_for_view(view, std::size_t(1) << 22);
  const double along = widest_terminator_facet(t.soup, view, light);
  const double uniform = widest_terminator_facet(surface->tessellate(8), view, light);
  std::printf(
      "widest facet along the terminator: %.2f pixels (8 x 8: %.2f); %zu triangles, "
      "finest %d\n",
      along, uniform, t.soup.face_count(), t.finest);
  EXPECT_LE(along, 2.0);
  EXPECT_GT(uniform, 10.0);
  EXPECT_LT(t.soup.face_count() * 20, surface->patch_count() * t.finest * t.finest * 2);
}

// The smallest angle of the soup's triangles, in degrees.
double smallest_angle(const PolygonSoup& soup) {
  double smallest = 180;
  for (std::size_t f = 0; f < soup.face_count(); ++f) {
    const std::uint32_t* v = &soup.indices[soup.face_start[f]];
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = soup.positions[v[k]], b = soup.positions[v[(k + 1) % 3]],
                 c = soup.positions[v[(k + 2) % 3]];
      const double cosine = dot(normalize(b - a), normalize(c - a));
      smallest = std::min(smallest, std::acos(std::clamp(cosine, -1.0, 1.0)) * 180 / M_PI);
    }
  }
  return smallest;
}

// The quadtrees are balanced 2:1, within and across patches, so that a cell is fanned over at
// most one more point a side: in (u, v) its triangles keep the uniform grid's 45 degrees, and
// no fan of slivers opens where fine cells meet coarse ones (unbalanced: 9.7 degrees here).
TEST(ViewTessellation, FansHaveNoSlivers) {
  const auto surface = SubdivisionSurface::build(test::torus_control(), "torus");
  ViewTolerance view = view_from({0.5, 3, 0.2});
  view.point_lights.push_back({-2, 1, 4});
  const ViewTessellation t = surface->tessellate_for_view(view, std::size_t(1) << 22);
  const double uniform = smallest_angle(surface->tessellate(t.finest));
  std::printf("smallest angle %.2f degrees (uniform %d x %d: %.2f)\n", smallest_angle(t.soup),
              t.finest, t.finest, uniform);
  EXPECT_GT(smallest_angle(t.soup), 0.9 * uniform);
}

// Over the bound, the finest cells are merged until the tessellation fits, still closed; at
// one cell a patch it is what it is.
TEST(ViewTessellation, TheBoundCoarsensItAndItStaysClosed) {
  const auto surface = SubdivisionSurface::build(test::torus_control(), "torus");
  const ViewTolerance near = view_from({0, 1.2, 0});
  const ViewTessellation free = surface->tessellate_for_view(near, std::size_t(1) << 22);
  const ViewTessellation bounded = surface->tessellate_for_view(near, free.soup.face_count() / 3);
  EXPECT_TRUE(bounded.coarsened);
  EXPECT_EQ(bounded.triangles_asked, free.soup.face_count());
  EXPECT_LE(bounded.soup.face_count(), free.soup.face_count() / 3);
  EXPECT_LT(bounded.finest, free.finest);
  EXPECT_TRUE(Mesh::build(bounded.soup, "torus", kQuiet).closed());
  const ViewTessellation tiny = surface->tessellate_for_view(near, 1);
  EXPECT_EQ(tiny.finest, 1);
  EXPECT_EQ(tiny.soup.face_count(), surface->patch_count() * 2);
}

}  // namespace
}  // namespace shadowkit
