#include "energyplus_schedule.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <set>
#include <string_view>

#include "shadowkit/core/error.h"

namespace shadowkit::sun_study {
namespace {

namespace chrono = std::chrono;

constexpr std::int64_t kDay = 86400;
constexpr std::array<int, 12> kTimesteps{1, 2, 3, 4, 5, 6, 10, 12, 15, 20, 30, 60};

// The name made safe for the schedule's header and an IDF: no comma (CSV), semicolon (ends an
// object), exclamation mark (starts a comment), quote or control character; no outer spaces.
std::string energyplus_name(const std::string& name) {
  std::string out;
  for (const char c : name) {
    const bool syntax = std::string_view(",;!\"").find(c) != std::string_view::npos;
    out += syntax || static_cast<unsigned char>(c) < 0x20 ? '_' : c;
  }
  const std::size_t first = out.find_first_not_of(' ');
  return first == std::string::npos ? "" : out.substr(first, out.find_last_not_of(' ') - first + 1);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

// \p rows weighted by their share of the rows' area; none when they have no area.
std::vector<std::pair<std::uint32_t, double>> area_weights(const Polygons& polygons,
                                                           const std::vector<std::uint32_t>& rows) {
  double total = 0;
  for (const std::uint32_t p : rows) total += polygons.rows[p].area;
  std::vector<std::pair<std::uint32_t, double>> weights;
  if (!(total > 0)) return weights;
  for (const std::uint32_t p : rows) {
    if (polygons.rows[p].area > 0) weights.emplace_back(p, polygons.rows[p].area / total);
  }
  return weights;
}

// Four decimals, trailing zeros dropped: a year of rows stays small, and EnergyPlus's own
// export writes two.
std::string fraction_text(double value) {
  char buffer[32];
  char* end = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, 4).ptr;
  while (end[-1] == '0') --end;
  if (end[-1] == '.') --end;
  return std::string(buffer, end);
}

// A row's length in seconds: an hour over the timesteps per hour, once they are checked.
std::int64_t row_seconds(int timesteps) {
  check_energyplus_timesteps(timesteps);
  return 3600 / timesteps;
}

}  // namespace

std::vector<ShadingColumn> shading_columns(const Scene& scene, const Polygons& polygons,
                                           const ShadingGroups* groups) {
  std::vector<ShadingColumn> columns;
  std::set<std::string> taken;  // lower case: EnergyPlus names ignore case
  if (groups) {
    for (const ShadingGroups::Group& group : groups->groups) taken.insert(lower(group.surface));
  }
  std::uint32_t first_row = 0;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& object = scene.objects[i];
    std::vector<std::uint32_t> rows(object.mesh.input_face_count());
    for (std::uint32_t k = 0; k < rows.size(); ++k) rows[k] = first_row + k;
    first_row += std::uint32_t(rows.size());
    std::string base = energyplus_name(object.name);
    if (base.empty()) base = "object_" + std::to_string(i);
    std::string name = base;
    for (int n = 2; !taken.insert(lower(name)).second; ++n) name = base + "_" + std::to_string(n);
    columns.push_back({name, area_weights(polygons, rows)});
  }
  SHADOWKIT_CHECK(first_row == polygons.rows.size());
  if (groups) {
    for (const ShadingGroups::Group& group : groups->groups) {
      columns.push_back({group.surface, area_weights(polygons, group.polygons)});
    }
  }
  return columns;
}

void check_energyplus_timesteps(int timesteps) {
  if (std::find(kTimesteps.begin(), kTimesteps.end(), timesteps) == kTimesteps.end()) {
    throw InputError("--energyplus-timesteps",
                     std::to_string(timesteps) +
                         " is not a number of timesteps per hour EnergyPlus allows (1, 2, 3, "
                         "4, 5, 6, 10, 12, 15, 20, 30 or 60)");
  }
}

EnergyPlusSchedule::EnergyPlusSchedule(std::ostream& out, std::vector<ShadingColumn> columns,
                                       sun::Instant first_step, double utc_offset_hours,
                                       std::int64_t step_seconds, int timesteps)
    : out_(out),
      columns_(std::move(columns)),
      offset_seconds_(std::llround(utc_offset_hours * 3600)),
      step_seconds_(step_seconds),
      row_seconds_(row_seconds(timesteps)),
      values_(columns_.size()),
      sums_(columns_.size()) {
  const auto day = chrono::floor<chrono::days>(first_step + chrono::seconds(offset_seconds_));
  const chrono::year year = chrono::year_month_day(day).year();
  const chrono::sys_days start{year / chrono::January / 1};
  const chrono::sys_days end{(year + chrono::years(1)) / chrono::January / 1};
  year_start_ = chrono::sys_seconds(start).time_since_epoch().count();
  rows_ = (end - start).count() * 24 * timesteps;
  out_ << "Surface Name";  // the first header cell of EnergyPlus's own export
  for (const ShadingColumn& column : columns_) out_ << ',' << column.name;
  out_ << '\n';
}

void EnergyPlusSchedule::add_step(sun::Instant t, const float* fractions) {
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    double value = 0;
    for (const auto& [p, weight] : columns_[c].weights) value += weight * double(fractions[p]);
    values_[c] = value;
  }
  // The step stands for (end - step, end], in seconds from the year's start.
  const std::int64_t end = t.time_since_epoch().count() + offset_seconds_ - year_start_;
  const std::int64_t begin = end - step_seconds_;
  while (next_row_ < rows_) {
    const std::int64_t low = next_row_ * row_seconds_, high = low + row_seconds_;
    if (low >= end) break;
    const std::int64_t overlap = std::min(high, end) - std::max(low, begin);
    if (overlap > 0) {
      for (std::size_t c = 0; c < columns_.size(); ++c) sums_[c] += values_[c] * double(overlap);
      covered_ += overlap;
    }
    if (high > end) break;  // the next step covers the rest of this row
    write_row();
  }
}

void EnergyPlusSchedule::finish() {
  while (next_row_ < rows_) write_row();
}

void EnergyPlusSchedule::write_row() {
  // The time stamp is the row's end, 24:00 rather than the next day's 00:00.
  const std::int64_t low = next_row_ * row_seconds_;
  const std::int64_t day = low / kDay;
  const std::int64_t minutes = (low + row_seconds_ - day * kDay) / 60;
  const chrono::year_month_day date{chrono::sys_days(chrono::days(year_start_ / kDay + day))};
  char stamp[32];
  std::snprintf(stamp, sizeof stamp, "%02u/%02u %02d:%02d", unsigned(date.month()),
                unsigned(date.day()), int(minutes / 60), int(minutes % 60));
  line_ = stamp;
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    line_ += ',';
    line_ += fraction_text(covered_ > 0 ? sums_[c] / double(covered_) : 0.0);
    sums_[c] = 0;
  }
  line_ += '\n';
  out_ << line_;
  covered_ = 0;
  ++next_row_;
}

}  // namespace shadowkit::sun_study
