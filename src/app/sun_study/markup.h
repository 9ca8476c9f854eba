#pragma once
// Text for the study's HTML page and SVG chart (html_escaped(): shadowkit/app/html.h).
#include <string>
#include <string_view>

namespace shadowkit::sun_study {

/// "+HH:MM" or "-HH:MM" of an offset from UTC in hours (whole minutes).
std::string utc_offset_text(double hours);

}  // namespace shadowkit::sun_study
