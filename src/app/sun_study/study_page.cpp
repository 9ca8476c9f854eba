#include "study_page.h"

#include <cstdio>

#include "contract_files.h"
#include "markup.h"
#include "shadowkit/app/html.h"
#include "shadowkit/core/error.h"
#include "study_reports.h"

namespace shadowkit::sun_study {
namespace {

namespace fs = std::filesystem;

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:24px;color:#222;max-width:1000px}"
    "table{border-collapse:collapse;margin:8px 0 20px}"
    "td,th{border:1px solid #ccc;padding:4px 10px;text-align:left}th{background:#f2f2f2}"
    "td.n{text-align:right;font-variant-numeric:tabular-nums}"
    "img{max-width:100%;border:1px solid #ccc}figcaption{color:#555;font-size:90%}";

std::string number(double value, const char* format = "%.6g") {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string setting(const std::string& name, const std::string& value) {
  return "<tr><th>" + name + "</th><td>" + value + "</td></tr>\n";
}

std::string size_text(std::uintmax_t bytes) {
  if (bytes < 1024) return std::to_string(bytes) + " B";
  if (bytes < 1024 * 1024) return number(double(bytes) / 1024, "%.1f") + " KiB";
  return number(double(bytes) / (1024 * 1024), "%.1f") + " MiB";
}

// What each of the folder's files holds, for the table of files.
std::string file_content(const std::string& name) {
  if (name == kTimes) return "every step: its instant (UTC) and the sun's azimuth and elevation";
  if (name == kPolygons) return "every polygon: its object, face and area";
  if (name == kFractions) return "steps x polygons sunlit fractions, float32 little-endian";
  if (name == kSunHours) return "every polygon's sun hours";
  if (name == kManifest) return "the study's settings and timings";
  if (name == kEnergyPlusShading) return "EnergyPlus Schedule:File:Shading, a column per surface";
  if (name == kSunHoursPly) return "the scene's faces in colour, with their sun hours";
  if (name == kHeatMap) return "sun hours seen from the scene camera";
  return "";
}

// "Karlsruhe, Germany: " when the scene's site has a name.
std::string site_label(const nlohmann::json& manifest) {
  const std::string name = manifest.value("site_name", "");
  return name.empty() ? "" : html_escaped(name) + ": ";
}

std::string settings_table(const nlohmann::json& manifest) {
  const nlohmann::json& study = manifest.at("study");
  const std::string offset = "UTC" + utc_offset_text(study.at("utc_offset").get<double>());
  std::string rows =
      setting("scene", html_escaped(manifest.at("scene").get<std::string>())) +
      setting("site", site_label(manifest) + number(study.at("lat").get<double>()) + "&deg; N, " +
                          number(study.at("lon").get<double>()) + "&deg; E, north turned " +
                          number(study.at("north").get<double>()) + "&deg;") +
      setting("period", html_escaped(study.at("from").get<std::string>()) + " to " +
                            html_escaped(study.at("to").get<std::string>()) +
                            " local standard time (" + offset + ")") +
      setting("step", number(study.at("step_seconds").get<double>() / 60) + " min, " +
                          std::to_string(study.at("steps").get<std::int64_t>()) + " steps") +
      setting("polygons", std::to_string(manifest.at("polygons").get<std::int64_t>()));
  if (!manifest.contains("timing")) {
    return rows + setting("timings", "not kept: the study was merged from shards");
  }
  const nlohmann::json& timing = manifest.at("timing");
  return rows +
         setting("steps with the sun up",
                 std::to_string(timing.at("daytime_steps").get<std::int64_t>())) +
         setting("scene load", number(timing.at("load_ms").get<double>(), "%.0f") + " ms") +
         setting("scene BSP", number(timing.at("scene_bsp_ms").get<double>(), "%.0f") + " ms") +
         setting("steps", number(timing.at("steps_ms").get<double>(), "%.0f") + " ms, " +
                              number(timing.at("ms_per_daytime_step").get<double>(), "%.2f") +
                              " ms per step with the sun up");
}

std::string files_table(const fs::path& dir, const std::vector<std::string>& reports) {
  std::vector<std::string> names{kTimes, kPolygons, kFractions, kSunHours, kManifest};
  names.insert(names.end(), reports.begin(), reports.end());
  std::string table = "<table>\n<tr><th>file</th><th>size</th><th>holds</th></tr>\n";
  for (const std::string& name : names) {
    std::error_code ec;
    const std::uintmax_t bytes = fs::file_size(dir / name, ec);
    table += "<tr><td><a href=\"" + html_escaped(name) + "\">" + html_escaped(name) +
             "</a></td><td class=\"n\">" + (ec ? "missing" : size_text(bytes)) + "</td><td>" +
             file_content(name) + "</td></tr>\n";
  }
  return table + "</table>\n";
}

std::string plotted_table(const StudyPageContent& content) {
  std::string table =
      "<table>\n<tr><th>polygon</th><th>object</th><th>face</th><th>area</th><th>sun "
      "hours</th></tr>\n";
  for (const StudyPageContent::PlottedPolygon& p : content.plotted) {
    table += "<tr><td class=\"n\">" + std::to_string(p.row) + "</td><td>" + html_escaped(p.object) +
             "</td><td class=\"n\">" + std::to_string(p.face) + "</td><td class=\"n\">" +
             number(p.area) + "</td><td class=\"n\">" + number(p.sun_hours, "%.2f") +
             "</td></tr>\n";
  }
  return table + "</table>\n";
}

std::string page(const fs::path& dir, const StudyPageContent& content) {
  const std::string scene = html_escaped(content.manifest.at("scene").get<std::string>());
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Sun study: " +
      scene + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<h1>Sun study: " + scene +
      "</h1>\n<h2>Settings</h2>\n<table>\n" + settings_table(content.manifest) +
      "</table>\n<h2>Files</h2>\n" + files_table(dir, content.reports);
  if (content.heat_map) {
    html += std::string("<h2>Sun hours from the scene camera</h2>\n<figure><img src=\"") +
            kHeatMap +
            "\" alt=\"sun hours seen from the scene camera, in false colour\">"
            "<figcaption>Dark violet: no sun; pale yellow: the most sun hours of any pixel "
            "(the legend's maximum).</figcaption></figure>\n";
  }
  html += "<h2>Sunlit fraction of the largest polygons</h2>\n";
  if (content.plot_svg.empty()) return html + "<p>No polygon has an area.</p>\n</body>\n</html>\n";
  const std::string note =
      content.steps_per_point == 1
          ? "Each point is one step."
          : "Each point is the mean over a run of " + std::to_string(content.steps_per_point) +
                " consecutive steps, of those with the sun up (0 when it is up at none).";
  return html + content.plot_svg + "<p>" + note + "</p>\n" + plotted_table(content) +
         "</body>\n</html>\n";
}

}  // namespace

std::string study_page(const fs::path& dir, const StudyPageContent& content) {
  try {
    return page(dir, content);
  } catch (const nlohmann::json::exception& e) {
    throw InputError((dir / kManifest).string(),
                     std::string("lacks the study's settings: ") + e.what());
  }
}

}  // namespace shadowkit::sun_study
