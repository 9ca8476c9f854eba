#include "bitmap_font.h"

#include <array>
#include <cstdint>

#include "shadowkit/core/error.h"

namespace shadowkit::sun_study {
namespace {

// A glyph's 7 rows, top first; in each row bit 4 is the leftmost of the 5 columns.
using GlyphRows = std::array<std::uint8_t, 7>;

struct FontGlyph {
  char c;
  GlyphRows rows;
};

constexpr std::array<FontGlyph, 24> kFont{{
    {'0', {14, 17, 19, 21, 25, 17, 14}}, {'1', {4, 12, 4, 4, 4, 4, 14}},
    {'2', {14, 17, 1, 2, 4, 8, 31}},     {'3', {31, 2, 4, 2, 1, 17, 14}},
    {'4', {2, 6, 10, 18, 31, 2, 2}},     {'5', {31, 16, 30, 1, 1, 17, 14}},
    {'6', {6, 8, 16, 30, 17, 17, 14}},   {'7', {31, 1, 2, 4, 8, 8, 8}},
    {'8', {14, 17, 17, 14, 17, 17, 14}}, {'9', {14, 17, 17, 15, 1, 2, 12}},
    {'.', {0, 0, 0, 0, 0, 12, 12}},      {'-', {0, 0, 0, 31, 0, 0, 0}},
    {' ', {0, 0, 0, 0, 0, 0, 0}},        {'a', {0, 0, 14, 1, 15, 17, 15}},
    {'h', {16, 16, 22, 25, 17, 17, 17}}, {'m', {0, 0, 26, 21, 21, 17, 17}},
    {'n', {0, 0, 22, 25, 17, 17, 17}},   {'o', {0, 0, 14, 17, 17, 17, 14}},
    {'r', {0, 0, 22, 25, 16, 16, 16}},   {'s', {0, 0, 14, 16, 14, 1, 30}},
    {'u', {0, 0, 17, 17, 17, 19, 13}},   {'x', {0, 0, 17, 10, 4, 10, 17}},
    {'(', {2, 4, 8, 8, 8, 4, 2}},        {')', {8, 4, 2, 2, 2, 4, 8}},
}};

const GlyphRows& glyph(char c) {
  for (const FontGlyph& g : kFont) {
    if (g.c == c) return g.rows;
  }
  SHADOWKIT_CHECK(!"character outside the legend's font");
  return kFont.front().rows;
}

}  // namespace

void draw_text(Image<Rgb8>& image, int x, int y, std::string_view text, Rgb8 colour, int scale) {
  for (const char c : text) {
    const GlyphRows& rows = glyph(c);
    for (int row = 0; row < 7; ++row) {
      for (int column = 0; column < 5; ++column) {
        if (!(rows[row] >> (4 - column) & 1)) continue;
        for (int dy = 0; dy < scale; ++dy) {
          for (int dx = 0; dx < scale; ++dx) {
            const int px = x + column * scale + dx, py = y + row * scale + dy;
            if (px >= 0 && py >= 0 && px < image.width && py < image.height) {
              image.at(px, py) = colour;
            }
          }
        }
      }
    }
    x += glyph_advance(scale);
  }
}

}  // namespace shadowkit::sun_study
