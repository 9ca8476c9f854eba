#include "scene_info.h"

#include "shadowkit/methods/registry.h"

namespace shadowkit::viewer {
namespace {

nlohmann::json vec(Vec3 v) {
  return {v.x, v.y, v.z};
}

nlohmann::json camera_json(const Camera& c) {
  return {{"position", vec(c.position)}, {"look_at", vec(c.look_at)}, {"up", vec(c.up)},
          {"fov_y_deg", c.fov_y_deg},    {"width", c.width},          {"height", c.height}};
}

nlohmann::json light_json(const Light& light) {
  if (light.type == Light::Type::point) {
    return {{"type", "point"}, {"position", vec(light.position)}};
  }
  return {{"type", "directional"}, {"direction", vec(light.direction)}};
}

nlohmann::json methods_json() {
  nlohmann::json methods = nlohmann::json::array();
  for (const std::string& name : method_names()) {
    nlohmann::json settings = nlohmann::json::array();
    for (const SettingInfo& s : method_settings(name)) {
      settings.push_back(
          {{"key", s.key}, {"default", s.fallback}, {"choices", s.choices}, {"range", s.range}});
    }
    methods.push_back({{"name", name}, {"settings", settings}});
  }
  return methods;
}

}  // namespace

nlohmann::json scene_info(const FrameRenderer& renderer, const std::string& stream) {
  const Scene& scene = renderer.scene();
  const SceneView& view = renderer.scene_view();
  const Bounds3 bounds = scene.world_bounds();
  nlohmann::json lights = nlohmann::json::array();
  for (const Light& light : view.lights) lights.push_back(light_json(light));
  nlohmann::json site;
  if (scene.site) {
    site = {{"latitude", scene.site->latitude_deg},
            {"longitude", scene.site->longitude_deg},
            {"utc_offset", scene.site->utc_offset_hours},
            {"north", scene.site->north_deg}};
  }
  return {
      {"name", scene.name},
      {"polygons", scene.face_count()},
      {"triangles", scene.triangles().triangles.size()},
      {"bounds", {{"lo", vec(bounds.lo)}, {"hi", vec(bounds.hi)}}},
      {"camera", camera_json(view.camera)},
      {"lights", lights},
      {"site", site},
      {"methods", methods_json()},
      {"limits",
       {{"pixels", kMaxFramePixels}, {"lights", kMaxLights}, {"request_bytes", kMaxRequestBytes}}},
      {"stream", stream}};
}

}  // namespace shadowkit::viewer
