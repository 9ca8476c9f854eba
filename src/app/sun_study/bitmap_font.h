#pragma once
// A 5 x 7 pixel font for the heat map's legend: digits, the decimal point, the minus sign, a
// space and the letters of its labels ("sun hours", "max").
#include <string_view>

#include "shadowkit/core/image.h"

namespace shadowkit::sun_study {

/// Columns a glyph advances at \p scale: 5 for the glyph and 1 for the gap, times scale.
constexpr int glyph_advance(int scale) {
  return 6 * scale;
}
/// Rows a line of text takes at \p scale.
constexpr int glyph_height(int scale) {
  return 7 * scale;
}

/// Draws \p text with its top-left corner at (x, y), each font pixel a scale x scale square,
/// clipped to the image. A character outside the font is a programmer error.
void draw_text(Image<Rgb8>& image, int x, int y, std::string_view text, Rgb8 colour, int scale);

}  // namespace shadowkit::sun_study
