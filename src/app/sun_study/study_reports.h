#pragma once
// The study's reports beside the contract's files (docs/commands.md, "Reports"): an
// EnergyPlus shading schedule, the scene's faces with their sun hours as PLY, a heat map of
// sun hours from the scene camera, and an HTML page tying them together.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "heat_map.h"
#include "shading_groups.h"
#include "shadowkit/scene/scene.h"
#include "study_polygons.h"

namespace shadowkit::sun_study {

namespace fs = std::filesystem;

constexpr const char* kEnergyPlusShading = "energyplus_shading.csv";
constexpr const char* kSunHoursPly = "sun_hours.ply";
constexpr const char* kHeatMap = "sun_hours_map.png";
constexpr const char* kStudyPage = "index.html";

/// \brief What the reports are made of: the study in memory and its folder of files.
struct StudyRecord {
  const Scene& scene;
  const Polygons& polygons;
  fs::path dir;  ///< holds the contract's four files and sun_study.json, complete
  double step_hours = 0;
  std::int64_t steps = 0;  ///< T, every step of the study
  double utc_offset_hours = 0;
  /// Rows per hour of the EnergyPlus schedule: the IDF's Timestep (1, 2, 3, 4, 5, 6, 10, 12,
  /// 15, 20, 30 or 60), which EnergyPlus requires the file to match.
  int energyplus_timesteps = 1;
  const ShadingGroups* shading_groups = nullptr;  ///< null: a column per scene object only
  const SunHoursImage* heat_map = nullptr;        ///< null: no heat map
};

/// Every file write_reports() may write, for prepare_folder() to clear before a run.
std::vector<std::string> report_file_names();

/// Writes the reports into record.dir, each under a temporary name renamed into place when
/// complete, and returns the names written. Reads the fractions in bounded blocks of steps.
/// InputError when the folder's files do not hold the study the record describes, or for a
/// bad energyplus_timesteps.
std::vector<std::string> write_reports(const StudyRecord& record);

}  // namespace shadowkit::sun_study
