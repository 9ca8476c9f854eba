#pragma once
// The study's time steps and a shard's block of them (sun-study.md, "Command").
#include <chrono>
#include <cstdint>
#include <string>

#include "shadowkit/app/commands.h"
#include "shadowkit/scene/sun_position.h"

namespace shadowkit::sun_study {

/// \brief The instants --from + k * --step that are not after --to.
struct Steps {
  sun::Instant from;
  std::int64_t step_seconds = 0;
  std::int64_t count = 0;  ///< T, every step of the study, night included
  sun::Instant at(std::int64_t k) const { return from + std::chrono::seconds(k * step_seconds); }
  double step_hours() const { return double(step_seconds) / 3600.0; }
};

/// The steps of \p options at a site whose local standard time is UTC + \p utc_offset_hours;
/// InputError naming the option when they make no study. The offset moves every step alike,
/// so how many steps there are does not depend on it; only whether the first and last
/// steps lie within the years 0000 to 9999 in UTC, as times.csv writes them, does.
Steps study_steps(const SunStudyOptions& options, double utc_offset_hours);

/// \brief The I-th of N contiguous blocks of steps whose sizes differ by one at most.
struct Shard {
  std::int64_t index = 0, count = 1;
  std::int64_t first = 0, end = 0;  ///< its block of steps, [first, end)
};

/// The shard "I/N" of \p text (empty: the whole study) over \p steps steps.
Shard study_shard(const std::string& text, std::int64_t steps);

}  // namespace shadowkit::sun_study
