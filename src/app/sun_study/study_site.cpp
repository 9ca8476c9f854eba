#include "study_site.h"

#include <string>

#include "shadowkit/core/error.h"

namespace shadowkit::sun_study {
namespace {

double given_or_scene(const std::optional<double>& given,
                      const std::optional<sun::Site>& scene_site, double sun::Site::*field,
                      const std::string& option, const std::string& key) {
  if (given) return *given;
  if (scene_site) return (*scene_site).*field;
  throw InputError(option, "not given and the scene has no site." + key);
}

}  // namespace

void check_site_options(const SunStudyOptions& options) {
  // An option not given stands in as 0, which every field's range holds.
  sun::validate({options.latitude_deg.value_or(0), options.longitude_deg.value_or(0),
                 options.utc_offset_hours.value_or(0), options.north_deg.value_or(0)});
}

sun::Site study_site(const SunStudyOptions& options, const std::optional<sun::Site>& scene_site) {
  // Braced initialisers run in order, so the first missing option is the one named.
  return {given_or_scene(options.latitude_deg, scene_site, &sun::Site::latitude_deg, "--lat",
                         "latitude"),
          given_or_scene(options.longitude_deg, scene_site, &sun::Site::longitude_deg, "--lon",
                         "longitude"),
          given_or_scene(options.utc_offset_hours, scene_site, &sun::Site::utc_offset_hours,
                         "--utc-offset", "utc_offset"),
          options.north_deg.value_or(scene_site ? scene_site->north_deg : 0.0)};
}

}  // namespace shadowkit::sun_study
