#include "report_test_study.h"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "contract_files.h"
#include "shadowkit/scene/scene_file.h"
#include "shadowkit/scene/sun_position.h"

namespace shadowkit::sun_study {
namespace {

namespace fs = std::filesystem;

// A 1 x 1 and a 1 x 3 square facing up, and a 2 x 1 square facing up with a face of two
// vertices, which the contract keeps as a polygon of area 0.
constexpr const char* kSquares =
    "v 0 0 0\nv 0 0 1\nv 1 0 1\nv 1 0 0\nf 1 2 3 4\n"
    "v 2 0 0\nv 2 0 3\nv 3 0 3\nv 3 0 0\nf 5 6 7 8\n";
constexpr const char* kWall = "v 0 1 0\nv 0 1 1\nv 2 1 1\nv 2 1 0\nf 1 2 3 4\nf 1 2\n";
constexpr const char* kScene = R"({"camera": {"position": [0, 5, 9], "look_at": [0, 0, 0]},
  "objects": [{"mesh": "squares.obj", "name": "Roof"},
              {"mesh": "wall.obj", "name": "wall,east"},
              {"mesh": "wall.obj", "name": "roof", "transform": {"translate": [0, 0, 5]}},
              {"mesh": "squares.obj", "name": "  ", "transform": {"translate": [5, 0, 0]}}]})";

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

}  // namespace

HandStudy::HandStudy(const std::string& name)
    : dir_(fs::temp_directory_path() / ("shadowkit_reports_" + name)) {
  fs::remove_all(dir_);
  fs::create_directories(dir_ / "scene");
  write_text(dir_ / "scene" / "squares.obj", kSquares);
  write_text(dir_ / "scene" / "wall.obj", kWall);
  write_text(dir_ / "scene" / "scene.json", kScene);
  scene_ = load_scene((dir_ / "scene" / "scene.json").string(), {0, [](const std::string&) {}});
  polygons_ = input_polygons(scene_);
}

HandStudy::~HandStudy() {
  fs::remove_all(dir_);
}

void HandStudy::write_study(const std::string& first_utc, int step_minutes,
                            const std::vector<std::vector<float>>& fractions,
                            double utc_offset_hours) {
  const sun::Instant first = sun::parse_utc_time(first_utc + ":00Z", "test");
  const std::size_t polygons = polygons_.rows.size();
  std::string times = kTimesHeader, bytes;
  std::vector<double> hours(polygons, 0.0);
  step_hours_ = step_minutes / 60.0;
  for (std::size_t k = 0; k < fractions.size(); ++k) {
    // The sun is up where a fraction is above 0, as the contract has it.
    const bool sun_up =
        std::any_of(fractions[k].begin(), fractions[k].end(), [](float f) { return f > 0; });
    times += times_row(std::int64_t(k), first + std::chrono::minutes(step_minutes * k),
                       {180, sun_up ? 30.0 : -10.0});
    append_float32_le(fractions[k].data(), polygons, bytes);
    add_sun_hours(fractions[k].data(), step_hours_, hours);
  }
  const std::string polygons_text = polygons_csv(polygons_);
  write_text(dir_ / kTimes, times);
  write_text(dir_ / kFractions, bytes);
  write_text(dir_ / kPolygons, polygons_text);
  write_text(dir_ / kSunHours, sun_hours_csv(row_keys(polygons_text, kPolygons), hours));
  const nlohmann::json manifest = {{"format", "shadowkit sun-study"},
                                   {"contract", 1},
                                   {"scene", "scene/scene.json"},
                                   {"study",
                                    {{"lat", 48},
                                     {"lon", 11},
                                     {"utc_offset", utc_offset_hours},
                                     {"north", 0},
                                     {"from", first_utc},
                                     {"to", first_utc},
                                     {"step_seconds", step_minutes * 60},
                                     {"steps", fractions.size()}}},
                                   {"polygons", polygons},
                                   {"shard", 0},
                                   {"shards", 1},
                                   {"first_step", 0},
                                   {"step_count", fractions.size()},
                                   {"timing",
                                    {{"load_ms", 1.5},
                                     {"scene_bsp_ms", 2.5},
                                     {"steps_ms", 30},
                                     {"daytime_steps", 3},
                                     {"ms_per_daytime_step", 10}}}};
  write_text(dir_ / kManifest, manifest.dump(2) + "\n");
  steps_ = std::int64_t(fractions.size());
  utc_offset_hours_ = utc_offset_hours;
}

StudyRecord HandStudy::record() const {
  return {scene_, polygons_, dir_, step_hours_, steps_, utc_offset_hours_};
}

std::vector<std::string> HandStudy::lines(const std::string& name) const {
  std::ifstream in(dir_ / name, std::ios::binary);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

}  // namespace shadowkit::sun_study
