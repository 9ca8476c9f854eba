#include "shadowkit/core/files.h"

#include <system_error>

namespace shadowkit {

void create_parent_directories(const std::filesystem::path& path) {
  if (!path.has_parent_path()) return;
  std::error_code ignored;
  std::filesystem::create_directories(path.parent_path(), ignored);
}

}  // namespace shadowkit
