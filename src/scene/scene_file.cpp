#include "shadowkit/scene/scene_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <sstream>

#include "io/json_text.h"
#include "json_cursor.h"
#include "shadowkit/core/error.h"
#include "shadowkit/scene/generators.h"
#include "shadowkit/scene/limits.h"
#include "shadowkit/scene/mesh_io.h"
#include "shadowkit/scene/scene_assembly.h"
#include "shadowkit/scene/sun_position.h"

namespace shadowkit {
namespace {

namespace fs = std::filesystem;

Vec3 position(const JsonCursor& c) {
  const Vec3 p = c.vec3();
  if (max_abs_component(p) > limits::kCoordinate) {
    c.fail("coordinates beyond +-1e15 are not supported");
  }
  return p;
}

// A direction: only its sense matters, so it is brought to a largest component of 1 before
// anything squares it; [1e300, -1e300, 0] and [3e-170, -1e-170, 0] are as good as [1, -1, 0]
// and [3, -1, 0], where a length would overflow to infinity or underflow to 0.
Vec3 direction(const JsonCursor& c) {
  const Vec3 d = c.vec3();
  const double largest = max_abs_component(d);
  if (largest == 0) c.fail("is the zero vector");
  return d / largest;
}

// A key whose value must be an object: has() finds nothing in any other value, which would
// skip every key under it without a word.
void require_object(const JsonCursor& c, const std::string& what) {
  if (!c.value().is_object()) {
    c.fail("expected an object" + what + ", got " + std::string(c.value().type_name()));
  }
}

nlohmann::json parse_json(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot open scene file");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json json = parse_json_text(text.str(), path.string());
  check_unique_keys(text.str(), path.string());
  return json;
}

void warn_unknown(const JsonCursor& c, const std::vector<std::string>& known, const Context& ctx,
                  const std::string& file) {
  for (const std::string& key : c.unknown_keys(known)) {
    ctx.warning(file + ": key '" + key + "' is not part of the scene format; ignored");
  }
}

Camera read_camera(const JsonCursor& c, Camera camera, const Context& ctx,
                   const std::string& file) {
  require_object(c, "");
  warn_unknown(c, {"position", "look_at", "up", "fov_y_deg", "width", "height"}, ctx, file);
  if (c.has("position")) camera.position = position(c["position"]);
  if (c.has("look_at")) camera.look_at = position(c["look_at"]);
  if (c.has("up")) camera.up = direction(c["up"]);
  if (c.has("fov_y_deg")) camera.fov_y_deg = c["fov_y_deg"].number();
  if (c.has("width")) camera.width = c["width"].integer(1, limits::kImageSide);
  if (c.has("height")) camera.height = c["height"].integer(1, limits::kImageSide);
  if (std::int64_t{camera.width} * camera.height > limits::kPixels) {
    c.fail(std::to_string(camera.width) + "x" + std::to_string(camera.height) + " makes " +
           std::to_string(std::int64_t{camera.width} * camera.height) + " pixels; at most " +
           std::to_string(limits::kPixels) + " are allowed");
  }
  const Vec3 view = camera.look_at - camera.position;
  // Relative to the coordinates alone: a scene in units of 1e-13 is as good as one in metres.
  const double size =
      std::max(max_abs_component(camera.position), max_abs_component(camera.look_at));
  if (!(length(view) > 1e-12 * size)) {
    c["look_at"].fail(view == Vec3{} ? "equals camera.position: the view direction is undefined"
                                     : "lies too close to camera.position, against their "
                                       "coordinates' size, to define a view direction");
  }
  if (!(length(cross(normalize(view), normalize(camera.up))) > 1e-9)) {
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
    light.direction = normalize(direction(c["direction"]));
  } else {
    c["type"].fail("unknown light type '" + type + "' (expected \"point\" or \"directional\")");
  }
  return light;
}

// The `camera` keys given over \p view's camera; `lights`, when given, in place of its lights.
void read_view_keys(const JsonCursor& root, SceneView& view, const Context& ctx,
                    const std::string& file) {
  if (root.has("camera")) view.camera = read_camera(root["camera"], view.camera, ctx, file);
  if (root.has("lights")) {
    const JsonCursor lights = root["lights"];
    view.lights.clear();
    for (std::size_t i = 0; i < lights.array_size(); ++i) {
      view.lights.push_back(read_light(lights[i], ctx, file));
    }
  }
  const std::int64_t pixels = std::int64_t{view.camera.width} * view.camera.height;
  if (std::int64_t(view.lights.size()) * pixels > limits::kMaskPixels) {
    const JsonCursor at = root.has("lights") ? root["lights"] : root["camera"];
    at.fail(std::to_string(view.lights.size()) + " lights of " + std::to_string(pixels) +
            " pixels each make more than " + std::to_string(limits::kMaskPixels) +
            " mask pixels; at most " + std::to_string(limits::kMaskPixels / pixels) +
            " lights fit this image");
  }
}

// The sun study's site (docs/scene-format.md, "Site"), checked here so that a bad value names
// its key; its ranges are those of the study's options (sun::validate).
sun::Site read_site(const JsonCursor& c, const Context& ctx, const std::string& file) {
  warn_unknown(c, {"latitude", "longitude", "utc_offset", "north", "name"}, ctx, file);
  const sun::Site site{c["latitude"].number(), c["longitude"].number(), c["utc_offset"].number(),
                       c.has("north") ? c["north"].number() : 0.0};
  const std::string where = c.where();
  sun::validate(site, {key_location(where, "latitude"), key_location(where, "longitude"),
                       key_location(where, "utc_offset"), key_location(where, "north")});
  return site;
}

// An object's `transform`, the identity when absent.
struct ObjectTransform {
  Vec3 scale{1, 1, 1};
  Vec3 rotate_deg;
  Vec3 translate;
};

ObjectTransform read_transform(const JsonCursor& c, const Context& ctx, const std::string& file) {
  ObjectTransform transform;
  if (!c.has("transform")) return transform;
  const JsonCursor t = c["transform"];
  // A transform of another type, or a misspelt key in it, would otherwise leave the object
  // silently where its mesh put it.
  require_object(t, " with \"scale\", \"rotate_deg\" or \"translate\"");
  warn_unknown(t, {"scale", "rotate_deg", "translate"}, ctx, file);
  if (t.has("scale")) transform.scale = t["scale"].scale3();
  if (const Vec3 scale = transform.scale; scale.x == 0 || scale.y == 0 || scale.z == 0) {
    t["scale"].fail("a zero scale flattens the object to nothing");
  }
  if (t.has("rotate_deg")) transform.rotate_deg = t["rotate_deg"].vec3();
  if (t.has("translate")) transform.translate = t["translate"].vec3();
  return transform;
}

// Segments per patch edge of a Catmull-Clark object's tessellation, kTessellationForView
// for "view" (the default: the contract's surface is the limit surface, and a fixed count is
// too coarse seen from close and wasted seen from afar), 0 for a polygon mesh.
int tessellation_segments(const JsonCursor& c) {
  if (!c.has("subdivision")) {
    if (c.has("tessellation")) c["tessellation"].fail("applies only with \"subdivision\"");
    return 0;
  }
  const std::string scheme = c["subdivision"].string();
  if (scheme != "catmull-clark") {
    c["subdivision"].fail("unknown scheme '" + scheme + "' (expected \"catmull-clark\")");
  }
  if (!c.has("tessellation")) return kTessellationForView;
  const JsonCursor tessellation = c["tessellation"];
  if (!tessellation.value().is_string()) return tessellation.integer(1, limits::kTessellation);
  if (tessellation.string() != "view") {
    tessellation.fail("expected a number of segments or \"view\"");
  }
  return kTessellationForView;
}

void read_objects(const JsonCursor& list, const fs::path& dir, SceneSource& scene,
                  const Context& ctx, const std::string& file) {
  // A root generator's objects come first, one input object each; the file's entries follow.
  const auto first_entry = std::uint32_t(scene.objects.size());
  for (std::size_t i = 0; i < list.array_size(); ++i) {
    const JsonCursor c = list[i];
    if (!c.value().is_object()) c.fail("expected an object with \"mesh\" or \"generator\"");
    std::vector<GeneratedObject> parts;
    if (c.has("mesh")) {
      warn_unknown(c, {"mesh", "transform", "name", "subdivision", "tessellation"}, ctx, file);
      const std::string mesh = c["mesh"].string();
      if (mesh.empty()) c["mesh"].fail("is an empty path");
      const fs::path mesh_path = dir / mesh;
      parts.push_back({mesh_path.stem().string(), read_mesh_file(mesh_path, ctx).soup});
    } else if (c.has("generator")) {
      parts = generate_objects(c.value(), c.where());
    } else {
      c.fail("needs a \"mesh\" file or a \"generator\"");
    }
    const int segments = tessellation_segments(c);
    const std::string name = c.has("name") ? c["name"].string() : "";
    const ObjectTransform transform = read_transform(c, ctx, file);
    std::uint32_t first_face = 0;
    for (GeneratedObject& part : parts) {
      apply_transform(part.soup.positions, transform.scale, transform.rotate_deg,
                      transform.translate);
      const auto faces = std::uint32_t(part.soup.face_count());
      scene.objects.push_back({name.empty() ? part.name : name, std::move(part.soup), segments,
                               c.where(), first_entry + std::uint32_t(i), first_face});
      first_face += faces;
    }
  }
}

// A root "generator" key: a built-in scene whose camera, lights and objects the file's own
// keys replace or extend.
SceneSource generated_scene(const JsonCursor& root, const std::string& file) {
  const std::string spec = root["generator"].string();
  if (spec.find(':') != std::string::npos)
    return builtin_scene_source(spec, root["generator"].where());
  // Its parameters are the file's keys but for the scene's own.
  nlohmann::json params = nlohmann::json::object();
  for (const auto& [key, value] : root.value().items()) {
    if (key != "camera" && key != "lights" && key != "objects" && key != "site") {
      params[key] = value;
    }
  }
  return builtin_scene_source(params, file);
}

}  // namespace

Scene load_scene_file(const fs::path& path, const Context& ctx) {
  const nlohmann::json json = parse_json(path);
  const std::string file = path.string();
  const JsonCursor root(json, file, "");
  if (!json.is_object()) throw InputError(file, "a scene file holds one JSON object");
  if (!root.has("generator")) {
    warn_unknown(root, {"camera", "lights", "objects", "site"}, ctx, file);
  }

  SceneSource scene;
  if (root.has("generator")) {
    scene = generated_scene(root, file);
  } else {
    // Without a built-in scene's camera to start from, the view must be given; the other
    // camera keys have defaults (docs/scene-format.md, "Defaults").
    const JsonCursor camera = root["camera"];
    require_object(camera, "");
    for (const std::string key : {"position", "look_at"}) {
      if (!camera.has(key)) throw InputError(file + ": key 'camera." + key + "'", "is missing");
    }
  }
  scene.name = path.stem().string();
  scene.where = file;
  SceneView view{scene.camera, std::move(scene.lights)};
  read_view_keys(root, view, ctx, file);
  scene.camera = view.camera;
  scene.lights = std::move(view.lights);
  // Before the objects: a bad site is found without reading a mesh.
  std::optional<sun::Site> site;
  std::string site_name;
  if (root.has("site")) {
    site = read_site(root["site"], ctx, file);
    if (root["site"].has("name")) site_name = root["site"]["name"].string();
  }
  if (root.has("objects")) read_objects(root["objects"], path.parent_path(), scene, ctx, file);
  if (scene.lights.empty()) ctx.warning(file + ": the scene has no lights");
  Scene assembled = assemble_scene(std::move(scene), ctx);
  assembled.site = site;
  assembled.site_name = site_name;
  if (assembled.face_count() == 0) ctx.warning(file + ": the scene has no faces");
  return assembled;
}

SceneView read_scene_view(const nlohmann::json& json, SceneView view, const std::string& where,
                          const Context& ctx) {
  if (!json.is_object()) throw InputError(where, "expected one JSON object");
  read_view_keys(JsonCursor(json, where, ""), view, ctx, where);
  return view;
}

Scene load_mesh_as_scene(const fs::path& path, const Context& ctx) {
  return mesh_scene(read_mesh_file(path, ctx), path, ctx);
}

Scene mesh_scene(MeshFile file, const fs::path& path, const Context& ctx) {
  Bounds3 box;
  for (const Vec3& p : file.soup.positions) box.add(p);
  SceneSource scene;
  scene.name = path.stem().string();
  scene.where = path.string();
  // From the front, right and above (+y up, as glTF, COLLADA and assimp place models), far
  // enough for the bounding sphere to fit the 45-degree view with a margin.
  const double radius = box.diagonal() > 0 ? 0.5 * box.diagonal() : 1.0;
  const Vec3 toward_camera = normalize(Vec3{0.6, 0.45, 1});
  scene.camera.look_at = box.center();
  scene.camera.position =
      box.center() + toward_camera * (1.05 * radius / std::sin(std::numbers::pi / 8));
  scene.camera.up = {0, 1, 0};
  scene.camera.fov_y_deg = 45;
  scene.lights.push_back(Light::directional({-0.4, -1, -0.6}));
  const std::size_t polygons = file.soup.face_count();
  scene.objects.push_back({scene.name, std::move(file.soup), 0, scene.where});
  Scene assembled = assemble_scene(std::move(scene), ctx);
  if (assembled.face_count() == 0) {
    throw InputError(path.string(), "all " + std::to_string(polygons) +
                                        " of its polygons are degenerate (no area)");
  }
  return assembled;
}

namespace {

// A scene file is JSON: named .json, or opening with '{'. Any other file is a mesh, which
// assimp recognises by its content when its name does not say.
bool is_scene_file(const fs::path& path) {
  if (is_mesh_file_name(path)) return false;
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".json") return true;
  std::ifstream in(path, std::ios::binary);
  char c = ' ';
  while (in.get(c) && std::isspace(static_cast<unsigned char>(c))) {
  }
  return !in || c == '{' || c == '\xEF';  // '\xEF': a UTF-8 byte order mark
}

}  // namespace

Scene load_scene(const std::string& spec, const Context& ctx) {
  std::error_code ec;
  if (fs::is_regular_file(spec, ec)) {
    return is_scene_file(spec) ? load_scene_file(spec, ctx) : load_mesh_as_scene(spec, ctx);
  }
  const std::string name = spec.substr(0, spec.find(':'));
  const std::vector<std::string> builtins = builtin_scene_names();
  if (std::find(builtins.begin(), builtins.end(), name) != builtins.end()) {
    return make_builtin_scene(spec, ctx);
  }
  if (fs::is_directory(spec, ec)) throw InputError(spec, "is a directory, not a scene file");
  if (fs::exists(spec, ec)) {
    throw InputError(spec, "is not a regular file (a device or a pipe), not a scene file");
  }
  std::string list;
  for (const std::string& b : builtins) list += (list.empty() ? "" : ", ") + b;
  throw InputError(spec, "no such scene file or built-in scene (built-in scenes: " + list + ")");
}

}  // namespace shadowkit
