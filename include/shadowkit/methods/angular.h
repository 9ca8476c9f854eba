#pragma once
/// \brief Thakur, Cheng & Miura: the ridge-edge loops of the scene sliced into an angular lookup
/// table around the light, queried scan line by scan line.
#include <memory>

#include "shadowkit/methods/shadow_method.h"

namespace shadowkit::angular {

/// The method with \p options (its settings, docs/methods/angular.md); InputError for an unknown
/// key or a bad value.
std::unique_ptr<ShadowMethod> make_method(const MethodOptions& options);

}  // namespace shadowkit::angular
