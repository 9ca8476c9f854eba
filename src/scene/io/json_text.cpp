#include "json_text.h"

#include <algorithm>

#include "shadowkit/core/error.h"
#include "shadowkit/scene/limits.h"

namespace shadowkit {
namespace {

std::string at_line(std::string_view text, std::size_t offset, const std::string& file) {
  const std::size_t end = std::min(offset, text.size());
  return file + ":" + std::to_string(1 + std::count(text.begin(), text.begin() + end, '\n'));
}

// The DOM parser, with the position of the error it meets kept: nlohmann's own exceptions
// give a byte offset only for syntax errors, not for numbers that overflow.
class PositionedParser : public nlohmann::detail::json_sax_dom_parser<nlohmann::json> {
 public:
  using json_sax_dom_parser::json_sax_dom_parser;
  template <class Exception>
  bool parse_error(std::size_t position, const std::string& /*last_token*/,
                   const Exception& error) {
    position_ = position;
    what_ = error.what();
    return false;
  }
  std::size_t position_ = 0;
  std::string what_;
};

}  // namespace

void check_json_depth(std::string_view text, const std::string& file) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limits::kJsonDepth) {
        throw InputError(
            at_line(text, i, file),
            "JSON nested deeper than " + std::to_string(limits::kJsonDepth) + " levels");
      }
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

nlohmann::json parse_json_text(std::string_view text, const std::string& file) {
  check_json_depth(text, file);
  nlohmann::json json;
  PositionedParser parser(json, /*allow_exceptions=*/false);
  if (nlohmann::json::sax_parse(text, &parser) && !parser.is_errored()) return json;
  // nlohmann's messages begin "[json.exception.parse_error.101] parse error at line 1,
  // column 5: " or "[json.exception.out_of_range.406] "; the line is said once, in front.
  std::string what = parser.what_.substr(parser.what_.find("] ") + 2);
  if (what.starts_with("parse error")) what = what.substr(what.find(": ") + 2);
  // The token nlohmann quotes may be a 400-digit number or a whole line.
  constexpr std::size_t kLongest = 160;
  if (what.size() > kLongest) what = what.substr(0, kLongest) + "...";
  throw InputError(at_line(text, parser.position_, file), "malformed JSON: " + what);
}

}  // namespace shadowkit
