#pragma once
// The reports of a finished study, from its folder and the settings its manifest records, so
// that one run and the merge of its shards write the same reports.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "shadowkit/app/commands.h"
#include "study_polygons.h"
#include "study_steps.h"

namespace shadowkit::sun_study {

/// Every file a study writes beside the contract's four and its manifest: the heat map's
/// counts and the reports, for prepare_folder() to clear.
std::vector<std::string> made_files();

/// What the manifest records for the reports: --energyplus-timesteps and the absolute path
/// of --shading-groups (null: none).
nlohmann::json report_settings(const SunStudyOptions& options);

/// Checks the report options before any step runs: InputError naming the option or the
/// groups' file and line.
void check_report_options(const SunStudyOptions& options, const Polygons& polygons);

/// Writes the reports of the complete study in \p dir (its four files, its manifest
/// \p manifest and, when the manifest names one, its heat map's counts).
std::vector<std::string> write_finished_reports(const Scene& scene, const Polygons& polygons,
                                                const std::filesystem::path& dir,
                                                const nlohmann::json& manifest);

}  // namespace shadowkit::sun_study
