// The sun-study-merge command: the shards of one study joined into the files one unsharded
// run writes, byte for byte (sun-study.md).
#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "contract_files.h"
#include "finished_study.h"
#include "shadowkit/app/commands.h"
#include "shadowkit/core/error.h"
#include "shadowkit/scene/scene_file.h"
#include "study_polygons.h"
#include "sunlit_steps.h"

namespace shadowkit {
namespace {

using namespace sun_study;

struct Part {
  fs::path dir;
  nlohmann::json manifest;
};

// The heat map's counts of every shard, added (the shards share the camera: their settings
// are equal).
void merge_counts(const std::vector<Part>& parts, const fs::path& dir) {
  const nlohmann::json& heat_map = parts.front().manifest["heat_map"];
  if (heat_map.is_null()) return;
  const auto pixels = heat_map["width"].get<std::size_t>() * heat_map["height"].get<std::size_t>();
  std::vector<std::uint32_t> sum = read_counts(parts.front().dir / kSunStepCounts, pixels);
  for (std::size_t i = 1; i < parts.size(); ++i) {
    add_counts(read_counts(parts[i].dir / kSunStepCounts, pixels), sum);
  }
  write_counts(dir / kSunStepCounts, sum);
}

// The study's reports, which need its scene: loaded again from where the manifest says. The
// four files stand without them, so a scene that is gone, or no longer the study's, is a
// warning.
void merged_reports(const fs::path& dir, const nlohmann::json& manifest,
                    const std::string& polygons_text, const Context& ctx) {
  const std::string scene_name = manifest["scene"].get<std::string>();
  try {
    const Scene scene = load_scene(scene_name, ctx);
    const Polygons polygons = input_polygons(scene);
    if (polygons_csv(polygons) != polygons_text) {
      ctx.warning(scene_name + ": no reports: the scene's polygons are no longer the study's");
      return;
    }
    write_finished_reports(scene, polygons, dir, manifest);
  } catch (const InputError& e) {
    ctx.warning(std::string("no reports: ") + e.what());
  }
}

int merge_shards(const SunStudyMergeOptions& options, const Context& ctx) {
  if (options.shards.empty()) throw InputError("sun-study-merge", "give the shards' folders");
  if (options.out.empty()) throw InputError("--out", "needs a folder");
  std::vector<Part> parts;
  for (const std::string& d : options.shards) {
    const fs::path path = fs::path(d) / kManifest;
    nlohmann::json manifest;
    try {
      manifest = nlohmann::json::parse(read_file(path));
    } catch (const nlohmann::json::exception& e) {
      throw InputError(path.string(), std::string("not a sun study's manifest: ") + e.what());
    }
    if (!manifest.is_object() || manifest.value("format", "") != "shadowkit sun-study") {
      throw InputError(path.string(), "not a sun study's manifest");
    }
    parts.push_back({d, std::move(manifest)});
  }
  std::sort(parts.begin(), parts.end(), [](const Part& a, const Part& b) {
    return a.manifest["shard"].get<std::int64_t>() < b.manifest["shard"].get<std::int64_t>();
  });
  const nlohmann::json& first = parts.front().manifest;
  const auto shards = first["shards"].get<std::int64_t>();
  if (std::int64_t(parts.size()) != shards) {
    throw InputError(parts.front().dir.string(), "the study has " + std::to_string(shards) +
                                                     " shards; " + std::to_string(parts.size()) +
                                                     " folders were given");
  }
  const std::string polygons_text = read_file(parts.front().dir / kPolygons);
  const std::vector<std::string> keys = row_keys(polygons_text, parts.front().dir / kPolygons);
  const std::size_t P = keys.size();
  std::int64_t next_step = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const nlohmann::json& m = parts[i].manifest;
    const std::string where = (parts[i].dir / kManifest).string();
    if (m["shard"].get<std::int64_t>() != std::int64_t(i) || m["shards"] != first["shards"]) {
      throw InputError(where, "shard " + m["shard"].dump() + "/" + m["shards"].dump() +
                                  " does not fit: the folders must hold shards 0 to " +
                                  std::to_string(shards - 1) + " of one study");
    }
    if (m["study"] != first["study"] || m["polygons"] != first["polygons"]) {
      throw InputError(where,
                       "belongs to another study than " + (parts.front().dir / kManifest).string());
    }
    if (m["first_step"].get<std::int64_t>() != next_step) {
      throw InputError(where, "its steps do not follow the previous shard's");
    }
    next_step += m["step_count"].get<std::int64_t>();
    if (read_file(parts[i].dir / kPolygons) != polygons_text) {
      throw InputError((parts[i].dir / kPolygons).string(), "differs from the first shard's");
    }
  }
  if (next_step != first["study"]["steps"].get<std::int64_t>()) {
    throw InputError(parts.back().dir.string(), "the shards do not cover every step");
  }

