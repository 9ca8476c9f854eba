#include "study_reports.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "contract_files.h"
#include "energyplus_schedule.h"
#include "fraction_plot.h"
#include "fraction_stream.h"
#include "shadowkit/core/error.h"
#include "study_page.h"
#include "sun_hours_ply.h"

namespace shadowkit::sun_study {
namespace {

// The chart follows the largest polygons, each as a line of at most this many points.
constexpr std::size_t kPlottedPolygons = 8;
constexpr std::size_t kPlotPoints = 2000;

nlohmann::json read_manifest(const fs::path& dir) {
  const fs::path path = dir / kManifest;
  try {
    return nlohmann::json::parse(read_file(path));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path.string(), std::string("not a sun study's manifest: ") + e.what());
  }
}

// The scene object each row of polygons.csv belongs to: objects hold consecutive rows.
std::vector<const SceneObject*> objects_of_rows(const Scene& scene) {
  std::vector<const SceneObject*> objects;
  for (const SceneObject& object : scene.objects) {
    objects.insert(objects.end(), object.mesh.input_face_count(), &object);
  }
  return objects;
}

/// \brief The reports made while the steps stream by: the schedule, the chart's series and
/// every polygon's sun hours.
struct StreamedReports {
  FractionSeries series;
  std::vector<double> hours;
};

StreamedReports stream_steps(const StudyRecord& record, FractionStream& steps,
                             std::ostream& schedule_out) {
  SHADOWKIT_CHECK(steps.next());  // a study has one step at least
  const std::int64_t step_seconds = std::llround(record.step_hours * 3600);
  EnergyPlusSchedule schedule(
      schedule_out, shading_columns(record.scene, record.polygons, record.shading_groups),
      steps.instant(0), record.utc_offset_hours, step_seconds, record.energyplus_timesteps);
  StreamedReports reports{FractionSeries(largest_polygons(record.polygons, kPlottedPolygons),
                                         record.steps, step_seconds, kPlotPoints),
                          std::vector<double>(record.polygons.rows.size(), 0.0)};
  do {
    for (std::size_t i = 0; i < steps.size(); ++i) {
      schedule.add_step(steps.instant(i), steps.fractions(i));
      reports.series.add_step(steps.instant(i), steps.sun_up(i), steps.fractions(i));
      // As the contract's sun_hours.csv adds them, so the PLY's hours are the file's.
      add_sun_hours(steps.fractions(i), record.step_hours, reports.hours);
    }
  } while (steps.next());
  schedule.finish();
  return reports;
}

StudyPageContent page_content(const StudyRecord& record, const StreamedReports& streamed) {
  StudyPageContent content;
  content.manifest = read_manifest(record.dir);
  content.heat_map = record.heat_map != nullptr;
  const std::vector<std::uint32_t>& rows = streamed.series.polygons();
  if (rows.empty()) return content;
  const std::vector<const SceneObject*> objects = objects_of_rows(record.scene);
  std::vector<std::string> labels;
  for (const std::uint32_t p : rows) {
    const Polygons::Row& row = record.polygons.rows[p];
    content.plotted.push_back({p, objects[p]->name, row.face, row.area, streamed.hours[p]});
    labels.push_back("polygon " + std::to_string(p) + ": " + objects[p]->name + ", face " +
                     std::to_string(row.face));
  }
  content.plot_svg = fraction_plot_svg(streamed.series, labels, record.utc_offset_hours);
  content.steps_per_point = streamed.series.steps_per_point();
  return content;
}

}  // namespace

std::vector<std::string> report_file_names() {
  return {kEnergyPlusShading, kSunHoursPly, kHeatMap, kStudyPage};
}

std::vector<std::string> write_reports(const StudyRecord& record) {
  check_energyplus_timesteps(record.energyplus_timesteps);
  SHADOWKIT_CHECK(record.polygons.row_of_face.size() == record.scene.face_count());
  std::vector<std::string> written;
  // The folder's files are checked against the record before anything is written.
  FractionStream steps(record.dir, record.steps, record.polygons.rows.size());
  AtomicFile schedule(record.dir / kEnergyPlusShading);
  const StreamedReports streamed = stream_steps(record, steps, schedule.stream());
  schedule.commit();
  written.push_back(kEnergyPlusShading);

  AtomicFile ply(record.dir / kSunHoursPly);
  write_sun_hours_ply(ply.stream(), record.scene, record.polygons, streamed.hours);
  ply.commit();
  written.push_back(kSunHoursPly);

  if (record.heat_map) {
    write_file(record.dir / kHeatMap, encode_png(heat_map_image(*record.heat_map)));
    written.push_back(kHeatMap);
  }
  StudyPageContent content = page_content(record, streamed);
  content.reports = written;
  write_file(record.dir / kStudyPage, study_page(record.dir, content));
  written.push_back(kStudyPage);
  return written;
}

}  // namespace shadowkit::sun_study
