#include "json_cursor.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace shadowkit {
namespace {

std::string type_name(const nlohmann::json& v) {
  return v.type_name();
}

// A value as a message shows it: scalars as written (long strings cut short), arrays and
// objects by their size, so that a huge or deeply nested value cannot flood the message.
std::string brief(const nlohmann::json& v) {
  if (v.is_array()) return "an array of " + std::to_string(v.size()) + " values";
  if (v.is_object()) return "an object with " + std::to_string(v.size()) + " keys";
  if (v.is_string() && v.get_ref<const std::string&>().size() > 40) {
    return nlohmann::json(v.get_ref<const std::string&>().substr(0, 40)).dump() + "...";
  }
  return v.dump();
}

// Keys seen per open object, and where each open value lies, to name a repeated key's path.
class UniqueKeys : public nlohmann::json_sax<nlohmann::json> {
 public:
  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    open_.push_back({true, {}, {}, 0});
    return true;
  }
  bool key(string_t& key) override {
    Open& object = open_.back();
    object.key = key;
    if (!object.keys.insert(key).second) {
      repeated_ = path();
      return false;
    }
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override {
    open_.push_back({false, {}, {}, 0});
    return true;
  }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    return false;
  }

  std::string repeated_;  ///< the first repeated key's path, empty when there is none

 private:
  struct Open {
    bool object;
    std::set<std::string> keys;  // an object's keys so far
    std::string key;             // an object's current key
    std::size_t index;           // an array's current element
  };
  // A value ends: the array holding it moves to its next element.
  bool value() {
    if (!open_.empty() && !open_.back().object) ++open_.back().index;
    return true;
  }
  bool close() {
    open_.pop_back();
    return value();
  }
  std::string path() const {
    std::string text;
    for (const Open& o : open_) {
      text += o.object ? (text.empty() ? "" : ".") + o.key : "[" + std::to_string(o.index) + "]";
    }
    return text;
  }

  std::vector<Open> open_;
};

}  // namespace

void check_unique_keys(std::string_view text, const std::string& file) {
  UniqueKeys keys;
  nlohmann::json::sax_parse(text, &keys);
  if (!keys.repeated_.empty()) {
    throw InputError(file + ": key '" + keys.repeated_ + "'",
                     "is given twice in one object; JSON would keep only the last");
  }
}

JsonCursor JsonCursor::operator[](const std::string& key) const {
  const std::string child = path_.empty() ? key : path_ + "." + key;
  if (!value_.is_object()) fail("expected an object, got " + type_name(value_));
  if (!value_.contains(key)) throw InputError(file_ + ": key '" + child + "'", "is missing");
  return {value_.at(key), file_, child};
}

JsonCursor JsonCursor::operator[](std::size_t index) const {
  return {value_.at(index), file_, path_ + "[" + std::to_string(index) + "]"};
}

std::size_t JsonCursor::array_size() const {
  if (!value_.is_array()) fail("expected an array, got " + type_name(value_));
  return value_.size();
}

std::vector<std::string> JsonCursor::unknown_keys(const std::vector<std::string>& known) const {
  std::vector<std::string> unknown;
  if (!value_.is_object()) return unknown;
  for (const auto& item : value_.items()) {
    if (std::find(known.begin(), known.end(), item.key()) == known.end()) {
      unknown.push_back(path_.empty() ? item.key() : path_ + "." + item.key());
    }
  }
  return unknown;
}

double JsonCursor::number() const {
  if (!value_.is_number()) fail("expected a number, got " + type_name(value_));
  const double x = value_.get<double>();
  if (!std::isfinite(x)) fail("expected a finite number");
  return x;
}

int JsonCursor::integer(int lo, int hi) const {
  const double x = number();
  if (x != std::floor(x) || x < lo || x > hi) {
    fail("expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
         ", got " + brief(value_));
  }
  return int(x);
}

std::string JsonCursor::string() const {
  if (!value_.is_string()) fail("expected a string, got " + type_name(value_));
  return value_.get<std::string>();
}

Vec3 JsonCursor::vec3() const {
  if (!value_.is_array() || value_.size() != 3) {
    fail("expected an array of three numbers, got " + brief(value_));
  }
  return {(*this)[0].number(), (*this)[1].number(), (*this)[2].number()};
}

Vec3 JsonCursor::scale3() const {
  if (value_.is_number()) {
    const double s = number();
    return {s, s, s};
  }
  return vec3();
}

}  // namespace shadowkit
