#pragma once
/// \brief Williams 1978 shadow maps: a depth image from the light (a cube map for a point light),
/// looked up per visible point.
#include <memory>

#include "shadowkit/methods/shadow_method.h"

namespace shadowkit::shadowmap {

/// The method with \p options (its settings, docs/methods/shadowmap.md); InputError for an unknown
/// key or a bad value.
std::unique_ptr<ShadowMethod> make_method(const MethodOptions& options);

}  // namespace shadowkit::shadowmap
