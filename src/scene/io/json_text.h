#pragma once
/// \brief JSON texts (scene files, glTF) read with their errors placed at a line: syntax,
/// numbers beyond double's range, and nesting deep enough to exhaust recursive JSON code.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace shadowkit {

/// Throws InputError("file:line") at the first array or object nested deeper than
/// limits::kJsonDepth. Strings are skipped, so brackets inside them do not count.
void check_json_depth(std::string_view text, const std::string& file);

/// Parses \p text after check_json_depth(); every failure is an InputError("file:line").
nlohmann::json parse_json_text(std::string_view text, const std::string& file);

}  // namespace shadowkit
