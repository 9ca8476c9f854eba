#pragma once
/// \brief Crow 1977 shadow volumes: shadow polygons on the light's contour edges, counted per pixel
/// between the eye and the visible point.
#include <memory>

#include "shadowkit/methods/shadow_method.h"

namespace shadowkit::volume {

/// The method with \p options (its settings, docs/methods/volume.md); InputError for an unknown
/// key or a bad value.
std::unique_ptr<ShadowMethod> make_method(const MethodOptions& options);

}  // namespace shadowkit::volume
