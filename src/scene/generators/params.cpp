#include "params.h"

#include <cmath>
#include <utility>

#include "shadowkit/core/error.h"

namespace shadowkit::generators {
namespace {

/// Keys of an object entry that the scene loader reads itself and passes through.
constexpr std::string_view kLoaderKeys[] = {"generator", "name", "transform", "subdivision",
                                            "tessellation"};

std::string type_name(const nlohmann::json& value) {
  return value.type_name();
}

}  // namespace

ParamReader::ParamReader(const nlohmann::json& params, std::string where)
    : params_(params), where_(std::move(where)) {
  if (!params_.is_object()) {
    throw InputError(
        where_, "expected an object such as {\"generator\": \"cubes\"}, got " + type_name(params_));
  }
}

std::string ParamReader::key_where(std::string_view key) const {
  return key_location(where_, std::string(key));
}

void ParamReader::fail(std::string_view key, const std::string& what) const {
  throw InputError(key_where(key), what);
}

void ParamReader::allow_only(std::initializer_list<std::string_view> allowed) const {
  for (const auto& [key, value] : params_.items()) {
    bool known = false;
    for (std::string_view k : allowed) known = known || key == k;
    for (std::string_view k : kLoaderKeys) known = known || key == k;
    if (known) continue;
    std::string list;
    for (std::string_view k : allowed) list += (list.empty() ? "'" : ", '") + std::string(k) + "'";
    fail(key, "unknown parameter of generator " + generator_name() +
                  (list.empty() ? " (it takes none)" : " (expected " + list + ")"));
  }
}

std::string ParamReader::generator_name() const {
  const nlohmann::json* name = find("generator");
  return name != nullptr && name->is_string() ? "'" + name->get<std::string>() + "'" : "?";
}

const nlohmann::json* ParamReader::find(std::string_view key) const {
  auto it = params_.find(key);
  return it == params_.end() ? nullptr : &*it;
}

std::int64_t ParamReader::integer(std::string_view key, std::int64_t fallback, std::int64_t lo,
                                  std::int64_t hi) const {
  const nlohmann::json* value = find(key);
  if (value == nullptr) return fallback;
  if (!value->is_number_integer()) fail(key, "expected an integer, got " + type_name(*value));
  const std::string range = " (allowed: " + std::to_string(lo) + " to " + std::to_string(hi) + ")";
  // Unsigned JSON integers may exceed int64_t; compare before converting.
  if (value->is_number_unsigned() && value->get<std::uint64_t>() > std::uint64_t(hi)) {
    fail(key, value->dump() + " is too large" + range);
  }
  const auto n = value->get<std::int64_t>();
  if (n < lo) fail(key, value->dump() + " is too small" + range);
  if (n > hi) fail(key, value->dump() + " is too large" + range);
  return n;
}

std::uint64_t ParamReader::seed(std::string_view key, std::uint64_t fallback) const {
  const nlohmann::json* value = find(key);
  if (value == nullptr) return fallback;
  if (!value->is_number_integer()) fail(key, "expected an integer, got " + type_name(*value));
  if (value->is_number_unsigned()) return value->get<std::uint64_t>();
  const auto n = value->get<std::int64_t>();
  if (n < 0) fail(key, "expected a non-negative integer, got " + value->dump());
  return static_cast<std::uint64_t>(n);
}

double ParamReader::positive_value(std::string_view key, const nlohmann::json& value) const {
  if (!value.is_number()) fail(key, "expected a number, got " + type_name(value));
  const auto x = value.get<double>();
  if (!std::isfinite(x) || x <= 0) fail(key, "expected a positive number, got " + value.dump());
  return x;
}

double ParamReader::positive(std::string_view key, double fallback) const {
  const nlohmann::json* value = find(key);
  return value == nullptr ? fallback : positive_value(key, *value);
}

Vec3 ParamReader::size3(std::string_view key, Vec3 fallback, Vec3 ratio) const {
  const nlohmann::json* value = find(key);
  if (value == nullptr) return fallback;
  if (value->is_number()) {
    const double s = positive_value(key, *value);
    return s * ratio;
  }
  if (!value->is_array() || value->size() != 3) {
    fail(key, "expected a positive number or an array of 3 positive numbers");
  }
  return {positive_value(key, (*value)[0]), positive_value(key, (*value)[1]),
          positive_value(key, (*value)[2])};
}

Vec3 ParamReader::size2(std::string_view key, double fallback) const {
  const nlohmann::json* value = find(key);
  if (value == nullptr) return {fallback, 0, fallback};
  if (value->is_number()) {
    const double s = positive_value(key, *value);
    return {s, 0, s};
  }
  if (!value->is_array() || value->size() != 2) {
    fail(key, "expected a positive number or an array of 2 positive numbers [x, z]");
  }
  return {positive_value(key, (*value)[0]), 0, positive_value(key, (*value)[1])};
}

}  // namespace shadowkit::generators
