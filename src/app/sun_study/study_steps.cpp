#include "study_steps.h"

#include <charconv>
#include <cmath>
#include <string_view>

#include "shadowkit/core/error.h"

namespace shadowkit::sun_study {
namespace {

// The study's size in steps is bounded so that indices and the file of fractions stay in
// reach: 19 years at one-minute steps.
constexpr std::int64_t kMaxSteps = 10'000'000;
// The longest step, 1e10 minutes (19,000 years), is longer than any study (its years have
// four digits), so a longer one would change nothing; it keeps the step's seconds, and every
// sum of steps, within int64_t.
constexpr double kMaxStepMinutes = 1e10;
// times.csv writes UTC with four-digit years (the contract's YYYY-MM-DDTHH:MM:SSZ), which
// a local time in year 0000 or 9999 can leave.
constexpr sun::Instant kFirstWritable = std::chrono::sys_days{std::chrono::year{0} / 1 / 1};
constexpr sun::Instant kLastWritable =
    std::chrono::sys_days{std::chrono::year{9999} / 12 / 31} + std::chrono::seconds{86399};
// The most shards a study is cut into.
constexpr std::int64_t kMaxShards = 1'000'000;

}  // namespace

Steps study_steps(const SunStudyOptions& options, double utc_offset_hours) {
  Steps steps;
  steps.from = sun::parse_local_time(options.from, utc_offset_hours, "--from");
  const sun::Instant to = sun::parse_local_time(options.to, utc_offset_hours, "--to");
  const double seconds = options.step_minutes * 60;
  if (!(options.step_minutes > 0) || !std::isfinite(seconds)) {
    throw InputError("--step", "must be a positive number of minutes");
  }
  if (options.step_minutes > kMaxStepMinutes) {
    throw InputError("--step",
                     "must be at most 1e10 minutes (19,000 years), longer than any study");
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
  if (steps.from < kFirstWritable) {
    throw InputError("--from '" + options.from + "'",
                     "lies before the year 0000 in UTC, which times.csv cannot write");
  }
  if (steps.at(steps.count - 1) > kLastWritable) {
    throw InputError("--to '" + options.to + "'",
                     "lies after the year 9999 in UTC, which times.csv cannot write");
  }
  return steps;
}

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
  shard.first = shard.index * steps / shard.count;
  shard.end = (shard.index + 1) * steps / shard.count;
  return shard;
}

}  // namespace shadowkit::sun_study
