// Per-polygon shadowed areas against an independent estimate (the criterion):
// stratified points on a polygon, each tested with an Embree shadow ray.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "multi_light.h"
#include "shadowkit/methods/raytrace.h"
#include "shadowkit/scene/scene_file.h"
#include "svbsp_test_support.h"

namespace shadowkit::svbsp {
namespace {

constexpr int kGrid = 200;  // 200 x 200 strata over the polygon's bounding rectangle

// Crossing-number test in the polygon's 2D frame.
bool inside(const std::vector<std::pair<double, double>>& poly, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const auto [xi, yi] = poly[i];
    const auto [xj, yj] = poly[j];
    if ((yi > y) != (yj > y) && x < xi + (y - yi) * (xj - xi) / (yj - yi)) in = !in;
  }
  return in;
}

// Shadowed fraction of global face \p face for \p light from stratified samples, each
// lifted off the face toward the light by a tiny fraction of the scene's size.
double sampled_shadowed_fraction(const Scene& scene, const raytrace::ShadowRays& rays,
                                 std::uint32_t face, const Light& light) {
  const Mesh& mesh = scene.objects[scene.object_of_face(face)].mesh;
  const std::uint32_t f = scene.local_face(face);
  const Plane& plane = scene.face_plane(face);
  const Vec3 origin = mesh.vertices[mesh.face_vertex(f, 0)];
  const Vec3 u = normalize(mesh.vertices[mesh.face_vertex(f, 1)] - origin);
  const Vec3 v = cross(plane.normal, u);
  std::vector<std::pair<double, double>> poly;
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  for (std::uint32_t k = 0; k < mesh.face_size(f); ++k) {
    const Vec3 p = mesh.vertices[mesh.face_vertex(f, k)] - origin;
    poly.push_back({dot(p, u), dot(p, v)});
    x0 = std::min(x0, poly.back().first), x1 = std::max(x1, poly.back().first);
    y0 = std::min(y0, poly.back().second), y1 = std::max(y1, poly.back().second);
  }
  const double side = light.type == Light::Type::point ? plane.distance(light.position)
                                                       : -dot(plane.normal, light.direction);
  const Vec3 lift = plane.normal * std::copysign(1e-7 * scene.bounds().diagonal(), side);
  std::mt19937 rng(face);
  std::uniform_real_distribution<double> jitter(0, 1);
  std::size_t in = 0, shadowed = 0;
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      const double x = x0 + (x1 - x0) * (i + jitter(rng)) / kGrid;
      const double y = y0 + (y1 - y0) * (j + jitter(rng)) / kGrid;
      if (!inside(poly, x, y)) continue;
      ++in;
      shadowed += rays.occluded(origin + u * x + v * y + lift, light);
    }
  }
  return double(shadowed) / double(in);
}

// The faces a light shadows partly, most evenly split first: where an error would show.
std::vector<std::uint32_t> partly_shadowed(const std::map<std::uint32_t, FaceAreas>& a,
                                           std::size_t count) {
  std::vector<std::pair<double, std::uint32_t>> split;
  for (const auto& [face, areas] : a) {
    const double share = std::min(areas.lit, areas.shadowed) / (areas.lit + areas.shadowed);
    if (share > 1e-3) split.push_back({share, face});
  }
  std::sort(split.rbegin(), split.rend());
  std::vector<std::uint32_t> faces;
  for (std::size_t i = 0; i < std::min(count, split.size()); ++i) faces.push_back(split[i].second);
  return faces;
}

class SampledAreas : public ::testing::TestWithParam<const char*> {};

TEST_P(SampledAreas, ShadowedAreasAgreeWithin0_5PercentOfThePolygon) {
  const Scene scene = load_scene(GetParam(), {});
  const raytrace::ShadowRays rays(scene);
  const MultiLightFragments multi = generate_multi_light_shadows(SceneBsp::build(scene), scene);
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const auto areas = face_areas(multi.fragments, l);
    const std::vector<std::uint32_t> faces = partly_shadowed(areas, 4);
    ASSERT_FALSE(faces.empty()) << "light " << l;
    for (const std::uint32_t face : faces) {
      const double total = face_area(scene, face);
      const double sampled = sampled_shadowed_fraction(scene, rays, face, scene.lights[l]);
      EXPECT_NEAR(areas.at(face).shadowed / total, sampled, 0.005)
          << GetParam() << " light " << l << " face " << face;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Svbsp, SampledAreas, ::testing::Values("square", "table", "three-lights"));

}  // namespace
}  // namespace shadowkit::svbsp
