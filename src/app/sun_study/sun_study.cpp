// The sun-study command: the contract's time steps, polygons and files (sun-study.md). The
// sunlit areas are svbsp's; the sun's position is the scene layer's.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "contract_files.h"
#include "finished_study.h"
#include "interruption.h"
#include "shadowkit/app/commands.h"
#include "shadowkit/app/progress.h"
#include "shadowkit/core/error.h"
#include "shadowkit/methods/svbsp.h"
#include "shadowkit/scene/scene_file.h"
#include "shadowkit/scene/sun_position.h"
#include "study_polygons.h"
#include "study_site.h"
#include "study_steps.h"
#include "sunlit_steps.h"

namespace shadowkit {
namespace {

using namespace sun_study;
using Clock = std::chrono::steady_clock;

// Fractions held in memory at once: steps are computed in blocks of about this many values
// and written in step order, so memory does not grow with the study's length.
constexpr std::size_t kBlockValues = std::size_t(1) << 22;
// Steps computed between two progress lines, at most.
constexpr std::size_t kMaxBlockSteps = 64;
// The widest heat map: 8K UHD.
constexpr int kMaxHeatMapWidth = 7680;

// What the merge checks shards against: every setting that changes the files it joins.
nlohmann::json study_settings(const SunStudyOptions& options, const sun::Site& site,
                              const Steps& steps) {
  return {{"lat", site.latitude_deg},
          {"lon", site.longitude_deg},
          {"utc_offset", site.utc_offset_hours},
          {"north", site.north_deg},
          {"from", options.from},
          {"to", options.to},
          {"step_seconds", steps.step_seconds},
          {"heat_map_width", options.heat_map_width},
          {"steps", steps.count}};
}

// "sun study: 1200 of 8760 steps, 41 steps/s, 3 min left".
std::string progress_line(std::int64_t done, std::int64_t total, Clock::duration elapsed) {
  const double seconds = std::chrono::duration<double>(elapsed).count();
  const double rate = seconds > 0 ? double(done) / seconds : 0;
  const double left = rate > 0 ? double(total - done) / rate : 0;
  char line[160];
  std::snprintf(line, sizeof line, "sun study: %lld of %lld steps, %.0f steps/s, %s left",
                static_cast<long long>(done), static_cast<long long>(total), rate,
                left >= 90 ? (std::to_string(std::lround(left / 60)) + " min").c_str()
                           : (std::to_string(std::lround(left)) + " s").c_str());
  return line;
}

// The scene as the merge can load it again from another folder: a file by its absolute
// path, a built-in scene by its name.
std::string scene_reference(const std::string& scene) {
  std::error_code ec;
  return fs::is_regular_file(scene, ec) ? fs::absolute(scene).string() : scene;
}

nlohmann::json heat_map_entry(const Camera& camera, bool counted) {
  if (!counted) return nullptr;
  return {{"width", camera.width}, {"height", camera.height}, {"counts", kSunStepCounts}};
}

// The heat map's camera: the scene's, \p width pixels across, its aspect kept.
void heat_map_size(int width, Camera& camera) {
  const double aspect = double(camera.height) / camera.width;
  camera.width = width;
  camera.height = std::max(1, int(std::lround(width * aspect)));
}

void refuse_subdivision(const Scene& scene, const std::string& where) {
  for (const SceneObject& object : scene.objects) {
    if (object.subdivision) {
      throw InputError(
          where + ": object " + std::to_string(object.input_object) + " (" + object.name + ")",
          "is a subdivision surface; sun-study v1 covers plain meshes only");
    }
  }
}

}  // namespace

int run_sun_study(const SunStudyOptions& options, const Context& ctx) {
  // Every option is checked before the scene is read, and the site the scene completes right
  // after it, all before DIR is touched. The steps' checks hold at any UTC offset but for
  // the years of the first and last step in UTC, checked again once the site's offset is known.
  check_site_options(options);
  if (!options.settings.empty()) {
    throw InputError("--set",
                     "sun-study takes no method settings: its fractions are svbsp's exact "
                     "fragments, whatever the settings");
  }
  if (options.heat_map_width < 0 || options.heat_map_width > kMaxHeatMapWidth) {
    throw InputError("--heat-map-width",
                     "must be 0 (none) to " + std::to_string(kMaxHeatMapWidth) + " pixels");
  }
  const Shard shard =
      study_shard(options.shard, study_steps(options, options.utc_offset_hours.value_or(0)).count);
  if (options.out.empty()) throw InputError("--out", "needs a folder");

  const Clock::time_point load_start = Clock::now();
  Scene scene = load_scene(options.scene, ctx);  // its lights are ignored
  if (options.heat_map_width > 0) heat_map_size(options.heat_map_width, scene.camera);
  const sun::Site site = study_site(options, scene.site);
  const Steps steps = study_steps(options, site.utc_offset_hours);
  refuse_subdivision(scene, options.scene);
  const Polygons polygons = input_polygons(scene);
  check_report_options(options, polygons);
  const Clock::time_point bsp_start = Clock::now();
  const svbsp::SunlitAreas sunlit(scene);
  std::optional<SunlitStepCounts> heat_map;
  if (options.heat_map_width > 0) heat_map.emplace(scene, ctx);
  const Clock::time_point steps_start = Clock::now();

  const fs::path dir = options.out;
  prepare_folder(dir, "--out", made_files());

  const std::size_t P = polygons.rows.size();
  const std::string polygons_text = polygons_csv(polygons);
  AtomicFile fractions_file(dir / kFractions);
  AtomicFile times_file(dir / kTimes);
  times_file.stream() << kTimesHeader;
  std::vector<double> hours(P, 0.0);
  const std::size_t block =
      std::clamp<std::size_t>(kBlockValues / std::max<std::size_t>(P, 1), 1, kMaxBlockSteps);
  Progress progress;
  const Interruption interruption;
  std::vector<float> values;
  std::vector<sun::SunAngles> angles;
  std::string bytes;
  std::int64_t daytime = 0;
  for (std::int64_t first = shard.first; first < shard.end; first += std::int64_t(block)) {
    const auto n = std::size_t(std::min<std::int64_t>(std::int64_t(block), shard.end - first));
    values.assign(n * P, 0.0f);
    angles.assign(n, {});
    // Each step is computed whole by one thread, so its values never depend on threads.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1), [&](const auto& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        angles[i] = sun::sun_position(site, steps.at(first + std::int64_t(i)));
        // At or below the horizon every fraction is 0: nothing to compute.
        if (angles[i].elevation_deg <= 0) continue;
        const Vec3 toward_sun = sun::toward_sun(angles[i], site.north_deg);
        const std::vector<double> lit =
            heat_map ? heat_map->lit_areas(sunlit, toward_sun) : sunlit.lit_areas(toward_sun);
        sunlit_fractions(polygons, lit, toward_sun, values.data() + i * P);
      }
    });
    bytes.clear();
    for (std::size_t i = 0; i < n; ++i) {
      const std::int64_t k = first + std::int64_t(i);
      times_file.stream() << times_row(k, steps.at(k), angles[i]);
      daytime += angles[i].elevation_deg > 0;
      add_sun_hours(values.data() + i * P, steps.step_hours(), hours);
      append_float32_le(values.data() + i * P, P, bytes);
    }
    fractions_file.stream().write(bytes.data(), std::streamsize(bytes.size()));
    interruption.check();
    progress.step(progress_line(first + std::int64_t(n) - shard.first, shard.end - shard.first,
                                Clock::now() - steps_start));
  }
  const Clock::time_point steps_end = Clock::now();

  std::vector<std::string> keys = row_keys(polygons_text, kPolygons);
  times_file.commit();
  write_file(dir / kPolygons, polygons_text);
  fractions_file.commit();
  write_file(dir / kSunHours, sun_hours_csv(keys, hours));
  if (heat_map) write_counts(dir / kSunStepCounts, heat_map->counts());

  auto ms = [](Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); };
  const double steps_ms = ms(steps_end - steps_start);
  const double per_step = daytime > 0 ? steps_ms / double(daytime) : 0.0;
  nlohmann::json manifest = {{"format", "shadowkit sun-study"},
                             {"contract", 1},
                             {"scene", scene_reference(options.scene)},
                             {"study", study_settings(options, site, steps)},
                             {"site_name", scene.site_name},
                             {"polygons", P},
                             {"shard", shard.index},
                             {"shards", shard.count},
                             {"first_step", shard.first},
                             {"step_count", shard.end - shard.first},
                             {"heat_map", heat_map_entry(scene.camera, heat_map.has_value())},
                             {"reports", report_settings(options)},
                             {"timing",
                              {{"threads", tbb::this_task_arena::max_concurrency()},
                               {"load_ms", ms(bsp_start - load_start)},
                               {"scene_bsp_ms", ms(steps_start - bsp_start)},
                               {"steps_ms", steps_ms},
                               {"daytime_steps", daytime},
                               {"ms_per_daytime_step", per_step}}}};
  write_file(dir / kManifest, manifest.dump(2) + "\n");
  // A shard's reports would cover its steps only: the merge writes the study's.
  if (shard.count == 1) write_finished_reports(scene, polygons, dir, manifest);
  std::printf(
      "%lld of %lld steps (%lld with the sun up), %zu polygons: %.1f ms per daytime step "
      "(scene BSP %.0f ms): %s\n",
      static_cast<long long>(shard.end - shard.first), static_cast<long long>(steps.count),
      static_cast<long long>(daytime), P, per_step, ms(steps_start - bsp_start), dir.c_str());
  return 0;
}

}  // namespace shadowkit
