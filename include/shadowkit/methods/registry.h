#pragma once
/// \brief Every method by name: what the commands choose from.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "shadowkit/methods/shadow_method.h"

namespace shadowkit {

/// Names of the available methods, in the order compare shows them.
std::vector<std::string> method_names();

/// Creates a method by name; InputError for an unknown name or option.
std::unique_ptr<ShadowMethod> make_method(std::string_view name, const MethodOptions& options);

}  // namespace shadowkit