  const fs::path dir = options.out;
  std::error_code ec;
  // The merged files replace the folder's own: a shard's folder cannot receive them.
  for (const Part& part : parts) {
    if (fs::equivalent(part.dir, dir, ec)) {
      throw InputError("--out " + options.out, "is one of the shards' folders");
    }
  }
  prepare_folder(dir, "--out", made_files());
  const double step_hours = double(first["study"]["step_seconds"].get<std::int64_t>()) / 3600.0;
  AtomicFile times_file(dir / kTimes);
  times_file.stream() << kTimesHeader;
  std::vector<double> hours(P, 0.0);
  AtomicFile fractions_file(dir / kFractions);
  std::vector<float> row(P);
  std::vector<unsigned char> raw(P * 4);
  for (const Part& part : parts) {
    const auto count = part.manifest["step_count"].get<std::int64_t>();
    const std::string times = read_file(part.dir / kTimes);
    const std::size_t header_end = times.find('\n');
    if (times.rfind(kTimesHeader, 0) != 0 ||
        std::count(times.begin(), times.end(), '\n') != count + 1) {
      throw InputError((part.dir / kTimes).string(), "does not hold the shard's steps");
    }
    times_file.stream() << std::string_view(times).substr(header_end + 1);
    const fs::path f32 = part.dir / kFractions;
    if (fs::file_size(f32, ec) != std::uintmax_t(count) * P * 4) {
      throw InputError(f32.string(), "does not hold the shard's " + std::to_string(count) + " x " +
                                         std::to_string(P) + " values");
    }
    std::ifstream in(f32, std::ios::binary);
    for (std::int64_t k = 0; k < count; ++k) {
      if (!in.read(reinterpret_cast<char*>(raw.data()), std::streamsize(raw.size()))) {
        throw InputError(f32.string(), "cannot read");
      }
      for (std::size_t p = 0; p < P; ++p) {
        row[p] = read_float32_le(&raw[4 * p]);
        // A damaged file's NaN would be summed into sun_hours.csv as "nan".
        if (!(row[p] >= 0 && row[p] <= 1)) {
          throw InputError(f32.string(), "step " + std::to_string(k) + ", polygon " +
                                             std::to_string(p) + ": " + std::to_string(row[p]) +
                                             " is not a fraction from 0 to 1");
        }
      }
      add_sun_hours(row.data(), step_hours, hours);
      fractions_file.stream().write(reinterpret_cast<const char*>(raw.data()),
                                    std::streamsize(raw.size()));
    }
  }
  times_file.commit();
  write_file(dir / kPolygons, polygons_text);
  fractions_file.commit();
  write_file(dir / kSunHours, sun_hours_csv(keys, hours));
  merge_counts(parts, dir);
  nlohmann::json manifest = first;
  manifest["shard"] = 0;
  manifest["shards"] = 1;
  manifest["first_step"] = 0;
  manifest["step_count"] = next_step;
  manifest.erase("timing");
  write_file(dir / kManifest, manifest.dump(2) + "\n");
  merged_reports(dir, manifest, polygons_text, ctx);
  std::printf("%zu shards, %lld steps, %zu polygons: %s\n", parts.size(),
              static_cast<long long>(next_step), P, dir.c_str());
  return 0;
}

}  // namespace

int run_sun_study_merge(const SunStudyMergeOptions& options, const Context& ctx) {
  try {
    return merge_shards(options, ctx);
  } catch (const nlohmann::json::exception& e) {
    // A manifest without the keys a shard writes.
    throw InputError("sun-study-merge",
                     std::string("a shard's sun_study.json is not a sun study's: ") + e.what());
  }
}

}  // namespace shadowkit
