#pragma once
/// \brief What every command's output files share.
#include <filesystem>

namespace shadowkit {

/// Creates the missing parent directories of \p path. A failure is not reported here: it
/// shows up when the file is opened, as an error naming the file.
void create_parent_directories(const std::filesystem::path& path);

}  // namespace shadowkit
