#pragma once
/// \brief What a reader passes over, tallied per kind so that a file with a million line
/// elements gives one warning, not a million.
#include <cstddef>
#include <string>
#include <vector>

#include "shadowkit/core/context.h"

namespace shadowkit::mesh_io {

class SkippedItems {
 public:
  /// Counts one \p what ("'l' (line) element") met at \p line (0: no line to name).
  void add(const std::string& what, std::size_t line = 0, std::size_t count = 1) {
    for (Tally& t : tallies_) {
      if (t.what == what) {
        t.count += count;
        return;
      }
    }
    tallies_.push_back({what, count, line});
  }

  /// One warning per kind: "path: skipped 3 'l' (line) elements (the first at line 7)".
  void warn(const std::string& path, const Context& ctx) const {
    for (const Tally& t : tallies_) {
      std::string message = path + ": skipped " + std::to_string(t.count) + " " + t.what;
      if (t.first_line > 0) {
        message += t.count == 1 ? " at line " : " (the first at line ";
        message += std::to_string(t.first_line) + (t.count == 1 ? "" : ")");
      }
      ctx.warning(message);
    }
  }

 private:
  struct Tally {
    std::string what;
    std::size_t count = 0;
    std::size_t first_line = 0;
  };
  std::vector<Tally> tallies_;
};

}  // namespace shadowkit::mesh_io
