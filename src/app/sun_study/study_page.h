#pragma once
// The study's HTML page: its settings and timings, its files, the heat map and a chart of the
// largest polygons' sunlit fractions. Self-contained: no script, nothing fetched.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace shadowkit::sun_study {

/// \brief What the page shows besides the files it lists.
struct StudyPageContent {
  nlohmann::json manifest;           ///< sun_study.json
  std::vector<std::string> reports;  ///< the report files written before the page
  bool heat_map = false;             ///< whether sun_hours_map.png is among them
  std::string plot_svg;              ///< empty: no polygon has area
  std::int64_t steps_per_point = 1;  ///< the chart's steps per point
  struct PlottedPolygon {
    std::uint32_t row = 0;
    std::string object;  ///< the scene object's name
    std::uint32_t face = 0;
    double area = 0, sun_hours = 0;
  };
  std::vector<PlottedPolygon> plotted;  ///< in the chart's order
};

/// The page of the study in \p dir, linking its files by name (it sits beside them).
/// InputError naming sun_study.json when the manifest lacks the study's settings.
std::string study_page(const std::filesystem::path& dir, const StudyPageContent& content);

}  // namespace shadowkit::sun_study
