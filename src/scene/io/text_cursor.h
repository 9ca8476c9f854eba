#pragma once
/// \brief Line and token scanning shared by the text mesh formats (OBJ, ASCII PLY, OFF, ASCII
/// STL), with the line number kept for error messages.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <utility>

#include "shadowkit/core/error.h"
#include "shadowkit/core/vec.h"
#include "shadowkit/scene/limits.h"

namespace shadowkit::mesh_io {

/// Parses a whole token as a number; false when any of it is not part of one.
inline bool parse_double(std::string_view token, double& value) {
  // from_chars rejects a leading '+', which some exporters write.
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  auto [stop, error] = std::from_chars(token.data(), end, value);
  if (stop != end || token.empty()) return false;
  if (error == std::errc::result_out_of_range) {
    // Overflow and underflow both still name a number: strtod maps them to ±inf and ~0.
    value = std::strtod(std::string(token).c_str(), nullptr);
    return true;
  }
  return error == std::errc();
}

inline bool parse_int(std::string_view token, std::int64_t& value) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  auto [stop, error] = std::from_chars(token.data(), end, value);
  return !token.empty() && stop == end && error == std::errc();
}

/// The shortest text that reads back as \p value ("99", "0.5", "nan", "-inf").
inline std::string format_number(double value) {
  char buffer[32];
  auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return error == std::errc() ? std::string(buffer, end) : std::string("?");
}

/// \p text cut to \p longest bytes ("..." marks the cut) with control bytes masked, so that
/// binary garbage cannot flood or break a one-line message.
inline std::string printable(std::string_view text, std::size_t longest) {
  std::string shown;
  for (char c : text.substr(0, longest)) {
    const auto u = static_cast<unsigned char>(c);
    shown += u < 0x20 || u == 0x7f ? '?' : c;
  }
  return shown + (text.size() > longest ? "..." : "");
}

/// What is wrong with \p value, written \p shown, as a vertex coordinate ("a non-finite
/// coordinate (nan)"), or nothing: a scene's coordinates lie within +-limits::kCoordinate.
inline std::string coordinate_fault(double value, std::string_view shown) {
  if (std::abs(value) <= limits::kCoordinate) return {};
  const std::string written = " (" + printable(shown, 40) + ")";
  return std::isfinite(value) ? "a coordinate beyond +-1e15" + written + ", which is not supported"
                              : "a non-finite coordinate" + written;
}

/// A token quoted for a message, cut short and with control bytes masked.
inline std::string quote(std::string_view token) {
  return "'" + printable(token, 32) + "'";
}

/// The first line of a library's message (tinygltf's, assimp's), made printable: such
/// messages quote the file, a whole data URI or an IFC schema name of any length.
inline std::string first_line(std::string_view message) {
  return printable(message.substr(0, message.find('\n')), 160);
}

/// \p text without a leading UTF-8 byte order mark, which some Windows tools write.
inline std::string_view without_utf8_bom(std::string_view text) {
  return text.starts_with("\xEF\xBB\xBF") ? text.substr(3) : text;
}

/// Throws when \p text begins with a UTF-16 byte order mark: read as bytes it would give
/// messages about characters the file does not hold.
inline void refuse_utf16(std::string_view text, const std::string& path) {
  if (text.starts_with("\xFF\xFE") || text.starts_with("\xFE\xFF")) {
    throw InputError(path, "is UTF-16 text; save it as UTF-8 or ASCII");
  }
}

/// \brief Walks a text line by line and each line token by token (whitespace-separated).
///
/// Skips a UTF-8 byte order mark, strips '\r' (CRLF files), and optionally comments and
/// '\'-continued lines. Errors thrown through fail() name the file and the current line.
class TextCursor {
 public:
  struct Options {
    char comment = '\0';         ///< starts a comment running to the end of the line
    bool continuations = false;  ///< a line ending in '\' goes on on the next line
  };

  TextCursor(std::string_view text, std::string path, Options options)
      : text_(text),
        path_(std::move(path)),
        options_(options),
        next_(text.size() - without_utf8_bom(text).size()) {}
  TextCursor(std::string_view text, std::string path) : TextCursor(text, std::move(path), {}) {}

