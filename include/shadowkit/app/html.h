#pragma once
/// \brief Text inside the HTML pages shadowkit writes (the compare report, the sun study's
/// page).
#include <string>
#include <string_view>

namespace shadowkit {

/// \p text with the characters markup reads as syntax (& < > ") as entities: file names,
/// object names and failure reasons are text, not markup.
std::string html_escaped(std::string_view text);

}  // namespace shadowkit
