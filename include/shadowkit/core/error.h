#pragma once
/// \brief The two tiers of errors: InputError for bad input (reported with its location,
/// exit status 2) and SHADOWKIT_CHECK for broken invariants (a programmer error).
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace shadowkit {

/// \brief Bad input: a file, a line or a key, and what is wrong with it.
class InputError : public std::runtime_error {
 public:
  /// \p where is "file", "file:line" or "file: key 'a.b'"; \p what says what is wrong.
  InputError(const std::string& where, const std::string& what)
      : std::runtime_error(where.empty() ? what : where + ": " + what) {}
};

/// The location of \p key inside the value located by \p where: "file: key 'objects[2]'" and
/// "count" give "file: key 'objects[2].count'"; any other location gets ": key 'count'".
inline std::string key_location(const std::string& where, const std::string& key) {
  const std::string marker = ": key '";
  if (where.size() > marker.size() && where.back() == '\'' &&
      where.find(marker) != std::string::npos) {
    return where.substr(0, where.size() - 1) + "." + key + "'";
  }
  return where + marker + key + "'";
}

[[noreturn]] inline void check_failed(const char* expr, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: internal check failed: %s\n", file, line, expr);
  std::abort();
}

}  // namespace shadowkit

/// Stops loudly when an invariant does not hold (all build types: these are cheap).
#define SHADOWKIT_CHECK(expr) \
  ((expr) ? static_cast<void>(0) : ::shadowkit::check_failed(#expr, __FILE__, __LINE__))
