#pragma once
// The heat map of sun hours: the scene camera's view in false colour, with its legend.
#include <cstdint>
#include <vector>

#include "shadowkit/core/image.h"

namespace shadowkit::sun_study {

/// \brief Sun hours per pixel of the scene camera's image, row-major, top row first.
struct SunHoursImage {
  int width = 0, height = 0;
  std::vector<double> hours;
  std::vector<std::uint8_t> covered;  ///< 0: background, no surface seen
};

/// Sun hours per pixel from the counts of sunlit steps (kBackgroundCount: no surface), each
/// step \p step_hours long.
SunHoursImage sun_hours_image(const std::vector<std::uint32_t>& counts, int width, int height,
                              double step_hours);

/// The legend's text colour, light on the dark background.
inline constexpr Rgb8 kLegendText{205, 208, 214};

/// The image of \p map: each covered pixel in sequential_colour() of its hours over the
/// scale's top (the largest hours of a covered pixel; 1 when that is 0), the rest kBackground;
/// to its right a legend of the same height (at least 220 pixels): "sun hours", a colour bar
/// with ticks labelled in hours, and "max" with the largest hours.
Image<Rgb8> heat_map_image(const SunHoursImage& map);

}  // namespace shadowkit::sun_study
