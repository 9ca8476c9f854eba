#include "shadowkit/core/palette.h"

#include <algorithm>
#include <array>

namespace shadowkit {
namespace {

// Rounds half up, as std::lround does for these non-negative values, without its library
// call: a shaded image calls this three times a pixel.
std::uint8_t to_byte(double v) {
  return std::uint8_t(255.0 * std::clamp(v, 0.0, 1.0) + 0.5);
}

}  // namespace

Vec3 object_colour(std::uint32_t object) {
  static constexpr std::array<Vec3, 8> palette{{{0.85, 0.82, 0.75},
                                                {0.90, 0.55, 0.35},
                                                {0.45, 0.65, 0.90},
                                                {0.55, 0.80, 0.50},
                                                {0.85, 0.75, 0.35},
                                                {0.75, 0.50, 0.80},
                                                {0.40, 0.80, 0.80},
                                                {0.90, 0.45, 0.55}}};
  return palette[object % palette.size()];
}

Rgb8 to_rgb8(Vec3 c) {
  return {to_byte(c.x), to_byte(c.y), to_byte(c.z)};
}

}  // namespace shadowkit
