// Dispatch by generator name, the primitives usable in scene files, and make_builtin_scene.
#include "shadowkit/scene/generators.h"

#include <array>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string_view>

#include "builtin_scenes.h"
#include "primitives.h"
#include "shadowkit/core/error.h"

namespace shadowkit {
namespace generators {

Camera camera_looking_at(Vec3 position, Vec3 look_at, double fov_y_deg) {
  Camera camera;
  camera.position = position;
  camera.look_at = look_at;
  camera.up = {0, 1, 0};
  camera.fov_y_deg = fov_y_deg;
  camera.width = 1920;
  camera.height = 1080;
  return camera;
}

GeneratedObject ground_object(double half_size) {
  GeneratedObject ground{"ground", {}};
  add_horizontal_quad(ground.soup, {0, 0, 0}, 2 * half_size, 2 * half_size);
  return ground;
}

namespace {

// ---- Primitives for scene files ({"generator": "box", ...}), each centred at the origin ----

GeneratedObject box_primitive(const ParamReader& params) {
  params.allow_only({"size"});
  const Vec3 size = params.size3("size", {1, 1, 1});
  GeneratedObject box{"box", {}};
  add_box(box.soup, size * -0.5, size * 0.5);
  return box;
}

// An open horizontal square facing +y; `quad` and `ground` differ in name and default size.
GeneratedObject horizontal_square(const ParamReader& params, const char* name, double size) {
  params.allow_only({"size"});
  const Vec3 extent = params.size2("size", size);
  GeneratedObject square{name, {}};
  add_horizontal_quad(square.soup, {0, 0, 0}, extent.x, extent.z);
  return square;
}

GeneratedObject quad_primitive(const ParamReader& params) {
  return horizontal_square(params, "quad", 2);
}

GeneratedObject ground_primitive(const ParamReader& params) {
  return horizontal_square(params, "ground", 20);
}

GeneratedObject tetrahedron_primitive(const ParamReader& params) {
  params.allow_only({"size"});
  const double edge = params.positive("size", 1);
  // Bounding box centred at the origin, like the other solids; the base stays horizontal.
  std::array<Vec3, 4> corners = regular_tetrahedron({0, 0, 0}, edge);
  Bounds3 bounds;
  for (const Vec3& p : corners) bounds.add(p);
  for (Vec3& p : corners) p -= bounds.center();
  GeneratedObject tetrahedron{"tetrahedron", {}};
  add_tetrahedron(tetrahedron.soup, corners);
  return tetrahedron;
}

GeneratedObject sphere_primitive(const ParamReader& params) {
  params.allow_only({"radius", "segments", "rings"});
  const double radius = params.positive("radius", 1);
  const auto segments = static_cast<int>(params.integer("segments", 32, 3, 1024));
  const auto rings = static_cast<int>(params.integer("rings", 16, 2, 512));
  GeneratedObject sphere{"sphere", {}};
  add_uv_sphere(sphere.soup, {0, 0, 0}, radius, segments, rings);
  return sphere;
}

struct PrimitiveEntry {
  std::string_view name;
  GeneratedObject (*build)(const ParamReader&);
};

constexpr PrimitiveEntry kPrimitives[] = {
    {"box", box_primitive},       {"quad", quad_primitive},
    {"ground", ground_primitive}, {"tetrahedron", tetrahedron_primitive},
    {"sphere", sphere_primitive},
};

// ---- Full scenes ----

/// \brief A built-in scene; "NAME:VALUE" sets its parameter \p spec_key to VALUE.
struct SceneEntry {
  std::string_view name;
  SceneParts (*build)(const ParamReader&);
  std::string_view spec_key;  ///< empty: the scene takes no parameter in a spec string
  bool integer_value;
  std::string_view example;  ///< a valid spec, for error messages
};

constexpr SceneEntry kScenes[] = {
    {"cubes", cube_field_scene, "count", true, "cubes:2000"},
    {"terrain", terrain_scene, "cells", true, "terrain:160"},
    {"tetra", tetra_scene, "level", true, "tetra:4"},
    {"room", room_scene, "size", false, "room:12"},
    {"table", table_scene, "", false, "table"},
    {"three-lights", three_lights_scene, "", false, "three-lights"},
    {"square", square_scene, "height", false, "square:1.5"},
    {"coil", coil_scene, "turns", false, "coil:1.6"},
    {"holed", holed_scene, "", false, "holed"},
    {"hole-like", hole_like_scene, "", false, "hole-like"},
};

const SceneEntry* find_scene(std::string_view name) {
  for (const SceneEntry& entry : kScenes) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

std::string joined_names(bool with_primitives) {
  std::string names;
  for (const SceneEntry& entry : kScenes) {
    names += (names.empty() ? "" : ", ") + std::string(entry.name);
  }
  if (with_primitives) {
    for (const PrimitiveEntry& entry : kPrimitives) names += ", " + std::string(entry.name);
  }
  return names;
}

/// The JSON value of the VALUE in "NAME:VALUE"; the whole text must be a number.
nlohmann::json spec_value(const SceneEntry& entry, std::string_view text,
                          const std::string& where) {
  const char* end = text.data() + text.size();
  nlohmann::json value;
  std::from_chars_result parsed{};
  if (entry.integer_value) {
    std::int64_t n = 0;
    parsed = std::from_chars(text.data(), end, n);
    value = n;
  } else {
    double x = 0;
    parsed = std::from_chars(text.data(), end, x);
    value = x;
  }
  if (parsed.ec == std::errc() && parsed.ptr == end) return value;
  throw InputError(where, "'" + std::string(text) + "' is not a valid " +
                              std::string(entry.spec_key) + " (expected " +
                              (entry.integer_value ? "an integer" : "a number") + ", e.g. " +
                              std::string(entry.example) + ")");
}

}  // namespace
}  // namespace generators

std::vector<GeneratedObject> generate_objects(const nlohmann::json& params,
                                              const std::string& where) {
  using namespace generators;
  const ParamReader reader(params, where);
  const auto name_it = params.find("generator");
  if (name_it == params.end()) {
    reader.fail("generator", "missing (known: " + joined_names(true) + ")");
  }
  if (!name_it->is_string()) {
    reader.fail("generator", std::string("expected a string, got ") + name_it->type_name());
  }
  const auto name = name_it->get<std::string>();
  if (const SceneEntry* scene = find_scene(name)) return scene->build(reader).objects;
  for (const PrimitiveEntry& entry : kPrimitives) {
    if (entry.name == name) return {entry.build(reader)};
  }
  reader.fail("generator", "unknown generator '" + name + "' (known: " + joined_names(true) + ")");
}

SceneSource builtin_scene_source(const std::string& spec, const std::string& where) {
  using namespace generators;
  const std::size_t colon = spec.find(':');
  const std::string name = spec.substr(0, colon);
  const SceneEntry* entry = find_scene(name);
  if (entry == nullptr) {
    throw InputError(where,
                     "unknown built-in scene '" + name + "' (known: " + joined_names(false) + ")");
  }
  nlohmann::json params{{"generator", name}};
  if (colon != std::string::npos) {
    if (entry->spec_key.empty()) {
      throw InputError(where, "built-in scene '" + name + "' takes no parameter");
    }
    params[std::string(entry->spec_key)] =
        spec_value(*entry, std::string_view(spec).substr(colon + 1), where);
  }
  SceneSource source = builtin_scene_source(params, where);
  source.name = spec;
  return source;
}

SceneSource builtin_scene_source(const nlohmann::json& params, const std::string& where) {
  using namespace generators;
  const ParamReader reader(params, where);
  const auto name_it = params.find("generator");
  if (name_it == params.end() || !name_it->is_string()) {
    reader.fail("generator", "expected the name of a built-in scene");
  }
  const std::string name = name_it->get<std::string>();
  const SceneEntry* entry = find_scene(name);
  if (entry == nullptr) {
    reader.fail("generator",
                "unknown built-in scene '" + name + "' (known: " + joined_names(false) + ")");
  }
  SceneParts parts = entry->build(reader);
  SceneSource source{name, parts.camera, std::move(parts.lights), {}, where};
  for (GeneratedObject& object : parts.objects) {
    source.objects.push_back({object.name, std::move(object.soup), 0, where});
  }
  return source;
}

Scene make_builtin_scene(const std::string& spec, const Context& ctx) {
  return assemble_scene(builtin_scene_source(spec, "scene '" + spec + "'"), ctx);
}

std::vector<std::string> builtin_scene_names() {
  std::vector<std::string> names;
  for (const generators::SceneEntry& entry : generators::kScenes) names.emplace_back(entry.name);
  return names;
}

}  // namespace shadowkit