  /// Moves to the next line; false at the end of the text.
  bool next_line() {
    if (next_ >= text_.size()) {
      rest_ = {};
      return false;
    }
    line_number_ = next_line_number_;
    rest_ = take_physical_line();
    if (options_.continuations && ends_with_backslash(rest_)) {
      joined_.clear();
      do {
        rest_.remove_suffix(1);
        joined_.append(rest_).push_back(' ');
        rest_ = next_ < text_.size() ? take_physical_line() : std::string_view();
      } while (ends_with_backslash(rest_));
      joined_.append(rest_);
      rest_ = joined_;
    }
    return true;
  }

  /// Moves to the next line that holds a token; false at the end of the text.
  bool next_nonblank_line() {
    while (next_line()) {
      if (!line_done()) return true;
    }
    return false;
  }

  /// The next token on the current line; empty when the line has none left.
  std::string_view token() {
    skip_space();
    std::size_t n = 0;
    while (n < rest_.size() && !is_space(rest_[n])) ++n;
    std::string_view token = rest_.substr(0, n);
    rest_.remove_prefix(n);
    return token;
  }

  /// The next token, moving on to later lines as needed; empty at the end of the text.
  std::string_view token_across_lines() {
    while (line_done()) {
      if (!next_line()) return {};
    }
    return token();
  }

  /// True when only whitespace is left on the current line.
  bool line_done() {
    skip_space();
    return rest_.empty();
  }
  void skip_rest_of_line() { rest_ = {}; }

  /// Reads a number; \p what names it for the message when it is missing or malformed
  /// ("an x coordinate" gives "expected an x coordinate, found 'abc'").
  double read_double(std::string_view what) {
    std::string_view text = token();
    double value = 0;
    if (!parse_double(text, value)) fail_expected(what, text);
    return value;
  }
  std::int64_t read_int(std::string_view what) {
    std::string_view text = token();
    std::int64_t value = 0;
    if (!parse_int(text, value)) fail_expected(what, text);
    return value;
  }

  /// Reads "x y z" and insists on coordinates (coordinate_fault); \p noun and \p number name
  /// the point in the message ("vertex 3 has a non-finite coordinate (nan)").
  Vec3 read_point(std::string_view noun, std::int64_t number) {
    static constexpr std::string_view kAxes[] = {"an x coordinate", "a y coordinate",
                                                 "a z coordinate"};
    Vec3 point;
    for (int axis = 0; axis < 3; ++axis) {
      std::string_view text = token();
      if (!parse_double(text, point[axis])) fail_expected(kAxes[axis], text);
      if (const std::string fault = coordinate_fault(point[axis], text); !fault.empty()) {
        fail(std::string(noun) + " " + std::to_string(number) + " has " + fault);
      }
    }
    return point;
  }

  /// Throws InputError("path:line", what).
  [[noreturn]] void fail(const std::string& what) const { throw InputError(where(), what); }
  [[noreturn]] void fail_expected(std::string_view what, std::string_view found) const {
    fail("expected " + std::string(what) + ", found " +
         (found.empty() ? std::string("the end of the line") : quote(found)));
  }

  std::string where() const { return path_ + ":" + std::to_string(line_number_); }
  const std::string& path() const { return path_; }
  std::size_t line_number() const { return line_number_; }
  /// Byte offset just past the current line's end (where binary PLY data starts).
  std::size_t offset() const { return next_; }

 private:
  static bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  }
  static bool ends_with_backslash(std::string_view line) {
    while (!line.empty() && is_space(line.back())) line.remove_suffix(1);
    return !line.empty() && line.back() == '\\';
  }

  std::string_view take_physical_line() {
    std::size_t end = text_.find('\n', next_);
    if (end == std::string_view::npos) end = text_.size();
    std::string_view line = text_.substr(next_, end - next_);
    next_ = end + 1;
    ++next_line_number_;
    if (options_.comment != '\0') line = line.substr(0, line.find(options_.comment));
    return line;
  }

  void skip_space() {
    std::size_t n = 0;
    while (n < rest_.size() && is_space(rest_[n])) ++n;
    rest_.remove_prefix(n);
  }

  std::string_view text_;
  std::string path_;
  Options options_;
  std::size_t next_;  // offset of the next physical line
  std::size_t line_number_ = 0;
  std::size_t next_line_number_ = 1;
  std::string_view rest_;  // the unread part of the current line
  std::string joined_;     // a line assembled from '\'-continued pieces
};

}  // namespace shadowkit::mesh_io
