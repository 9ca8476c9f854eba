// The sequential colour map against Green's cubehelix at its ends, and its steady lightness.
#include "shadowkit/core/colour_map.h"

#include <gtest/gtest.h>

#include <cmath>

#include "shadowkit/core/palette.h"

namespace shadowkit {
namespace {

// The grey level Green's scheme holds to (his weights, section 2): exactly the lightness,
// up to rounding to 8 bits, wherever no channel is clipped.
double grey(Rgb8 c) {
  return (0.30 * c.r + 0.59 * c.g + 0.11 * c.b) / 255;
}

TEST(SequentialColour, EndsAreTheCubehelixColoursAtLightness012And085) {
  EXPECT_EQ(sequential_colour(0), (Rgb8{51, 13, 71}));
  EXPECT_EQ(sequential_colour(0.5), (Rgb8{21, 174, 133}));
  EXPECT_EQ(sequential_colour(1), (Rgb8{241, 214, 164}));
}

TEST(SequentialColour, OutOfRangeValuesClampToTheEnds) {
  EXPECT_EQ(sequential_colour(-3), sequential_colour(0));
  EXPECT_EQ(sequential_colour(7), sequential_colour(1));
  EXPECT_EQ(sequential_colour(std::nan("")), sequential_colour(0));
}

TEST(SequentialColour, LightnessRisesSteadily) {
  double previous = -1;
  for (int i = 0; i <= 255; ++i) {
    const double t = i / 255.0;
    const double g = grey(sequential_colour(t));
    EXPECT_NEAR(g, 0.12 + 0.73 * t, 0.002) << i;
    EXPECT_GT(g, previous) << i;
    previous = g;
  }
}

TEST(SequentialColour, DarkEndStandsApartFromTheBackground) {
  const Rgb8 low = sequential_colour(0);
  EXPECT_NE(low, kBackground);
  EXPECT_GT(std::abs(int(low.r) - kBackground.r) + std::abs(int(low.b) - kBackground.b), 40);
}

}  // namespace
}  // namespace shadowkit
