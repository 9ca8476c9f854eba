#pragma once
// The viewer's sun mode: where the sun stands at a local time, and a day's sun hours.
#include <nlohmann/json.hpp>
#include <string_view>

#include "shadowkit/app/sun_hours.h"
#include "shadowkit/scene/scene.h"
#include "shadowkit/scene/sun_position.h"

namespace shadowkit::viewer {

/// \brief A sun request: a site (the request's `site`, else the scene's) and a local time.
struct SunRequest {
  sun::Site site;
  std::string time;  ///< `time`, YYYY-MM-DDTHH:MM local standard time
  SunSpan day;       ///< the whole day of `time`, in steps of `step_minutes` (default 30)
};

/// The most steps a day's sun hours may take: one a minute.
inline constexpr double kMinStepMinutes = 1;

/// Reads a sun request's `site`, `time` and `step_minutes` (docs/commands.md, "serve") from
/// parse_request_json()'s object; InputError names the key at fault.
SunRequest parse_sun_request(const nlohmann::json& json, const Scene& scene);

/// The sun at the request's time: azimuth, elevation, and the direction a directional light
/// of the scene file takes to be that sun.
nlohmann::json sun_answer(const SunRequest& request);

}  // namespace shadowkit::viewer
