// The sun-study and sun-study-merge commands: the contract's time steps, files and shards
// (sun-study.md). The sunlit areas are svbsp's; the sun's position is the scene layer's.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "shadowkit/app/commands.h"
#include "shadowkit/core/error.h"
#include "shadowkit/methods/svbsp.h"
#include "shadowkit/scene/scene_file.h"
#include "shadowkit/scene/sun_position.h"

namespace shadowkit {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The study's size in steps is bounded so that indices and the file of fractions stay in
// reach: 19 years at one-minute steps.
constexpr std::int64_t kMaxSteps = 10'000'000;
// The most shards a study is cut into.
constexpr std::int64_t kMaxShards = 1'000'000;
// Fractions held in memory at once: steps are computed in blocks of about this many values
// and written in step order, so memory does not grow with the study's length.
constexpr std::size_t kBlockValues = std::size_t(1) << 22;
// "The sun is behind or in the polygon's plane", with svbsp's tolerance for a directional
// light in a face's plane (SceneBsp::kRelativeTolerance): a face whose plane holds the sun
// within it has no lit area either.
constexpr double kInPlane = 1e-9;

constexpr const char* kTimes = "times.csv";
constexpr const char* kPolygons = "polygons.csv";
constexpr const char* kFractions = "sunlit_fraction.f32";
constexpr const char* kSunHours = "sun_hours.csv";
constexpr const char* kManifest = "sun_study.json";
constexpr const char* kTimesHeader = "index,time_utc,azimuth_deg,elevation_deg\n";

// The contract's numbers: plain decimals with a dot, no exponent, at least 6 significant
// digits. The shortest text that reads back as the same double, in fixed notation, then
// padded with zeros to 6 significant digits (0.5 -> 0.500000, 1e-7 -> 0.000000100000).
std::string decimal(double x) {
  if (x == 0) return "0.000000";  // also -0
  char buffer[400];               // the longest fixed double, 5e-324, takes 326 characters
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::fixed).ptr;
  std::string text(buffer, end);
  std::size_t significant = 0;
  bool started = false;
  for (const char c : text) {
    if (c < '0' || c > '9') continue;
    started = started || c != '0';
    significant += started;
  }
  if (significant >= 6) return text;
  if (text.find('.') == std::string::npos) text += '.';
  return text + std::string(6 - significant, '0');
}

// Sun hours: each step's fraction, as stored in float32, times the step's length, summed in
// step order. The merge sums the merged file the same way, so the bytes agree.
void add_sun_hours(const float* fractions, double step_hours, std::vector<double>& hours) {
  for (std::size_t p = 0; p < hours.size(); ++p) hours[p] += double(fractions[p]) * step_hours;
}

void append_float32_le(const float* values, std::size_t count, std::string& out) {
  for (std::size_t i = 0; i < count; ++i) {
    const auto bits = std::bit_cast<std::uint32_t>(values[i]);
    for (int b = 0; b < 4; ++b) out.push_back(char((bits >> (8 * b)) & 0xff));
  }
}

float read_float32_le(const unsigned char* bytes) {
  const std::uint32_t bits = std::uint32_t(bytes[0]) | std::uint32_t(bytes[1]) << 8 |
                             std::uint32_t(bytes[2]) << 16 | std::uint32_t(bytes[3]) << 24;
  return std::bit_cast<float>(bits);
}

// A file written under a temporary name in its folder and renamed into place when complete:
// an interrupted run leaves no half-written file under the contract's name.
class AtomicFile {
 public:
  explicit AtomicFile(fs::path path) : path_(std::move(path)) {
    temporary_ = path_;
    temporary_ += ".partial";
    out_.open(temporary_, std::ios::binary | std::ios::trunc);
    if (!out_) throw InputError(temporary_.string(), "cannot open for writing");
  }
  std::ofstream& stream() { return out_; }
  void commit() {
    out_.close();
    if (!out_) throw InputError(temporary_.string(), "write failed");
    std::error_code ec;
    fs::rename(temporary_, path_, ec);
    if (ec) throw InputError(path_.string(), "cannot rename into place: " + ec.message());
  }

 private:
  fs::path path_, temporary_;
  std::ofstream out_;
};

