#pragma once
/// \brief The shaded image: ambient plus Lambert diffuse per light, the diffuse term removed
/// where a light's mask says shadow.
#include <vector>

#include "shadowkit/core/image.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/raster/visible_surface.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// The ambient share of the light in shaded images.
inline constexpr double kAmbient = 0.18;

/// The base colour of object \p object in shaded images.
Vec3 object_colour(std::uint32_t object);

/// A colour with channels in [0, 1] (clamped) as 8-bit RGB.
Rgb8 to_rgb8(Vec3 colour);

/// \p masks holds one mask per light, in the order of scene.lights.
Image<Rgb8> shade_image(const Scene& scene, const VisibleSurfaceBuffer& surfaces,
                        const std::vector<const ShadowMask*>& masks);

}  // namespace shadowkit
