// Object File Format: "OFF", the vertex, face and edge counts, one vertex per line, then one
// face per line as "n i0 ... i(n-1)" with optional colour values after the indices.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "readers.h"
#include "text_cursor.h"

namespace shadowkit::mesh_io {
namespace {

constexpr std::string_view kCounts = "the vertex, face and edge counts";

// Reads the counts from \p tokens, which may be the rest of the header line or the line after.
void parse_counts(TextCursor& in, std::vector<std::string_view>& tokens, std::uint64_t& vertices,
                  std::uint64_t& faces) {
  if (tokens.empty()) {
    if (!in.next_nonblank_line()) {
      in.fail("expected " + std::string(kCounts) + ", found the end of the file");
    }
    for (std::string_view t = in.token(); !t.empty(); t = in.token()) tokens.push_back(t);
  }
  // The edge count is often missing and is never used.
  if (tokens.size() < 2 || tokens.size() > 3) {
    in.fail("expected " + std::string(kCounts) + ", found " + std::to_string(tokens.size()) +
            (tokens.size() == 1 ? " value" : " values"));
  }
  std::int64_t counts[3] = {0, 0, 0};
  for (std::size_t k = 0; k < tokens.size(); ++k) {
    if (!parse_int(tokens[k], counts[k]) || counts[k] < 0) in.fail_expected(kCounts, tokens[k]);
  }
  if (counts[0] > std::numeric_limits<std::uint32_t>::max()) {
    in.fail("declares " + std::to_string(counts[0]) +
            " vertices; at most 4294967295 are supported");
  }
  vertices = static_cast<std::uint64_t>(counts[0]);
  faces = static_cast<std::uint64_t>(counts[1]);
}

}  // namespace

MeshFile read_off(std::string_view data, const std::string& path, const Context& /*ctx*/) {
  refuse_utf16(data, path);
  TextCursor in(data, path, {.comment = '#'});
  if (!in.next_nonblank_line()) throw InputError(path, "holds no faces (the file has no content)");

  // The keyword may carry prefixes (COFF, NOFF, STCNOFF, ...); a few writers glue the vertex
  // count onto it ("OFF1000").
  const std::string_view keyword = in.token();
  const std::size_t off = keyword.find("OFF");
  if (off == std::string_view::npos) in.fail("not an OFF file: it does not start with 'OFF'");
  const std::string_view prefix = keyword.substr(0, off);
  if (prefix.find_first_of("4n") != std::string_view::npos) {
    in.fail("only 3-dimensional OFF files are supported, not " + quote(keyword));
  }
  if (prefix.find_first_not_of("STCN") != std::string_view::npos) {
    in.fail("not an OFF file: unknown header keyword " + quote(keyword));
  }
  std::vector<std::string_view> count_tokens;
  if (keyword.size() > off + 3) count_tokens.push_back(keyword.substr(off + 3));
  for (std::string_view t = in.token(); !t.empty(); t = in.token()) {
    if (t == "BINARY") in.fail("binary OFF files are not supported");
    count_tokens.push_back(t);
  }
  std::uint64_t vertex_count = 0, face_count = 0;
  parse_counts(in, count_tokens, vertex_count, face_count);

  MeshFile file;
  PolygonSoup& soup = file.soup;
  // Each vertex needs a line of at least six bytes, so the file's size bounds an honest count.
  soup.positions.reserve(std::min<std::uint64_t>(vertex_count, data.size() / 6));
  for (std::uint64_t v = 0; v < vertex_count; ++v) {
    if (!in.next_nonblank_line()) {
      throw InputError(path, "the file ends at vertex " + std::to_string(v) +
                                 ", but its header declares " + std::to_string(vertex_count));
    }
    soup.positions.push_back(in.read_point("vertex", static_cast<std::int64_t>(v)));
    // Anything after x y z is a normal, colour or texture coordinate: ignored.
  }

  std::vector<std::uint32_t> face;
  for (std::uint64_t f = 0; f < face_count; ++f) {
    if (!in.next_nonblank_line()) {
      throw InputError(path, "the file ends at face " + std::to_string(f) +
                                 ", but its header declares " + std::to_string(face_count));
    }
    const std::int64_t n = in.read_int("a face's vertex count");
    if (n < 0) in.fail("face " + std::to_string(f) + " has a negative vertex count");
    face.clear();
    for (std::int64_t k = 0; k < n; ++k) {
      const std::int64_t index = in.read_int("a vertex index");
      if (index < 0 || static_cast<std::uint64_t>(index) >= vertex_count) {
        in.fail("face " + std::to_string(f) + " has vertex index " + std::to_string(index) +
                " out of range (the file has " + std::to_string(vertex_count) + " vertices)");
      }
      face.push_back(static_cast<std::uint32_t>(index));
    }
    // What is left on the line is the face's colour: an index, or 3 or 4 components.
    for (int component = 0; !in.line_done(); ++component) {
      const std::string_view text = in.token();
      double value = 0;
      if (component == 4 || !parse_double(text, value)) {
        in.fail("face " + std::to_string(f) + ": expected at most a colour (up to 4 numbers) " +
                "after its vertex indices, found " + quote(text));
      }
    }
    if (!face.empty()) soup.add_face(face);
  }
  file.stored_polygons = soup.face_count();
  return file;
}

}  // namespace shadowkit::mesh_io