void write_file(const fs::path& path, const std::string& text) {
  AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot open");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// ---- the study's steps ----

struct Steps {
  sun::Instant from;
  std::int64_t step_seconds = 0;
  std::int64_t count = 0;  ///< T, every step of the study
  sun::Instant at(std::int64_t k) const { return from + std::chrono::seconds(k * step_seconds); }
  double step_hours() const { return double(step_seconds) / 3600.0; }
};

Steps study_steps(const SunStudyOptions& options) {
  Steps steps;
  steps.from = sun::parse_local_time(options.from, options.utc_offset_hours, "--from");
  const sun::Instant to = sun::parse_local_time(options.to, options.utc_offset_hours, "--to");
  const double seconds = options.step_minutes * 60;
  if (!(options.step_minutes > 0) || !std::isfinite(seconds)) {
    throw InputError("--step", "must be a positive number of minutes");
  }
  if (seconds != std::round(seconds)) {
    throw InputError("--step",
                     "must be a whole number of seconds (times are written to the "
                     "second)");
  }
  if (steps.from > to) throw InputError("--from", options.from + " is after --to " + options.to);
  const std::int64_t span = (to - steps.from).count();
  if (double(span) / seconds >= double(kMaxSteps)) {
    throw InputError("--step", "makes more than " + std::to_string(kMaxSteps) +
                                   " steps between --from and --to");
  }
  steps.step_seconds = std::int64_t(seconds);
  steps.count = span / steps.step_seconds + 1;
  return steps;
}

struct Shard {
  std::int64_t index = 0, count = 1;
  std::int64_t first = 0, end = 0;  ///< its block of steps, [first, end)
};

Shard study_shard(const std::string& text, std::int64_t steps) {
  Shard shard;
  if (!text.empty()) {
    const std::size_t slash = text.find('/');
    auto parse = [&](std::string_view part, std::int64_t& value) {
      const auto [ptr, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
      return ec == std::errc() && ptr == part.data() + part.size() && !part.empty();
    };
    const std::string_view view(text);
    if (slash == std::string::npos || !parse(view.substr(0, slash), shard.index) ||
        !parse(view.substr(slash + 1), shard.count)) {
      throw InputError("--shard", "expected I/N with whole numbers 0 <= I < N, got '" + text + "'");
    }
    if (shard.count < 1 || shard.count > kMaxShards || shard.index < 0 ||
        shard.index >= shard.count) {
      throw InputError(
          "--shard", "'" + text + "': I/N needs 0 <= I < N and N <= " + std::to_string(kMaxShards));
    }
  }
  // The I-th of N contiguous blocks whose sizes differ by one at most.
  shard.first = shard.index * steps / shard.count;
  shard.end = (shard.index + 1) * steps / shard.count;
  return shard;
}

// ---- the contract's polygons ----

// The input polygons (faces as read, in file order) and the scene faces each became.
struct Polygons {
  struct Row {
    std::uint32_t object = 0, face = 0;
    double area = 0;  ///< world units
    Vec3 normal;      ///< the sum of its faces' normals times their areas: Newell's normal
  };
  std::vector<Row> rows;
  std::vector<std::uint32_t> row_of_face;  ///< per global scene face
};

Polygons input_polygons(const Scene& scene) {
  Polygons polygons;
  polygons.row_of_face.resize(scene.face_count());
  const double scale2 = scene.frame.scale * scene.frame.scale;
  for (const SceneObject& object : scene.objects) {
    const Mesh& mesh = object.mesh;
    SHADOWKIT_CHECK(mesh.input_faces.size() == mesh.face_count());
    const auto first_row = std::uint32_t(polygons.rows.size());
    for (std::size_t k = 0; k < mesh.input_face_count(); ++k) {
      polygons.rows.push_back(
          {object.input_object, object.input_first_face + std::uint32_t(k), 0, {}});
    }
    // A planar face is its polygon; a warped polygon's triangles sum to its area and, as
    // vector areas, to its Newell normal. A dropped (degenerate) face keeps area 0.
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      const std::uint32_t row = first_row + mesh.input_faces[f];
      polygons.row_of_face[object.first_face + f] = row;
      polygons.rows[row].area += mesh.areas[f] * scale2;
      polygons.rows[row].normal += mesh.planes[f].normal * mesh.areas[f];
    }
  }
  return polygons;
}

std::string polygons_csv(const Polygons& polygons) {
  std::string text = "index,object,face,area\n";
  for (std::size_t p = 0; p < polygons.rows.size(); ++p) {
    const Polygons::Row& row = polygons.rows[p];
    text += std::to_string(p) + "," + std::to_string(row.object) + "," + std::to_string(row.face) +
            "," + decimal(row.area) + "\n";
  }
  return text;
}

// The sunlit fraction of every polygon for the sun toward \p toward_sun (above the horizon).
void sunlit_fractions(const svbsp::SunlitAreas& sunlit, const Polygons& polygons, Vec3 toward_sun,
                      float* out) {
  const std::vector<double> lit = sunlit.lit_areas(toward_sun);
  std::vector<double> sum(polygons.rows.size(), 0.0);
  for (std::size_t face = 0; face < lit.size(); ++face)
    sum[polygons.row_of_face[face]] += lit[face];
  for (std::size_t p = 0; p < polygons.rows.size(); ++p) {
    const Polygons::Row& row = polygons.rows[p];
    // The front side only: the sun behind or in the polygon's plane gives 0 (the contract),
    // although svbsp's two-sided surfaces light the back.
    const bool front = dot(row.normal, toward_sun) > kInPlane * length(row.normal);
    out[p] = front && row.area > 0 ? float(std::clamp(sum[p] / row.area, 0.0, 1.0)) : 0.0f;
  }
}

std::string times_row(std::int64_t k, sun::Instant t, const sun::SunAngles& angles) {
  return std::to_string(k) + "," + sun::format_utc_time(t) + "," + decimal(angles.azimuth_deg) +
         "," + decimal(angles.elevation_deg) + "\n";
}

std::string sun_hours_csv(const std::vector<std::string>& row_keys,
                          const std::vector<double>& hours) {
  std::string text = "index,object,face,sun_hours\n";
  for (std::size_t p = 0; p < hours.size(); ++p) {
    text += row_keys[p] + "," + decimal(hours[p]) + "\n";
  }
  return text;
}

// "index,object,face" of every row of polygons.csv, the start of sun_hours.csv's rows.
std::vector<std::string> row_keys(const std::string& polygons_text, const std::string& where) {
  std::vector<std::string> keys;
  std::istringstream in(polygons_text);
  std::string line;
  std::getline(in, line);
  if (line != "index,object,face,area") throw InputError(where, "not a sun study's polygons.csv");
  while (std::getline(in, line)) {
    const std::size_t comma = line.rfind(',');
    if (comma == std::string::npos) throw InputError(where, "malformed row '" + line + "'");
    keys.push_back(line.substr(0, comma));
  }
  return keys;
}

// What the merge checks shards against: every setting that changes the four files.
nlohmann::json study_settings(const SunStudyOptions& options, const Steps& steps) {
  return {{"lat", options.latitude_deg},
          {"lon", options.longitude_deg},
          {"utc_offset", options.utc_offset_hours},
          {"north", options.north_deg},
          {"from", options.from},
          {"to", options.to},
          {"step_seconds", steps.step_seconds},
          {"steps", steps.count}};
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
  // Every option is checked before the scene is read and before DIR is touched.
  sun::validate(
      {options.latitude_deg, options.longitude_deg, options.utc_offset_hours, options.north_deg});
  const Steps steps = study_steps(options);
  const Shard shard = study_shard(options.shard, steps.count);
  if (options.out.empty()) throw InputError("--out", "needs a folder");
  const sun::Site site{options.latitude_deg, options.longitude_deg, options.utc_offset_hours,
                       options.north_deg};

  const Clock::time_point load_start = Clock::now();
  const Scene scene = load_scene(options.scene, ctx);  // its lights are ignored
  refuse_subdivision(scene, options.scene);
  const Polygons polygons = input_polygons(scene);
  const Clock::time_point bsp_start = Clock::now();
  const svbsp::SunlitAreas sunlit(scene);
  const Clock::time_point steps_start = Clock::now();

  const fs::path dir = options.out;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!fs::is_directory(dir)) throw InputError("--out " + options.out, "cannot create the folder");
  // Results of an earlier run go first: the folder never mixes two runs' files.
  for (const char* name : {kTimes, kPolygons, kFractions, kSunHours, kManifest}) {
    fs::remove(dir / name, ec);
  }

  const std::size_t P = polygons.rows.size();
  const std::string polygons_text = polygons_csv(polygons);
  AtomicFile fractions_file(dir / kFractions);
  AtomicFile times_file(dir / kTimes);
  times_file.stream() << kTimesHeader;
  std::vector<double> hours(P, 0.0);
  const std::size_t block = std::max<std::size_t>(1, kBlockValues / std::max<std::size_t>(P, 1));
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
        sunlit_fractions(sunlit, polygons, sun::toward_sun(angles[i], site.north_deg),
                         values.data() + i * P);
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
  }
  const Clock::time_point steps_end = Clock::now();

  std::vector<std::string> keys = row_keys(polygons_text, kPolygons);
  times_file.commit();
  write_file(dir / kPolygons, polygons_text);
  fractions_file.commit();
  write_file(dir / kSunHours, sun_hours_csv(keys, hours));

  auto ms = [](Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); };
  const double steps_ms = ms(steps_end - steps_start);
  const double per_step = daytime > 0 ? steps_ms / double(daytime) : 0.0;
  nlohmann::json manifest = {{"format", "shadowkit sun-study"},
                             {"contract", 1},
                             {"scene", options.scene},
                             {"study", study_settings(options, steps)},
                             {"polygons", P},
                             {"shard", shard.index},
                             {"shards", shard.count},
                             {"first_step", shard.first},
                             {"step_count", shard.end - shard.first},
                             {"timing",
                              {{"load_ms", ms(bsp_start - load_start)},
                               {"scene_bsp_ms", ms(steps_start - bsp_start)},
                               {"steps_ms", steps_ms},
                               {"daytime_steps", daytime},
                               {"ms_per_daytime_step", per_step}}}};
  write_file(dir / kManifest, manifest.dump(2) + "\n");
  std::printf(
      "%lld of %lld steps (%lld with the sun up), %zu polygons: %.1f ms per daytime step "
      "(scene BSP %.0f ms): %s\n",
      static_cast<long long>(shard.end - shard.first), static_cast<long long>(steps.count),
      static_cast<long long>(daytime), P, per_step, ms(steps_start - bsp_start), dir.c_str());
  return 0;
}

