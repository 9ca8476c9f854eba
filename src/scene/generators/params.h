#pragma once
/// \brief Reading and validating a generator's JSON parameters; every error names its key.
#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "shadowkit/core/vec.h"

namespace shadowkit::generators {

/// \brief Typed access to {"generator": NAME, ...params}; bad values throw InputError whose
/// location ends in the key ("scene.json: key 'objects[2].count'").
class ParamReader {
 public:
  /// \p params must outlive the reader. \p where labels the whole parameter object.
  ParamReader(const nlohmann::json& params, std::string where);

  /// The error location of \p key inside the parameter object.
  std::string key_where(std::string_view key) const;
  /// Throws InputError for \p key with message \p what.
  [[noreturn]] void fail(std::string_view key, const std::string& what) const;

  /// Rejects any key besides \p allowed and the keys the scene loader itself reads
  /// ("generator", "name", "transform", "subdivision"): a typo must not pass silently.
  void allow_only(std::initializer_list<std::string_view> allowed) const;

  /// An integer in [lo, hi], or \p fallback when the key is absent.
  std::int64_t integer(std::string_view key, std::int64_t fallback, std::int64_t lo,
                       std::int64_t hi) const;
  /// Any non-negative integer that fits 64 bits (random seeds).
  std::uint64_t seed(std::string_view key, std::uint64_t fallback) const;
  /// A finite number > 0.
  double positive(std::string_view key, double fallback) const;
  /// An array of three positive numbers, or a positive number s meaning s · \p ratio.
  Vec3 size3(std::string_view key, Vec3 fallback, Vec3 ratio = {1, 1, 1}) const;
  /// Same for a 2D size [x, z]; returned as {x, 0, z}.
  Vec3 size2(std::string_view key, double fallback) const;

 private:
  const nlohmann::json* find(std::string_view key) const;
  std::string generator_name() const;
  double positive_value(std::string_view key, const nlohmann::json& value) const;

  const nlohmann::json& params_;
  std::string where_;
};

}  // namespace shadowkit::generators
