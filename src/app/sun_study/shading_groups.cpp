#include "shading_groups.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <map>
#include <string_view>
#include <unordered_set>

#include "shadowkit/core/error.h"

namespace shadowkit::sun_study {
namespace {

constexpr std::string_view kHeader = "surface,object,faces";
// What EnergyPlus's input would read as syntax in a name: a semicolon ends an object and an
// exclamation mark starts a comment; a quote would need CSV quoting in the schedule's header.
constexpr std::string_view kUnsafe = ";!\"";

std::string_view trimmed(std::string_view s) {
  const std::size_t first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

std::vector<std::string_view> fields(std::string_view line) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    out.push_back(trimmed(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

bool parse_index(std::string_view text, std::uint32_t& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size() && !text.empty();
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return out;
}

// Per object of polygons.csv, the row of each of its faces.
std::vector<std::vector<std::uint32_t>> rows_by_object(const Polygons& polygons) {
  std::vector<std::vector<std::uint32_t>> rows;
  for (std::uint32_t p = 0; p < polygons.rows.size(); ++p) {
    const Polygons::Row& row = polygons.rows[p];
    if (row.object >= rows.size()) rows.resize(row.object + 1);
    if (row.face >= rows[row.object].size()) rows[row.object].resize(row.face + 1);
    rows[row.object][row.face] = p;
  }
  return rows;
}

// The inclusive range of faces `all`, `F` or `F-G` of an object with \p count faces.
std::pair<std::uint32_t, std::uint32_t> face_range(std::string_view text, std::size_t count,
                                                   const std::string& where) {
  if (text == "all") return {0, std::uint32_t(count - 1)};
  const std::size_t dash = text.find('-');
  std::uint32_t first = 0, last = 0;
  const bool parsed =
      dash == std::string_view::npos
          ? parse_index(text, first) && (last = first, true)
          : parse_index(text.substr(0, dash), first) && parse_index(text.substr(dash + 1), last);
  if (!parsed || first > last) {
    throw InputError(where,
                     "faces '" + std::string(text) + "': expected F, F-G with F <= G, or all");
  }
  if (last >= count) {
    throw InputError(where, "faces '" + std::string(text) + "': the object has faces 0 to " +
                                std::to_string(count - 1));
  }
  return {first, last};
}

}  // namespace

ShadingGroups read_shading_groups(const std::filesystem::path& file, const Polygons& polygons) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "cannot open");
  const std::vector<std::vector<std::uint32_t>> faces = rows_by_object(polygons);
  ShadingGroups result;
  std::map<std::string, std::size_t> group_of_name;  // lower case: EnergyPlus ignores case
  std::vector<std::unordered_set<std::uint32_t>> members;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string where = file.string() + ":" + std::to_string(number);
    if (number == 1) {
      // Spreadsheets save "CSV UTF-8" with a byte order mark.
      if (line.starts_with("\xEF\xBB\xBF")) line.erase(0, 3);
      if (line != kHeader) throw InputError(where, "expected the header 'surface,object,faces'");
      continue;
    }
    if (trimmed(line).empty()) continue;
    const std::vector<std::string_view> cells = fields(line);
    if (cells.size() != 3) {
      throw InputError(
          where, "expected 3 fields surface,object,faces; got " + std::to_string(cells.size()));
    }
    const std::string_view surface = cells[0];
    if (surface.empty()) throw InputError(where, "no surface name");
    if (surface.find_first_of(kUnsafe) != std::string_view::npos) {
      throw InputError(
          where, "surface '" + std::string(surface) + "': EnergyPlus names cannot hold ; ! or \"");
    }
    // A control character would break the schedule's header line (a carriage return) or be
    // unprintable in a message: refused, and the name left out of the message.
    if (std::any_of(surface.begin(), surface.end(),
                    [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; })) {
      throw InputError(where, "the surface name holds a control character");
    }
    std::uint32_t object = 0;
    if (!parse_index(cells[1], object) || object >= faces.size() || faces[object].empty()) {
      throw InputError(
          where, "object '" + std::string(cells[1]) + "' is no object of the study's polygons.csv");
    }
    const auto [first, last] = face_range(cells[2], faces[object].size(), where);
    const auto [it, added] = group_of_name.try_emplace(lower(surface), result.groups.size());
    if (added) {
      result.groups.push_back({std::string(surface), {}});
      members.emplace_back();
    }
    ShadingGroups::Group& group = result.groups[it->second];
    for (std::uint32_t f = first; f <= last; ++f) {
      const std::uint32_t row = faces[object][f];
      if (!members[it->second].insert(row).second) {
        throw InputError(where, "object " + std::to_string(object) + " face " + std::to_string(f) +
                                    " is already in surface '" + group.surface + "'");
      }
      group.polygons.push_back(row);
    }
  }
  if (number == 0)
    throw InputError(file.string(), "empty: expected the header 'surface,object,faces'");
  return result;
}

}  // namespace shadowkit::sun_study
