#include "shadowkit/scene/scene_file.h"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "json_cursor.h"
#include "shadowkit/core/error.h"
#include "shadowkit/scene/generators.h"
#include "shadowkit/scene/mesh_io.h"

namespace shadowkit {
namespace {

namespace fs = std::filesystem;

// Embree stores coordinates in float and treats |x| >= 1.8e18 as invalid; far below that,
// every stage has headroom in double.
constexpr double kMaxCoordinate = 1e15;

Vec3 position(const JsonCursor& c) {
  const Vec3 p = c.vec3();
  if (max_abs_component(p) > kMaxCoordinate) c.fail("coordinates beyond +-1e15 are not supported");
  return p;
}

nlohmann::json parse_json(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot open scene file");
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  try {
    return nlohmann::json::parse(s);
  } catch (const nlohmann::json::parse_error& e) {
    // nlohmann reports a byte offset; users need the line.
    const std::size_t end = std::min<std::size_t>(e.byte, s.size());
    const auto line = 1 + std::count(s.begin(), s.begin() + std::ptrdiff_t(end), '\n');
    std::string what = e.what();
    const std::size_t colon = what.find(": ");
    if (colon != std::string::npos) what = what.substr(colon + 2);
    throw InputError(path.string() + ":" + std::to_string(line), "malformed JSON: " + what);
  }
}

void warn_unknown(const JsonCursor& c, const std::vector<std::string>& known, const Context& ctx,
                  const std::string& file) {
  for (const std::string& key : c.unknown_keys(known)) {
    ctx.warning(file + ": key '" + key + "' is not part of the scene format; ignored");
  }
}

Camera read_camera(const JsonCursor& c, Camera camera, const Context& ctx,
                   const std::string& file) {
  warn_unknown(c, {"position", "look_at", "up", "fov_y_deg", "width", "height"}, ctx, file);
  if (c.has("position")) camera.position = position(c["position"]);
  if (c.has("look_at")) camera.look_at = position(c["look_at"]);
  if (c.has("up")) camera.up = c["up"].vec3();
  if (c.has("fov_y_deg")) camera.fov_y_deg = c["fov_y_deg"].number();
  if (c.has("width")) camera.width = c["width"].integer(1, 16384);
  if (c.has("height")) camera.height = c["height"].integer(1, 16384);
  const Vec3 view = camera.look_at - camera.position;
  if (!(length(view) > 1e-12 * std::max(1.0, max_abs_component(camera.position)))) {
    c["look_at"].fail("equals camera.position: the view direction is undefined");
  }
  if (!(length(cross(normalize(view), camera.up)) > 1e-9)) {
    c.has("up") ? c["up"].fail("is zero or parallel to the view direction")
                : c.fail("up [0, 1, 0] is parallel to the view direction; give camera.up");
  }
  if (!(camera.fov_y_deg >= 1e-3 && camera.fov_y_deg <= 179.9)) {
    c["fov_y_deg"].fail("must lie between 0.001 and 179.9 degrees");
  }
  return camera;
}

Light read_light(const JsonCursor& c, const Context& ctx, const std::string& file) {
  Light light;
  const std::string type = c["type"].string();
  if (type == "point") {
    warn_unknown(c, {"type", "position"}, ctx, file);
    light.type = Light::Type::point;
    light.position = position(c["position"]);
  } else if (type == "directional") {
    warn_unknown(c, {"type", "direction"}, ctx, file);
    light.type = Light::Type::directional;
    const Vec3 d = c["direction"].vec3();
    if (!(length(d) > 0)) c["direction"].fail("is the zero vector");
    light.direction = normalize(d);
  } else {
    c["type"].fail("unknown light type '" + type + "' (expected \"point\" or \"directional\")");
  }
  return light;
}

void apply_object_transform(const JsonCursor& c, std::vector<Vec3>& positions) {
  if (!c.has("transform")) return;
  const JsonCursor t = c["transform"];
  const Vec3 scale = t.has("scale") ? t["scale"].scale3() : Vec3{1, 1, 1};
  if (scale.x == 0 || scale.y == 0 || scale.z == 0) {
    t["scale"].fail("a zero scale flattens the object to nothing");
  }
  const Vec3 rotate = t.has("rotate_deg") ? t["rotate_deg"].vec3() : Vec3{};
  const Vec3 translate = t.has("translate") ? t["translate"].vec3() : Vec3{};
  apply_transform(positions, scale, rotate, translate);
}

void check_coordinates(const JsonCursor& c, const std::vector<Vec3>& positions) {
  for (const Vec3& p : positions) {
    if (max_abs_component(p) > kMaxCoordinate || !is_finite(p)) {
      c.fail(std::string(c.has("transform") ? "after its transform, " : "") +
             "a vertex lies beyond +-1e15, which is not supported");
    }
  }
}

// Segments per patch edge of a Catmull-Clark object's tessellation, 0 for a polygon mesh.
// With the default 8, the polygons of examples/subdivision.json stay within 0.3% of their
// object's size of the limit surface; the gap shrinks as 1 / segments^2 on regular patches
// but only about as 1 / segments next to extraordinary vertices.
int tessellation_segments(const JsonCursor& c) {
  if (!c.has("subdivision")) {
    if (c.has("tessellation")) c["tessellation"].fail("applies only with \"subdivision\"");
    return 0;
  }
  const std::string scheme = c["subdivision"].string();
  if (scheme != "catmull-clark") {
    c["subdivision"].fail("unknown scheme '" + scheme + "' (expected \"catmull-clark\")");
  }
  return c.has("tessellation") ? c["tessellation"].integer(1, 256) : 8;
}

// The limit surface of the control mesh \p control and its tessellation, which every method
// but voxel sees.
SceneObject subdivision_object(const PolygonSoup& control, const std::string& label, int segments,
                               const JsonCursor& c, const Context& ctx) {
  const std::string where = c.where() + " (" + label + ")";
  auto surface = SubdivisionSurface::build(control, where);
  return {label, Mesh::build(surface->tessellate(segments), where, ctx), 0, std::move(surface)};
}

void read_objects(const JsonCursor& list, const fs::path& dir, Scene& scene, const Context& ctx,
                  const std::string& file) {
  for (std::size_t i = 0; i < list.array_size(); ++i) {
    const JsonCursor c = list[i];
    if (!c.value().is_object()) c.fail("expected an object with \"mesh\" or \"generator\"");
    std::vector<GeneratedObject> parts;
    if (c.has("mesh")) {
      warn_unknown(c, {"mesh", "transform", "name", "subdivision", "tessellation"}, ctx, file);
      const fs::path mesh_path = dir / c["mesh"].string();
      parts.push_back({mesh_path.stem().string(), read_mesh_file(mesh_path)});
    } else if (c.has("generator")) {
      parts = generate_objects(c.value(), c.where());
    } else {
      c.fail("needs a \"mesh\" file or a \"generator\"");
    }
    const int segments = tessellation_segments(c);
    const std::string name = c.has("name") ? c["name"].string() : "";
    for (GeneratedObject& part : parts) {
      apply_object_transform(c, part.soup.positions);
      check_coordinates(c, part.soup.positions);
      const std::string label = name.empty() ? part.name : name;
      scene.objects.push_back(
          segments > 0
              ? subdivision_object(part.soup, label, segments, c, ctx)
              : SceneObject{label, Mesh::build(part.soup, file + ": " + label, ctx), 0, {}});
    }
  }
}

}  // namespace

Scene load_scene_file(const fs::path& path, const Context& ctx) {
  const nlohmann::json json = parse_json(path);
  const std::string file = path.string();
  const JsonCursor root(json, file, "");
  if (!json.is_object()) throw InputError(file, "a scene file holds one JSON object");
  if (!root.has("generator")) warn_unknown(root, {"camera", "lights", "objects"}, ctx, file);

  Scene scene;
  if (root.has("generator")) {
    // The scene file's own keys are not the generator's parameters.
    nlohmann::json params = json;
    for (const char* key : {"camera", "lights", "objects"}) params.erase(key);
    const std::string spec = root["generator"].string();
    scene = spec.find(':') == std::string::npos ? make_builtin_scene(params, file, ctx)
                                                : make_builtin_scene(spec, ctx);
  } else if (!root.has("camera")) {
    throw InputError(file + ": key 'camera'", "is missing");
  }
  scene.name = path.stem().string();
  if (root.has("camera")) scene.camera = read_camera(root["camera"], scene.camera, ctx, file);
  if (root.has("lights")) {
    const JsonCursor lights = root["lights"];
    scene.lights.clear();
    for (std::size_t i = 0; i < lights.array_size(); ++i) {
      scene.lights.push_back(read_light(lights[i], ctx, file));
    }
  }
  if (root.has("objects")) read_objects(root["objects"], path.parent_path(), scene, ctx, file);
  if (scene.lights.empty()) ctx.warning(file + ": the scene has no lights");
  scene.finalize();
  if (scene.face_count() == 0) ctx.warning(file + ": the scene has no faces");
  return scene;
}

Scene load_scene(const std::string& spec, const Context& ctx) {
  std::error_code ec;
  if (fs::is_regular_file(spec, ec)) return load_scene_file(spec, ctx);
  const std::string name = spec.substr(0, spec.find(':'));
  const std::vector<std::string> builtins = builtin_scene_names();
  if (std::find(builtins.begin(), builtins.end(), name) != builtins.end()) {
    return make_builtin_scene(spec, ctx);
  }
  std::string list;
  for (const std::string& b : builtins) list += (list.empty() ? "" : ", ") + b;
  throw InputError(spec, "no such scene file or built-in scene (built-in scenes: " + list + ")");
}

}  // namespace shadowkit
