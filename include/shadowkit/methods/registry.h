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

/// \brief One method setting as the viewer offers it (docs/commands.md, "Method settings").
struct SettingInfo {
  std::string key;       ///< without the method's prefix
  std::string fallback;  ///< the value when the setting is not given; "": chosen by others
  std::vector<std::string> choices;  ///< the values it takes; empty: a number in a range
  std::string range;                 ///< the range of a number, as the docs give it
};

/// The settings \p method takes, in the order of the docs' table (none for an unknown name).
std::vector<SettingInfo> method_settings(std::string_view method);

/// Creates a method by name; InputError for an unknown name or option.
std::unique_ptr<ShadowMethod> make_method(std::string_view name, const MethodOptions& options);

}  // namespace shadowkit
