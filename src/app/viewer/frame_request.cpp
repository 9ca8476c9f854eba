#include <algorithm>
#include <cmath>

#include "shadowkit/app/viewer.h"
#include "shadowkit/core/error.h"
#include "shadowkit/methods/registry.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit::viewer {
namespace {

const std::string kWhere = "request";
constexpr int kMaxDepth = 8;

[[noreturn]] void fail(const std::string& key, const std::string& what) {
  throw InputError(key_location(kWhere, key), what);
}

const nlohmann::json& typed(const nlohmann::json& json, const std::string& key,
                            nlohmann::json::value_t type, const char* what) {
  const nlohmann::json& value = json.at(key);
  const bool number = type == nlohmann::json::value_t::number_float && value.is_number();
  if (value.type() != type && !number) fail(key, std::string("expected ") + what);
  return value;
}

FrameView parse_view(const std::string& name) {
  if (name == "shaded") return FrameView::shaded;
  if (name == "mask") return FrameView::mask;
  if (name == "difference") return FrameView::difference;
  fail("view", "unknown view '" + name + "' (expected shaded, mask or difference)");
}

// A setting's value as the command line's --set would give it.
std::string setting_text(const std::string& key, const nlohmann::json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number()) return value.dump();
  fail("settings." + key, "expected a string or a number");
}

MethodOptions parse_settings(const nlohmann::json& json, const std::string& method) {
  std::map<std::string, std::string> values;
  if (json.contains("settings")) {
    const auto& settings = typed(json, "settings", nlohmann::json::value_t::object, "an object");
    for (const auto& [key, value] : settings.items()) values[key] = setting_text(key, value);
  }
  MethodOptions options(method, std::move(values));
  make_method(method, options);  // the method's own checks, which name the setting
  return options;
}

}  // namespace

SceneView parse_request_view(const nlohmann::json& json, const SceneView& scene_view,
                             std::vector<std::string>& warnings) {
  Context ctx;
  ctx.warn = [&](const std::string& message) { warnings.push_back(message); };
  if (json.contains("lights") && json["lights"].is_array() && json["lights"].size() > kMaxLights) {
    fail("lights", "more than " + std::to_string(kMaxLights) + " lights");
  }
  SceneView view = read_scene_view(json, scene_view, kWhere, ctx);
  const std::int64_t pixels = std::int64_t{view.camera.width} * view.camera.height;
  if (pixels > kMaxFramePixels) {
    fail("camera", std::to_string(view.camera.width) + "x" + std::to_string(view.camera.height) +
                       " is more than the viewer's " + std::to_string(kMaxFramePixels) + " pixels");
  }
  return view;
}

nlohmann::json parse_request_json(std::string_view text, const std::vector<std::string>& known) {
  if (text.size() > kMaxRequestBytes) {
    throw InputError(kWhere, "larger than " + std::to_string(kMaxRequestBytes) + " bytes");
  }
  // A request nests four deep at most (lights[0].position[0]); deeper is refused as it is
  // read, so that no hostile nesting reaches recursive code.
  const auto shallow = [](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
    if (depth > kMaxDepth) throw InputError(kWhere, "nests deeper than any request");
    return true;
  };
  nlohmann::json json = nlohmann::json::parse(text, shallow, /*allow_exceptions=*/false);
  if (json.is_discarded()) throw InputError(kWhere, "is not valid JSON");
  if (!json.is_object()) throw InputError(kWhere, "expected one JSON object");
  for (const auto& [key, value] : json.items()) {
    if (std::find(known.begin(), known.end(), key) == known.end()) fail(key, "unknown key");
  }
  return json;
}

FrameRequest parse_frame_request(std::string_view text, const SceneView& scene_view) {
  const nlohmann::json json = parse_request_json(
      text, {"id", "camera", "lights", "method", "settings", "view", "light", "mismatch"});
  FrameRequest request;
  using type = nlohmann::json::value_t;
  if (json.contains("id")) request.id = typed(json, "id", type::number_float, "a number");
  request.view = parse_request_view(json, scene_view, request.warnings);
  if (json.contains("method")) {
    request.method = typed(json, "method", type::string, "a method name").get<std::string>();
  }
  request.settings = parse_settings(json, request.method);
  if (json.contains("view")) {
    request.image = parse_view(typed(json, "view", type::string, "a view name"));
  }
  if (json.contains("light")) {
    const double light = typed(json, "light", type::number_float, "a light index");
    if (!(light >= 0 && light < double(request.view.lights.size()) && light == std::floor(light))) {
      fail("light", "no light " + json["light"].dump() + " among the frame's " +
                        std::to_string(request.view.lights.size()));
    }
    request.light = std::size_t(light);
  }
  if (request.image != FrameView::shaded && request.view.lights.empty()) {
    fail("view", "a mask or difference view needs a light");
  }
  if (json.contains("mismatch")) {
    request.mismatch = typed(json, "mismatch", type::boolean, "true or false");
  }
  return request;
}

}  // namespace shadowkit::viewer
