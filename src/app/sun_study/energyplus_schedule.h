#pragma once
// The study's sunlit fractions as EnergyPlus reads them with Schedule:File:Shading: one column
// per surface (its area-weighted fraction), one row per timestep of a whole calendar year.
#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "shading_groups.h"
#include "shadowkit/scene/scene.h"
#include "shadowkit/scene/sun_position.h"
#include "study_polygons.h"

namespace shadowkit::sun_study {

/// \brief A column of the schedule: an EnergyPlus surface and its polygons' area shares.
struct ShadingColumn {
  std::string name;
  std::vector<std::pair<std::uint32_t, double>> weights;  ///< polygon, its share of the area
};

/// A column per scene object, named by the object's name made EnergyPlus-safe and unique
/// (ignoring case, as EnergyPlus does), then one per group of \p groups (if any), named as
/// given. A column of no area has no weights: its fraction is 0.
std::vector<ShadingColumn> shading_columns(const Scene& scene, const Polygons& polygons,
                                           const ShadingGroups* groups);

/// InputError unless \p timesteps is a number of timesteps per hour EnergyPlus's Timestep
/// object allows: a divisor of 60.
void check_energyplus_timesteps(int timesteps);

/// \brief Writes the schedule row by row as the study's steps stream by, in step order.
///
/// The file covers the calendar year, in local standard time, of the study's first step:
/// days x 24 x timesteps rows. A row stands for the timestep that ends at its time stamp (the
/// first, 01/01 01:00 when hourly, for 00:00 to 01:00); a step for the step length that ends
/// at it. A row holds the time-weighted mean of the steps over the part of it the study
/// covers, 0 where the study covers none of it.
class EnergyPlusSchedule {
 public:
  EnergyPlusSchedule(std::ostream& out, std::vector<ShadingColumn> columns, sun::Instant first_step,
                     double utc_offset_hours, std::int64_t step_seconds, int timesteps);

  void add_step(sun::Instant t, const float* fractions);
  /// Writes the rows after the last step's.
  void finish();

 private:
  void write_row();

  std::ostream& out_;
  std::vector<ShadingColumn> columns_;
  std::int64_t offset_seconds_ = 0, step_seconds_ = 0, row_seconds_ = 0;
  std::int64_t year_start_ = 0;  ///< local seconds since 1970 of the year's first instant
  std::int64_t rows_ = 0, next_row_ = 0;
  std::vector<double> values_, sums_;  ///< per column: this step's, and the open row's
  std::int64_t covered_ = 0;           ///< seconds of the open row the study covers
  std::string line_;
};

}  // namespace shadowkit::sun_study
