#include "sun_request.h"

#include <cmath>

#include "shadowkit/core/error.h"

namespace shadowkit::viewer {
namespace {

const std::string kWhere = "request";

double number_at(const nlohmann::json& json, const std::string& key, const std::string& where) {
  if (!json.contains(key)) throw InputError(key_location(kWhere, where), "is missing");
  if (!json[key].is_number()) throw InputError(key_location(kWhere, where), "expected a number");
  return json[key].get<double>();
}

sun::Site site_of(const nlohmann::json& json, const Scene& scene) {
  if (!json.contains("site")) {
    if (!scene.site)
      throw InputError(key_location(kWhere, "site"), "is missing (the scene has none)");
    return *scene.site;
  }
  const nlohmann::json& s = json["site"];
  if (!s.is_object()) throw InputError(key_location(kWhere, "site"), "expected an object");
  const sun::Site site{number_at(s, "latitude", "site.latitude"),
                       number_at(s, "longitude", "site.longitude"),
                       number_at(s, "utc_offset", "site.utc_offset"),
                       s.contains("north") ? number_at(s, "north", "site.north") : 0.0};
  sun::validate(site,
                {key_location(kWhere, "site.latitude"), key_location(kWhere, "site.longitude"),
                 key_location(kWhere, "site.utc_offset"), key_location(kWhere, "site.north")});
  return site;
}

}  // namespace

SunRequest parse_sun_request(const nlohmann::json& json, const Scene& scene) {
  SunRequest request;
  request.site = site_of(json, scene);
  if (!json.contains("time") || !json["time"].is_string()) {
    throw InputError(key_location(kWhere, "time"), "expected YYYY-MM-DDTHH:MM");
  }
  request.time = json["time"].get<std::string>();
  sun::parse_local_time(request.time, request.site.utc_offset_hours,
                        key_location(kWhere, "time"));  // checks it
  const std::string date = request.time.substr(0, 10);
  request.day = {date + "T00:00", date + "T23:59", 30};
  if (json.contains("step_minutes")) {
    const double step = number_at(json, "step_minutes", "step_minutes");
    if (!(step >= kMinStepMinutes && step <= 24 * 60 && step == std::round(step))) {
      throw InputError(key_location(kWhere, "step_minutes"), "expected whole minutes, 1 to 1440");
    }
    request.day.step_minutes = step;
  }
  return request;
}

nlohmann::json sun_answer(const SunRequest& request) {
  const sun::SunAngles angles = sun::sun_position(
      request.site, sun::parse_local_time(request.time, request.site.utc_offset_hours, kWhere));
  const Vec3 toward = sun::toward_sun(angles, request.site.north_deg);
  return {{"azimuth_deg", angles.azimuth_deg},
          {"elevation_deg", angles.elevation_deg},
          {"direction", {-toward.x, -toward.y, -toward.z}}};
}

}  // namespace shadowkit::viewer
