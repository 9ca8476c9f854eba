#include "contract_files.h"

#include <bit>
#include <charconv>
#include <sstream>

#include "shadowkit/core/error.h"

namespace shadowkit::sun_study {

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

std::string times_row(std::int64_t index, sun::Instant t, const sun::SunAngles& angles) {
  return std::to_string(index) + "," + sun::format_utc_time(t) + "," + decimal(angles.azimuth_deg) +
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

std::vector<std::string> row_keys(const std::string& polygons_text, const std::string& where) {
  std::vector<std::string> keys;
  std::istringstream in(polygons_text);
  std::string line;
  std::getline(in, line);
  if (line + "\n" != kPolygonsHeader) throw InputError(where, "not a sun study's polygons.csv");
  while (std::getline(in, line)) {
    const std::size_t comma = line.rfind(',');
    if (comma == std::string::npos) throw InputError(where, "malformed row '" + line + "'");
    keys.push_back(line.substr(0, comma));
  }
  return keys;
}

void add_sun_hours(const float* fractions, double step_hours, std::vector<double>& hours) {
  for (std::size_t p = 0; p < hours.size(); ++p) hours[p] += double(fractions[p]) * step_hours;
}

void append_uint32_le(std::uint32_t value, std::string& out) {
  for (int b = 0; b < 4; ++b) out.push_back(char((value >> (8 * b)) & 0xff));
}

std::uint32_t read_uint32_le(const unsigned char* bytes) {
  return std::uint32_t(bytes[0]) | std::uint32_t(bytes[1]) << 8 | std::uint32_t(bytes[2]) << 16 |
         std::uint32_t(bytes[3]) << 24;
}

void append_float32_le(const float* values, std::size_t count, std::string& out) {
  for (std::size_t i = 0; i < count; ++i)
    append_uint32_le(std::bit_cast<std::uint32_t>(values[i]), out);
}

float read_float32_le(const unsigned char* bytes) {
  return std::bit_cast<float>(read_uint32_le(bytes));
}

AtomicFile::AtomicFile(fs::path path) : path_(std::move(path)) {
  temporary_ = path_;
  temporary_ += ".partial";
  out_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!out_) throw InputError(temporary_.string(), "cannot open for writing");
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.close();
  std::error_code ignored;
  fs::remove(temporary_, ignored);
}

void AtomicFile::commit() {
  out_.close();
  if (!out_) throw InputError(temporary_.string(), "write failed");
  std::error_code ec;
  fs::rename(temporary_, path_, ec);
  if (ec) throw InputError(path_.string(), "cannot rename into place: " + ec.message());
  committed_ = true;
}

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

void prepare_folder(const fs::path& dir, const std::string& option,
                    const std::vector<std::string>& also) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!fs::is_directory(dir))
    throw InputError(option + " " + dir.string(), "cannot create the folder");
  for (const char* name : {kTimes, kPolygons, kFractions, kSunHours, kManifest}) {
    fs::remove(dir / name, ec);
  }
  for (const std::string& name : also) fs::remove(dir / name, ec);
}

}  // namespace shadowkit::sun_study
