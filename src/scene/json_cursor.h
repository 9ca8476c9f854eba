#pragma once
// A JSON value together with its key path, so that every type error names the file and key.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "shadowkit/core/error.h"
#include "shadowkit/core/vec.h"

namespace shadowkit {

/// Throws InputError naming the key path (`file: key 'camera.position'`) of the first key that
/// one object of \p text holds twice; nlohmann would keep the last value and drop the others
/// without a word. \p text is well-formed JSON (parsed before).
void check_unique_keys(std::string_view text, const std::string& file);

class JsonCursor {
 public:
  JsonCursor(const nlohmann::json& value, std::string file, std::string path)
      : value_(value), file_(std::move(file)), path_(std::move(path)) {}

  const nlohmann::json& value() const { return value_; }
  const std::string& path() const { return path_; }
  /// "file: key 'a.b'" — the location prefix of this value's errors.
  std::string where() const { return file_ + ": key '" + path_ + "'"; }
  [[noreturn]] void fail(const std::string& what) const { throw InputError(where(), what); }

  bool has(const std::string& key) const { return value_.is_object() && value_.contains(key); }
  JsonCursor operator[](const std::string& key) const;
  JsonCursor operator[](std::size_t index) const;
  std::size_t array_size() const;
  /// Warns about keys not in \p known (typos would otherwise be silently ignored).
  std::vector<std::string> unknown_keys(const std::vector<std::string>& known) const;

  double number() const;
  int integer(int lo, int hi) const;
  std::string string() const;
  Vec3 vec3() const;
  /// A number s or three numbers; s means (s, s, s).
  Vec3 scale3() const;

 private:
  const nlohmann::json& value_;
  std::string file_;
  std::string path_;
};

}  // namespace shadowkit
