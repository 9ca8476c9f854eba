#pragma once
// The sunlit fraction of the largest polygons over the study, as an inline SVG chart.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "shadowkit/scene/sun_position.h"
#include "study_polygons.h"

namespace shadowkit::sun_study {

/// The rows of the \p count largest polygons with area, largest first (ties: lower row first).
std::vector<std::uint32_t> largest_polygons(const Polygons& polygons, std::size_t count);

/// \brief The fractions of a few polygons gathered into at most a given number of points,
/// so that a long study plots as a short line: each point is the mean over a run of
/// consecutive steps of those with the sun up (0 when it is up at none). Runs are whole days
/// of steps where shorter runs would leave fewer than 24 points a day: a line that samples a
/// day a few times aliases the days into noise.
class FractionSeries {
 public:
  FractionSeries(std::vector<std::uint32_t> polygons, std::int64_t steps, std::int64_t step_seconds,
                 std::size_t points);

  /// Adds the next step, in step order.
  void add_step(sun::Instant t, bool sun_up, const float* fractions);

  const std::vector<std::uint32_t>& polygons() const { return polygons_; }
  std::size_t size() const { return counts_.size(); }
  /// The middle of point \p j's run of steps.
  sun::Instant time(std::size_t j) const { return first_[j] + (last_[j] - first_[j]) / 2; }
  /// The mean fraction of polygons()[line] over point \p j's steps with the sun up.
  double value(std::size_t line, std::size_t j) const {
    return sun_up_[j] > 0 ? sums_[line * counts_.size() + j] / double(sun_up_[j]) : 0.0;
  }
  std::int64_t steps_per_point() const { return steps_per_point_; }

 private:
  std::vector<std::uint32_t> polygons_;
  std::int64_t steps_per_point_ = 1, added_ = 0;
  std::vector<double> sums_;                   ///< line-major
  std::vector<std::int64_t> counts_, sun_up_;  ///< per point: its steps, those with the sun up
  std::vector<sun::Instant> first_, last_;
};

/// A self-contained SVG line chart of \p series: x the local standard time (UTC +
/// \p utc_offset_hours), y the sunlit fraction from 0 to 1, axes with ticks and titles, and a
/// legend entry per line labelled by \p labels.
std::string fraction_plot_svg(const FractionSeries& series, const std::vector<std::string>& labels,
                              double utc_offset_hours);

}  // namespace shadowkit::sun_study
