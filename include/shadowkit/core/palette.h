#pragma once
/// \brief The colours every shaded image shares: the command's images and voxel's image of
/// its subpatches light the same objects alike.
#include <cstdint>

#include "shadowkit/core/image.h"
#include "shadowkit/core/vec.h"

namespace shadowkit {

/// The ambient share of the light in shaded images.
inline constexpr double kAmbient = 0.18;

/// The background of shaded images, where no surface is seen.
inline constexpr Rgb8 kBackground{24, 26, 32};

/// The base colour of object \p object in shaded images.
Vec3 object_colour(std::uint32_t object);

/// A colour with channels in [0, 1] (clamped) as 8-bit RGB.
Rgb8 to_rgb8(Vec3 colour);

}  // namespace shadowkit
