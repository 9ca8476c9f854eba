#pragma once
// Triangle setup for the scan converter: clipping in view space and fixed-point edges.
#include <cstdint>
#include <vector>

#include "shadowkit/raster/projection.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::raster {

/// Sub-pixel precision: 1/256 pixel. Pixel centres sit at 256 x + 128.
inline constexpr int kSubpixelBits = 8;
inline constexpr std::int64_t kSubpixel = 1 << kSubpixelBits;
/// Triangles are clipped to the raster plus this margin in pixels, which keeps fixed-point
/// edge functions well inside 64 bits.
inline constexpr double kGuardBand = 4096;

/// \brief A triangle ready for scan conversion: counter-clockwise fixed-point vertices with
/// the top-left rule folded into the edge biases, and the depth-key plane of its face.
struct ScreenTriangle {
  std::int64_t x[3], y[3];  ///< fixed point
  std::int64_t bias[3];     ///< 0 if the edge owns pixel centres on it, 1 otherwise
  double key_a, key_b, key_c;  ///< depth key = a * px + b * py + c at pixel centre (px, py)
  int min_x, min_y, max_x, max_y;  ///< pixel bounds, clamped to the raster
  std::uint32_t face;
};

/// Clips and sets up every triangle of \p scene for \p view, in triangle order (so that the
/// tie rule "lower triangle index wins" survives binning). Runs in parallel.
std::vector<ScreenTriangle> setup_triangles(const Scene& scene, const RasterProjection& view);

/// Narrows [x_lo, x_hi] to the pixel columns of row \p py whose centres the triangle owns
/// under the fill rule; false if none.
bool row_span(const ScreenTriangle& t, int py, int& x_lo, int& x_hi);

}  // namespace shadowkit::raster
