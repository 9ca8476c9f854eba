// Wavefront OBJ: only "v" and "f" statements matter here; every other statement is ignored.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "readers.h"
#include "text_cursor.h"

namespace shadowkit::mesh_io {
namespace {

[[noreturn]] void fail_corner(const TextCursor& in, std::string_view corner) {
  in.fail("face vertex " + quote(corner) + " is malformed (expected i, i/t, i//n or i/t/n)");
}

// A face corner "i", "i/t", "i//n" or "i/t/n" gives the 0-based position index; texture and
// normal indices only have to be well-formed.
std::uint32_t parse_corner(const TextCursor& in, std::string_view corner,
                           std::size_t vertex_count) {
  std::string_view parts[3];
  int part_count = 0;
  for (std::string_view rest = corner;;) {
    if (part_count == 3) fail_corner(in, corner);
    const std::size_t slash = rest.find('/');
    parts[part_count++] = rest.substr(0, slash);
    if (slash == std::string_view::npos) break;
    rest.remove_prefix(slash + 1);
  }
  std::int64_t index = 0, ignored = 0;
  if (!parse_int(parts[0], index)) fail_corner(in, corner);
  // "i//n" leaves the texture index empty; nothing else may be.
  if (part_count >= 2 && !(part_count == 3 && parts[1].empty()) && !parse_int(parts[1], ignored)) {
    fail_corner(in, corner);
  }
  if (part_count == 3 && !parse_int(parts[2], ignored)) fail_corner(in, corner);
  if (index == 0) in.fail("face index 0 is invalid (OBJ indices start at 1)");
  const auto count = static_cast<std::int64_t>(vertex_count);
  // Negative indices count back from the latest vertex.
  const std::int64_t resolved = index > 0 ? index - 1 : count + index;
  if (resolved < 0 || resolved >= count) {
    in.fail("face index " + std::to_string(index) + " is out of range (the file has " +
            std::to_string(count) + " vertices so far)");
  }
  return static_cast<std::uint32_t>(resolved);
}

}  // namespace

PolygonSoup read_obj(std::string_view data, const std::string& path) {
  TextCursor in(data, path, {.comment = '#', .continuations = true});
  PolygonSoup soup;
  std::vector<std::uint32_t> face;
  while (in.next_line()) {
    const std::string_view keyword = in.token();
    if (keyword == "v") {
      if (soup.positions.size() == std::numeric_limits<std::uint32_t>::max()) {
        in.fail("too many vertices (at most 4294967295 are supported)");
      }
      soup.positions.push_back(in.read_point("vertex", soup.positions.size() + 1));
      // An optional w, or r g b colours some exporters add: ignored but still checked.
      while (!in.line_done()) in.read_double("a number");
    } else if (keyword == "f") {
      face.clear();
      for (std::string_view corner = in.token(); !corner.empty(); corner = in.token()) {
        face.push_back(parse_corner(in, corner, soup.positions.size()));
      }
      if (face.empty()) in.fail("face has no vertex indices");
      soup.add_face(face);
    }
  }
  return soup;
}

}  // namespace shadowkit::mesh_io
