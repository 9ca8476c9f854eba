#include "heat_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "bitmap_font.h"
#include "shadowkit/core/colour_map.h"
#include "shadowkit/core/error.h"
#include "shadowkit/core/palette.h"
#include "sunlit_steps.h"

namespace shadowkit::sun_study {
namespace {

constexpr int kScale = 2;  // font pixels per glyph pixel: 10 x 14 glyphs
constexpr int kMargin = 16, kBarWidth = 20, kTickLength = 5, kGap = 9;
constexpr int kMinHeight = 220;  // room for the title, a bar of 120 pixels and the maximum

// The ticks of a scale from 0 to top: multiples of 1, 2 or 5 times a power of ten, about five.
struct Ticks {
  double step = 1;
  int decimals = 0;
};

Ticks ticks_to(double top) {
  const double raw = top / 5;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  Ticks ticks;
  for (const double m : {1.0, 2.0, 5.0, 10.0}) {
    ticks.step = m * magnitude;
    if (ticks.step >= raw) break;
  }
  ticks.decimals = std::max(0, int(-std::floor(std::log10(ticks.step) + 1e-9)));
  return ticks;
}

std::string number_text(double value, int decimals) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

int text_width(const std::string& text) {
  return int(text.size()) * glyph_advance(kScale) - kScale;
}

void fill(Image<Rgb8>& image, int x0, int y0, int x1, int y1, Rgb8 colour) {
  for (int y = std::max(y0, 0); y < std::min(y1, image.height); ++y) {
    for (int x = std::max(x0, 0); x < std::min(x1, image.width); ++x) image.at(x, y) = colour;
  }
}

}  // namespace

SunHoursImage sun_hours_image(const std::vector<std::uint32_t>& counts, int width, int height,
                              double step_hours) {
  SunHoursImage image{width, height, std::vector<double>(counts.size(), 0.0),
                      std::vector<std::uint8_t>(counts.size(), 0)};
  for (std::size_t i = 0; i < counts.size(); ++i) {
    if (counts[i] == kBackgroundCount) continue;
    image.covered[i] = 1;
    image.hours[i] = counts[i] * step_hours;
  }
  return image;
}

Image<Rgb8> heat_map_image(const SunHoursImage& map) {
  const std::size_t pixels = std::size_t(map.width) * std::size_t(map.height);
  SHADOWKIT_CHECK(map.hours.size() == pixels && map.covered.size() == pixels);
  double largest = 0;
  for (std::size_t i = 0; i < pixels; ++i) {
    if (map.covered[i]) largest = std::max(largest, map.hours[i]);
  }
  const double top = largest > 0 ? largest : 1.0;  // a study all in shade still has a scale
  const Ticks ticks = ticks_to(top);
  std::vector<std::pair<double, std::string>> labels;
  for (int k = 0; k * ticks.step <= top * (1 + 1e-9); ++k) {
    labels.emplace_back(k * ticks.step, number_text(k * ticks.step, ticks.decimals));
  }
  const std::string title = "sun hours";
  // Three significant digits or more: 4400 h, 15.8 h, 0.75 h.
  const int max_decimals = largest >= 100 ? 0 : largest >= 10 ? 1 : 2;
  const std::string maximum = "max " + number_text(largest, max_decimals) + " h";
  int label_width = 0;
  for (const auto& label : labels) label_width = std::max(label_width, text_width(label.second));
  const int legend_width = 2 * kMargin + std::max({text_width(title), text_width(maximum),
                                                   kBarWidth + kTickLength + kGap + label_width});

  Image<Rgb8> image(map.width + legend_width, std::max(map.height, kMinHeight), kBackground);
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      const std::size_t i = std::size_t(y) * map.width + x;
      if (map.covered[i]) image.at(x, y) = sequential_colour(map.hours[i] / top);
    }
  }

  // Legend: the title, the bar from 0 (bottom) to the top of the scale, its ticks, the maximum.
  const int th = glyph_height(kScale);
  const int left = map.width + kMargin;
  const int bar_top = kMargin + th + 12 + th / 2;
  const int bar_bottom = image.height - kMargin - th - 12 - th / 2;
  draw_text(image, left, kMargin, title, kLegendText, kScale);
  for (int y = bar_top; y <= bar_bottom; ++y) {
    const double t = double(bar_bottom - y) / double(bar_bottom - bar_top);
    fill(image, left, y, left + kBarWidth, y + 1, sequential_colour(t));
  }
  for (const auto& [value, text] : labels) {
    const int y = bar_bottom - int(std::lround(value / top * (bar_bottom - bar_top)));
    fill(image, left + kBarWidth, y, left + kBarWidth + kTickLength, y + 1, kLegendText);
    draw_text(image, left + kBarWidth + kTickLength + kGap, y - th / 2, text, kLegendText, kScale);
  }
  draw_text(image, left, bar_bottom + th / 2 + 12, maximum, kLegendText, kScale);
  return image;
}

}  // namespace shadowkit::sun_study
