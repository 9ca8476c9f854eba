// A height field of N x N cells under a low sun: one large open mesh whose hills shadow
// each other, the shape of a landscape or a scanned surface rather than a field of separate
// solids. Its height is a fixed sum of sinusoids, so every N samples the same landscape.
#include <cmath>
#include <cstdint>

#include "builtin_scenes.h"

namespace shadowkit::generators {
namespace {

constexpr std::int64_t kMaxCells = 1024;  // 2,097,152 triangles
constexpr double kHalfSize = 10;          // the field spans [-10, 10] in x and z

// Seven waves: frequencies 1.5 times apart, directions a golden angle apart, amplitudes
// falling as frequency^-1.2 (rougher in the small, as landscapes are).
constexpr int kWaves = 7;
constexpr double kBaseFrequency = 0.55, kFrequencyStep = 1.5, kGoldenAngle = 2.399963;
constexpr double kAmplitude = 0.5;  // heights within about +-2.4

// The camera looks over the field from one side; the sun, 17 degrees high, shines from
// behind the camera's left, so the hills' shadows run long away from it and to the right.
constexpr Vec3 kCamera{0, 6, 14};
constexpr Vec3 kLookAt{0, 0, 0};
constexpr double kFovYDeg = 50;
constexpr Vec3 kSunDirection{0.9, -0.3, -0.4};

double height(double x, double z) {
  double h = 0, frequency = kBaseFrequency;
  for (int i = 0; i < kWaves; ++i, frequency *= kFrequencyStep) {
    const double angle = kGoldenAngle * i, phase = 1.3 * i + 0.4;
    h += std::pow(frequency, -1.2) *
         std::sin(frequency * (x * std::cos(angle) + z * std::sin(angle)) + phase);
  }
  return kAmplitude * h;
}

}  // namespace

SceneParts terrain_scene(const ParamReader& params) {
  params.allow_only({"cells"});
  const auto n = static_cast<std::uint32_t>(params.integer("cells", 160, 1, kMaxCells));
  GeneratedObject terrain{"terrain", {}};
  PolygonSoup& soup = terrain.soup;
  const double step = 2 * kHalfSize / n;
  for (std::uint32_t j = 0; j <= n; ++j) {
    for (std::uint32_t i = 0; i <= n; ++i) {
      const double x = -kHalfSize + step * i, z = -kHalfSize + step * j;
      soup.positions.push_back({x, height(x, z), z});
    }
  }
  // Two triangles a cell, counter-clockwise seen from above.
  for (std::uint32_t j = 0; j < n; ++j) {
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t a = j * (n + 1) + i, b = a + 1, d = a + n + 1, c = d + 1;
      soup.add_face({a, d, c});
      soup.add_face({a, c, b});
    }
  }
  SceneParts parts;
  parts.objects.push_back(std::move(terrain));
  parts.lights.push_back(Light::directional(kSunDirection));
  parts.camera = camera_looking_at(kCamera, kLookAt, kFovYDeg);
  return parts;
}

}  // namespace shadowkit::generators
