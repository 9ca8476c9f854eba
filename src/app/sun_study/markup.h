#pragma once
// Text for the study's HTML page and SVG chart.
#include <string>
#include <string_view>

namespace shadowkit::sun_study {

/// \p text with the characters markup reads as syntax (& < > ") as entities: object names and
/// file names are text, not markup.
std::string escaped(std::string_view text);

/// "+HH:MM" or "-HH:MM" of an offset from UTC in hours (whole minutes).
std::string utc_offset_text(double hours);

}  // namespace shadowkit::sun_study
