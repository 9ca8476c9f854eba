#pragma once
/// \brief The shaded image: ambient plus Lambert diffuse per light, the diffuse term removed
/// where a light's mask says shadow.
#include <vector>

#include "shadowkit/core/image.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/raster/visible_surface.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// \p masks holds one mask per light, in the order of scene.lights.
Image<Rgb8> shade_image(const Scene& scene, const VisibleSurfaceBuffer& surfaces,
                        const std::vector<const ShadowMask*>& masks);

}  // namespace shadowkit
