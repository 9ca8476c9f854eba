#pragma once
// The sun-study contract's files (sun-study.md): their names, their number format, and
// writing them so that an interrupted run leaves no half-written file under those names.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "shadowkit/scene/sun_position.h"

namespace shadowkit::sun_study {

namespace fs = std::filesystem;

constexpr const char* kTimes = "times.csv";
constexpr const char* kPolygons = "polygons.csv";
constexpr const char* kFractions = "sunlit_fraction.f32";
constexpr const char* kSunHours = "sun_hours.csv";
constexpr const char* kManifest = "sun_study.json";
constexpr const char* kTimesHeader = "index,time_utc,azimuth_deg,elevation_deg\n";
constexpr const char* kPolygonsHeader = "index,object,face,area\n";

/// The contract's numbers: plain decimals with a dot, no exponent, at least 6 significant
/// digits. The shortest text that reads back as the same double, in fixed notation, padded
/// with zeros to 6 significant digits (0.5 -> 0.500000, 1e-7 -> 0.000000100000).
std::string decimal(double x);

/// One row of times.csv.
std::string times_row(std::int64_t index, sun::Instant t, const sun::SunAngles& angles);

/// sun_hours.csv from the "index,object,face" of every polygon and its sun hours.
std::string sun_hours_csv(const std::vector<std::string>& row_keys,
                          const std::vector<double>& hours);

/// "index,object,face" of every row of polygons.csv (\p polygons_text), the start of
/// sun_hours.csv's rows; InputError naming \p where if it is not a polygons.csv.
std::vector<std::string> row_keys(const std::string& polygons_text, const std::string& where);

/// Sun hours: each step's fraction, as stored in float32, times the step's length, added in
/// step order. The merge sums the merged file the same way, so the bytes agree.
void add_sun_hours(const float* fractions, double step_hours, std::vector<double>& hours);

void append_uint32_le(std::uint32_t value, std::string& out);
std::uint32_t read_uint32_le(const unsigned char* bytes);
void append_float32_le(const float* values, std::size_t count, std::string& out);
float read_float32_le(const unsigned char* bytes);

/// \brief A file written under a temporary name (".partial") in its folder and renamed into
/// place when complete; a file never committed (an error, an interruption) is removed.
class AtomicFile {
 public:
  explicit AtomicFile(fs::path path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  std::ofstream& stream() { return out_; }
  void commit();

 private:
  fs::path path_, temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

void write_file(const fs::path& path, const std::string& text);
std::string read_file(const fs::path& path);

/// Creates \p dir and removes the files of an earlier run from it (the contract's, the
/// manifest and \p also), so that the folder never mixes two runs' files.
void prepare_folder(const fs::path& dir, const std::string& option,
                    const std::vector<std::string>& also = {});

}  // namespace shadowkit::sun_study
