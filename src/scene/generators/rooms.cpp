// Small hand-built scenes: the room (light and camera inside), Chin & Feiner's table and chairs
// (Fig. 10) and three-light solids (Figs. 5–8), and the analytic square-above-a-plane test.
#include <string>
#include <utility>

#include "builtin_scenes.h"
#include "primitives.h"

namespace shadowkit::generators {
namespace {

/// A table standing on the floor point \p at: a top of \p top_size (x, thickness, z) whose upper
/// face is at \p height and four square legs of side \p leg. The legs end halfway into the top
/// (no coplanar faces, no shared vertices) so every part stays a separate closed box.
void add_table(PolygonSoup& soup, Vec3 at, Vec3 top_size, double height, double leg) {
  const Vec3 half{top_size.x / 2, 0, top_size.z / 2};
  add_box(soup, at + Vec3{-half.x, height - top_size.y, -half.z},
          at + Vec3{half.x, height, half.z});
  const double leg_x = half.x - leg * 1.2, leg_z = half.z - leg * 1.2;
  const double leg_top = height - top_size.y / 2;
  for (const double sx : {-1.0, 1.0}) {
    for (const double sz : {-1.0, 1.0}) {
      const Vec3 c = at + Vec3{sx * leg_x, 0, sz * leg_z};
      add_box(soup, c + Vec3{-leg / 2, 0, -leg / 2}, c + Vec3{leg / 2, leg_top, leg / 2});
    }
  }
}

/// A chair on the floor point \p at facing -z turned by \p quarter_turns × 90° about +y:
/// seat, four legs and a back. Legs and back sink into the seat and are narrower than it, so
/// no two parts have coplanar overlapping faces.
void add_chair(PolygonSoup& soup, Vec3 at, int quarter_turns) {
  const std::size_t first = soup.positions.size();
  add_box(soup, {-0.22, 0.44, -0.22}, {0.22, 0.48, 0.22});  // seat
  for (const double sx : {-1.0, 1.0}) {
    for (const double sz : {-1.0, 1.0}) {
      const Vec3 c{sx * 0.185, 0, sz * 0.185};
      add_box(soup, c + Vec3{-0.02, 0, -0.02}, c + Vec3{0.02, 0.47, 0.02});
    }
  }
  add_box(soup, {-0.2, 0.45, 0.17}, {0.2, 0.98, 0.21});  // back
  transform_positions(soup, first, {1, 1, 1}, quarter_turns_about_y(quarter_turns), at);
}

/// Appends an empty object named \p name to \p parts and returns its soup to fill.
PolygonSoup& new_object(SceneParts& parts, std::string name) {
  parts.objects.push_back({std::move(name), {}});
  return parts.objects.back().soup;
}

}  // namespace

SceneParts room_scene(const ParamReader& params) {
  params.allow_only({"size"});
  // Built for a 10 × 6 × 10 room, then scaled to "size" (a number s means s × 0.6 s × s).
  const Vec3 nominal{10, 6, 10};
  const Vec3 size = params.size3("size", nominal, {1, 0.6, 1});
  const Vec3 scale{size.x / nominal.x, size.y / nominal.y, size.z / nominal.z};

  SceneParts parts;
  add_box(new_object(parts, "room"), {-5, 0, -5}, {5, 6, 5}, Facing::inward);
  add_oriented_box(new_object(parts, "crate"), {2.3, 0.75, -2.4}, {0.75, 0.75, 0.75},
                   rotation_from_quaternion(1, 0, 0.2, 0));
  add_box(new_object(parts, "pillar"), {-2.9, 0, -2.6}, {-2.1, 4.6, -1.8});
  add_table(new_object(parts, "table"), {-0.4, 0, 1.6}, {1.8, 0.1, 1.2}, 1.05, 0.1);
  for (GeneratedObject& o : parts.objects) transform_positions(o.soup, 0, scale, {}, {});

  // The light hangs near the ceiling (Thakur et al. Fig. 9(a): light inside the room); the
  // camera stands in the near corner at eye height.
  const auto scaled = [&](Vec3 p) { return Vec3{p.x * scale.x, p.y * scale.y, p.z * scale.z}; };
  parts.lights.push_back(Light::point(scaled({0.4, 5.3, -0.3})));
  parts.camera = camera_looking_at(scaled({4.2, 2.4, 4.3}), scaled({-1.5, 1.1, -1.8}), 65);
  return parts;
}

SceneParts table_scene(const ParamReader& params) {
  params.allow_only({});
  SceneParts parts;
  add_table(new_object(parts, "table"), {0, 0, 0}, {1.6, 0.06, 1.0}, 0.8, 0.06);
  // Chairs pushed under the long sides and at both ends, each facing the table.
  const Vec3 chair_at[4] = {{0, 0, 0.62}, {0, 0, -0.62}, {1.05, 0, 0}, {-1.05, 0, 0}};
  const int chair_turns[4] = {0, 2, 1, -1};
  for (int i = 0; i < 4; ++i) {
    add_chair(new_object(parts, "chair-" + std::to_string(i)), chair_at[i], chair_turns[i]);
  }
  parts.objects.push_back(ground_object(6));
  parts.lights.push_back(Light::point({1.3, 3.1, 1.7}));
  parts.lights.push_back(Light::directional({-0.55, -1, -0.35}));
  parts.camera = camera_looking_at({2.4, 2.1, 3.0}, {0, 0.35, 0});
  return parts;
}

SceneParts three_lights_scene(const ParamReader& params) {
  params.allow_only({});
  SceneParts parts;
  add_box(new_object(parts, "cube"), {-2.6, 0, -1.6}, {-0.6, 2, 0.4});
  add_box(new_object(parts, "tower"), {1.0, 0, -2.6}, {2.0, 3.2, -1.6});
  add_prism(new_object(parts, "prism"), {Vec3{0.6, 0, 0.7}, Vec3{2.8, 0, 0.7}, Vec3{1.7, 1.4, 0.7}},
            {0, 0, 1.8});
  add_tetrahedron(new_object(parts, "tetrahedron"), regular_tetrahedron({-1.5, 0, 2.4}, 1.8));
  parts.objects.push_back(ground_object(8));
  parts.lights.push_back(Light::point({-5.2, 6.5, 3.6}));
  parts.lights.push_back(Light::point({4.6, 5.1, 3.9}));
  parts.lights.push_back(Light::directional({0.35, -1, -0.45}));
  parts.camera = camera_looking_at({1.2, 6.3, 11.5}, {0, 0.8, 0});
  return parts;
}

SceneParts square_scene(const ParamReader& params) {
  params.allow_only({"height", "light_height"});
  const double light_height = params.positive("light_height", 4);
  const double height = params.positive("height", 1);
  if (height >= light_height) {
    params.fail("height", "the square must be below the light (height < light_height = " +
                              nlohmann::json(light_height).dump() + ")");
  }
  // A 2 × 2 square at y = h under a light at (0, L, 0): its shadow on y = 0 is the same square
  // scaled by L / (L - h) about the origin.
  SceneParts parts;
  add_horizontal_quad(new_object(parts, "square"), {0, height, 0}, 2, 2);
  parts.objects.push_back(ground_object(10));
  parts.lights.push_back(Light::point({0, light_height, 0}));
  parts.camera = camera_looking_at({0, 5.5, 5.5}, {0, 0.2, 0});
  return parts;
}

}  // namespace shadowkit::generators
