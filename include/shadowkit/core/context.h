#pragma once
/// \brief What every stage receives explicitly instead of global state.
#include <functional>
#include <string>

namespace shadowkit {

/// \brief Execution settings and the warning sink, passed to every stage.
struct Context {
  /// Worker threads for oneTBB (0: all cores). Applied by the caller's task_arena.
  int threads = 0;
  /// Receives non-fatal warnings (dropped faces, ...). Default: stderr.
  std::function<void(const std::string&)> warn;

  void warning(const std::string& message) const;
};

}  // namespace shadowkit
