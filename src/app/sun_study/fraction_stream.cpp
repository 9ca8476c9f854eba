#include "fraction_stream.h"

#include <algorithm>
#include <charconv>
#include <string>
#include <string_view>

#include "contract_files.h"
#include "shadowkit/core/error.h"

namespace shadowkit::sun_study {
namespace {

// Fractions held at once: about the sun-study command's own block, 16 MB of floats.
constexpr std::size_t kBlockValues = std::size_t(1) << 22;

struct TimesRow {
  sun::Instant instant;
  bool sun_up = false;
};

// A row of times.csv, index,time_utc,azimuth_deg,elevation_deg, which must be step \p step's.
TimesRow parse_times_row(const std::string& line, std::int64_t step, const std::string& where) {
  const std::size_t time = line.find(',') + 1, azimuth = line.find(',', time) + 1;
  const std::size_t elevation = line.find(',', azimuth) + 1;
  const std::string index = std::to_string(step);
  if (time == 0 || azimuth == 0 || elevation == 0 || line.compare(0, time - 1, index) != 0) {
    throw InputError(where, "expected the row of step " + index);
  }
  double degrees = 0;
  const char* end = line.data() + line.size();
  const auto parsed = std::from_chars(line.data() + elevation, end, degrees);
  if (parsed.ec != std::errc() || parsed.ptr != end) {
    throw InputError(where, "malformed elevation_deg");
  }
  return {sun::parse_utc_time(std::string_view(line).substr(time, azimuth - 1 - time), where),
          degrees > 0};
}

}  // namespace

FractionStream::FractionStream(const std::filesystem::path& dir, std::int64_t steps,
                               std::size_t polygons)
    : times_path_(dir / kTimes),
      fractions_path_(dir / kFractions),
      times_(times_path_, std::ios::binary),
      fractions_(fractions_path_, std::ios::binary),
      steps_(steps),
      polygons_(polygons),
      block_(std::max<std::size_t>(1, kBlockValues / std::max<std::size_t>(polygons, 1))) {
  if (!times_) throw InputError(times_path_.string(), "cannot open");
  if (!fractions_) throw InputError(fractions_path_.string(), "cannot open");
  std::error_code ec;
  if (std::filesystem::file_size(fractions_path_, ec) != std::uintmax_t(steps) * polygons * 4) {
    throw InputError(fractions_path_.string(), "does not hold the study's " +
                                                   std::to_string(steps) + " x " +
                                                   std::to_string(polygons) + " values");
  }
  std::string header;
  std::getline(times_, header);
  if (header + "\n" != kTimesHeader) throw InputError(times_path_.string(), "not a times.csv");
}

bool FractionStream::next() {
  const std::int64_t first = next_;
  const auto n = std::size_t(std::min<std::int64_t>(std::int64_t(block_), steps_ - first));
  instants_.resize(n);
  sun_up_.resize(n);
  values_.resize(n * polygons_);
  bytes_.resize(n * polygons_ * 4);
  if (n == 0) return false;
  std::string line;
  for (std::size_t i = 0; i < n; ++i) {
    const std::string where =
        times_path_.string() + ":" + std::to_string(first + std::int64_t(i) + 2);
    if (!std::getline(times_, line)) throw InputError(where, "missing: the study has more steps");
    const TimesRow row = parse_times_row(line, first + std::int64_t(i), where);
    instants_[i] = row.instant;
    sun_up_[i] = row.sun_up;
  }
  if (!fractions_.read(reinterpret_cast<char*>(bytes_.data()), std::streamsize(bytes_.size()))) {
    throw InputError(fractions_path_.string(), "cannot read");
  }
  for (std::size_t v = 0; v < values_.size(); ++v) values_[v] = read_float32_le(&bytes_[4 * v]);
  next_ += std::int64_t(n);
  return true;
}

}  // namespace shadowkit::sun_study