namespace {

int merge_shards(const SunStudyMergeOptions& options) {
  if (options.shards.empty()) throw InputError("sun-study-merge", "give the shards' folders");
  if (options.out.empty()) throw InputError("--out", "needs a folder");
  struct Part {
    fs::path dir;
    nlohmann::json manifest;
  };
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
  fs::create_directories(dir, ec);
  if (!fs::is_directory(dir)) throw InputError("--out " + options.out, "cannot create the folder");
  for (const char* name : {kTimes, kPolygons, kFractions, kSunHours, kManifest}) {
    fs::remove(dir / name, ec);
  }
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
      for (std::size_t p = 0; p < P; ++p) row[p] = read_float32_le(&raw[4 * p]);
      add_sun_hours(row.data(), step_hours, hours);
      fractions_file.stream().write(reinterpret_cast<const char*>(raw.data()),
                                    std::streamsize(raw.size()));
    }
  }
  times_file.commit();
  write_file(dir / kPolygons, polygons_text);
  fractions_file.commit();
  write_file(dir / kSunHours, sun_hours_csv(keys, hours));
  nlohmann::json manifest = first;
  manifest["shard"] = 0;
  manifest["shards"] = 1;
  manifest["first_step"] = 0;
  manifest["step_count"] = next_step;
  manifest.erase("timing");
  write_file(dir / kManifest, manifest.dump(2) + "\n");
  std::printf("%zu shards, %lld steps, %zu polygons: %s\n", parts.size(),
              static_cast<long long>(next_step), P, dir.c_str());
  return 0;
}

}  // namespace

int run_sun_study_merge(const SunStudyMergeOptions& options, const Context& /*ctx*/) {
  try {
    return merge_shards(options);
  } catch (const nlohmann::json::exception& e) {
    // A manifest without the keys a shard writes.
    throw InputError("sun-study-merge",
                     std::string("a shard's sun_study.json is not a sun study's: ") + e.what());
  }
}

}  // namespace shadowkit
