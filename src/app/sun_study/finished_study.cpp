#include "finished_study.h"

#include <optional>

#include "energyplus_schedule.h"
#include "heat_map.h"
#include "shading_groups.h"
#include "study_reports.h"
#include "sunlit_steps.h"

namespace shadowkit::sun_study {

std::vector<std::string> made_files() {
  std::vector<std::string> names = report_file_names();
  names.push_back(kSunStepCounts);
  return names;
}

nlohmann::json report_settings(const SunStudyOptions& options) {
  nlohmann::json groups = nullptr;
  if (!options.shading_groups.empty()) groups = fs::absolute(options.shading_groups).string();
  return {{"energyplus_timesteps", options.energyplus_timesteps}, {"shading_groups", groups}};
}

void check_report_options(const SunStudyOptions& options, const Polygons& polygons) {
  check_energyplus_timesteps(options.energyplus_timesteps);
  if (!options.shading_groups.empty()) read_shading_groups(options.shading_groups, polygons);
}

std::vector<std::string> write_finished_reports(const Scene& scene, const Polygons& polygons,
                                                const fs::path& dir,
                                                const nlohmann::json& manifest) {
  const nlohmann::json& study = manifest["study"];
  const nlohmann::json& reports = manifest["reports"];
  std::optional<ShadingGroups> groups;
  if (!reports["shading_groups"].is_null()) {
    groups = read_shading_groups(reports["shading_groups"].get<std::string>(), polygons);
  }
  const double step_hours = double(study["step_seconds"].get<std::int64_t>()) / 3600.0;
  std::optional<SunHoursImage> heat_map;
  if (const nlohmann::json& entry = manifest["heat_map"]; !entry.is_null()) {
    const int width = entry["width"].get<int>(), height = entry["height"].get<int>();
    heat_map = sun_hours_image(read_counts(dir / kSunStepCounts, std::size_t(width) * height),
                               width, height, step_hours);
  }
  const StudyRecord record{scene,
                           polygons,
                           dir,
                           step_hours,
                           study["steps"].get<std::int64_t>(),
                           study["utc_offset"].get<double>(),
                           reports["energyplus_timesteps"].get<int>(),
                           groups ? &*groups : nullptr,
                           heat_map ? &*heat_map : nullptr};
  return write_reports(record);
}

}  // namespace shadowkit::sun_study
