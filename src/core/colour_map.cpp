#include "shadowkit/core/colour_map.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "shadowkit/core/palette.h"

namespace shadowkit {
namespace {

// The map's parameters (Green 2011, section 2) and its lightness range: below 0.12 the colours
// sink into kBackground; above 0.85 they wash out to white.
constexpr double kStart = 0.6, kRotations = -0.9, kHue = 1.8;
constexpr double kLightest = 0.85, kDarkest = 0.12;

}  // namespace

Rgb8 sequential_colour(double t) {
  t = std::isnan(t) ? 0.0 : std::clamp(t, 0.0, 1.0);
  const double lightness = kDarkest + (kLightest - kDarkest) * t;
  // Eq. 2: a deviation from grey of amplitude a, turning about the grey diagonal by angle phi.
  const double phi = 2 * std::numbers::pi * (kStart / 3 + kRotations * lightness);
  const double a = kHue * lightness * (1 - lightness) / 2;
  const double c = std::cos(phi), s = std::sin(phi);
  return to_rgb8({lightness + a * (-0.14861 * c + 1.78277 * s),
                  lightness + a * (-0.29227 * c - 0.90649 * s), lightness + a * (1.97294 * c)});
}

}  // namespace shadowkit
