#pragma once
// Tiny hand-built scenes with exactly known answers, shared by the tests of every layer.
#include <initializer_list>
#include <string>
#include <vector>

#include "shadowkit/scene/scene.h"

namespace shadowkit::testing {

/// \p scene seen by the same camera at \p width x \p height pixels (a reduced test size).
inline Scene resized(Scene scene, int width, int height) {
  scene.camera.width = width;
  scene.camera.height = height;
  return scene;
}

/// One polygon with the given corners, in order.
inline PolygonSoup polygon(std::initializer_list<Vec3> corners) {
  PolygonSoup soup;
  std::vector<std::uint32_t> face;
  for (const Vec3& c : corners) {
    face.push_back(std::uint32_t(soup.positions.size()));
    soup.positions.push_back(c);
  }
  soup.add_face(face);
  return soup;
}

/// The horizontal square [x0, x1] x [z0, z1] at height y, normal +y.
inline PolygonSoup horizontal_quad(double x0, double x1, double z0, double z1, double y) {
  return polygon({{x0, y, z1}, {x1, y, z1}, {x1, y, z0}, {x0, y, z0}});
}

/// An axis-aligned closed box with outward normals, six quads sharing eight vertices.
inline PolygonSoup box(Vec3 lo, Vec3 hi) {
  PolygonSoup s;
  for (int i = 0; i < 8; ++i) {
    s.positions.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
  }
  s.add_face({0, 4, 6, 2});  // -x
  s.add_face({1, 3, 7, 5});  // +x
  s.add_face({0, 1, 5, 4});  // -y
  s.add_face({2, 6, 7, 3});  // +y
  s.add_face({0, 2, 3, 1});  // -z
  s.add_face({4, 5, 7, 6});  // +z
  return s;
}

inline Camera camera(Vec3 position, Vec3 look_at, int width, int height, double fov = 45) {
  Camera c;
  c.position = position;
  c.look_at = look_at;
  c.width = width;
  c.height = height;
  c.fov_y_deg = fov;
  return c;
}

inline Light point_light(Vec3 p) {
  return Light::point(p);
}
inline Light directional_light(Vec3 d) {
  return Light::directional(d);
}

/// A finalized scene with one object per soup.
inline Scene make_scene(const Camera& cam, std::vector<Light> lights,
                        const std::vector<PolygonSoup>& soups) {
  Scene scene;
  scene.name = "test";
  scene.camera = cam;
  scene.lights = std::move(lights);
  const Context ctx;
  for (std::size_t i = 0; i < soups.size(); ++i) {
    const std::string name = "object" + std::to_string(i);
    scene.objects.push_back({name, Mesh::build(soups[i], name, ctx), 0, {}});
  }
  scene.finalize();
  return scene;
}

/// The analytic test of the issue: ground y = 0 ([-10, 10]^2), an open 2x2 square at
/// height 1, a point light at (0, 4, 0): the shadow is |x|, |z| < 4/3 on the ground.
inline Scene square_over_plane(const Camera& cam, Light light) {
  return make_scene(cam, {light},
                    {horizontal_quad(-10, 10, -10, 10, 0), horizontal_quad(-1, 1, -1, 1, 1)});
}

/// A 5 x 5 x 5 block of unit cubes with gaps of 0.1 over a ground: seen from \p light, the
/// cubes beyond its first layers lie wholly in the shadow of nearer ones (Crow's footprints).
inline Scene cube_block(Light light) {
  std::vector<PolygonSoup> objects{horizontal_quad(-10, 10, -10, 10, 0)};
  for (int i = 0; i < 125; ++i) {
    const Vec3 lo = Vec3{i % 5 - 2.5, 1.0 + i / 5 % 5, i / 25 - 2.5} * 1.1;
    objects.push_back(box(lo, lo + Vec3{1, 1, 1}));
  }
  return make_scene(camera({9, 9, 14}, {0, 3, 0}, 200, 150), {light}, objects);
}

}  // namespace shadowkit::testing
