#pragma once
// The page's own files (page/), built into the binary: the server reads nothing else.
#include <string_view>

namespace shadowkit::viewer {

/// \brief One file of the page, at its URL path.
struct PageAsset {
  std::string_view path;  ///< "/", "/viewer.js", ...
  std::string_view content_type;
  std::string_view bytes;
};

/// The asset at \p path, or nullptr: a fixed table, so no request path reaches a file system.
const PageAsset* page_asset(std::string_view path);

}  // namespace shadowkit::viewer
