// STL, ASCII or binary. Every facet gets its own three positions; welding is the mesh
// builder's job.
#include <algorithm>
#include <bit>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "readers.h"
#include "text_cursor.h"

namespace shadowkit::mesh_io {
namespace {

constexpr std::size_t kHeaderBytes = 84;  // 80-byte header and a uint32 triangle count
constexpr std::size_t kRecordBytes = 50;  // normal, three vertices, attribute word

template <typename T>
T load_little_endian(const char* bytes) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, bytes, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(raw, raw + sizeof(T));
  T value;
  std::memcpy(&value, raw, sizeof(T));
  return value;
}

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

// Binary files may begin with "solid" too; the record count matching the size is the reliable
// sign, and bytes no text holds after the header are the next best.
bool is_binary(std::string_view data) {
  if (data.size() >= kHeaderBytes) {
    const auto count = load_little_endian<std::uint32_t>(data.data() + 80);
    if (kHeaderBytes + kRecordBytes * std::uint64_t{count} == data.size()) return true;
  }
  const std::string_view text = without_utf8_bom(data);
  const std::size_t start = text.find_first_not_of(" \t\r\n");
  if (start == std::string_view::npos || !equals_ignoring_case(text.substr(start, 5), "solid")) {
    return true;
  }
  const std::string_view sample = text.substr(std::min<std::size_t>(text.size(), 80), 1024);
  return std::any_of(sample.begin(), sample.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x09 || (u > 0x0d && u < 0x20) || u == 0x7f;
  });
}

PolygonSoup read_binary(std::string_view data, const std::string& path) {
  if (data.size() < kHeaderBytes) {
    throw InputError(path,
                     "is neither ASCII STL (it does not start with 'solid') nor binary STL "
                     "(it is shorter than the 84-byte header)");
  }
  const auto count = load_little_endian<std::uint32_t>(data.data() + 80);
  const std::uint64_t held = (data.size() - kHeaderBytes) / kRecordBytes;
  if (held < count) {
    throw InputError(path, "binary STL declares " + std::to_string(count) +
                               " triangles but the file holds only " + std::to_string(held));
  }
  PolygonSoup soup;
  soup.positions.reserve(std::size_t{count} * 3);
  const char* record = data.data() + kHeaderBytes;
  for (std::uint32_t t = 0; t < count; ++t, record += kRecordBytes) {
    const auto first = static_cast<std::uint32_t>(soup.positions.size());
    for (int corner = 0; corner < 3; ++corner) {
      Vec3 p;
      for (int axis = 0; axis < 3; ++axis) {
        const auto value = load_little_endian<float>(record + 12 * (corner + 1) + 4 * axis);
        if (const std::string fault = coordinate_fault(value, format_number(value));
            !fault.empty()) {
          throw InputError(path, "triangle " + std::to_string(t) + " has " + fault);
        }
        p[axis] = value;
      }
      soup.positions.push_back(p);
    }
    soup.add_face({first, first + 1, first + 2});
  }
  return soup;
}

void expect(TextCursor& in, std::string_view keyword) {
  const std::string_view found = in.token_across_lines();
  if (!equals_ignoring_case(found, keyword)) {
    in.fail("expected '" + std::string(keyword) + "', found " +
            (found.empty() ? std::string("the end of the file") : quote(found)));
  }
}

PolygonSoup read_ascii(std::string_view data, const std::string& path) {
  TextCursor in(data, path);
  PolygonSoup soup;
  std::vector<std::uint32_t> face;
  expect(in, "solid");
  in.skip_rest_of_line();  // the solid's name
  for (std::int64_t facet = 0;;) {
    const std::string_view keyword = in.token_across_lines();
    if (equals_ignoring_case(keyword, "endsolid")) {
      in.skip_rest_of_line();
      // Some files hold several solids one after another.
      const std::string_view next = in.token_across_lines();
      if (next.empty()) break;
      if (!equals_ignoring_case(next, "solid")) {
        in.fail("expected 'solid' or the end of the file, found " + quote(next));
      }
      in.skip_rest_of_line();
      continue;
    }
    if (!equals_ignoring_case(keyword, "facet")) {
      in.fail("expected 'facet' or 'endsolid', found " +
              (keyword.empty() ? std::string("the end of the file") : quote(keyword)));
    }
    in.skip_rest_of_line();  // the normal, which is recomputed from the vertices anyway
    expect(in, "outer");
    expect(in, "loop");
    face.clear();
    for (std::string_view word = in.token_across_lines(); !equals_ignoring_case(word, "endloop");
         word = in.token_across_lines()) {
      if (!equals_ignoring_case(word, "vertex")) {
        in.fail("expected 'vertex' or 'endloop', found " +
                (word.empty() ? std::string("the end of the file") : quote(word)));
      }
      face.push_back(static_cast<std::uint32_t>(soup.positions.size()));
      soup.positions.push_back(in.read_point("facet", facet));
    }
    if (face.size() < 3) {
      in.fail("facet " + std::to_string(facet) + " has " + std::to_string(face.size()) +
              " vertices; a facet needs 3");
    }
    expect(in, "endfacet");
    soup.add_face(face);
    ++facet;
  }
  return soup;
}

}  // namespace

MeshFile read_stl(std::string_view data, const std::string& path, const Context& /*ctx*/) {
  MeshFile file;
  file.soup = is_binary(data) ? read_binary(data, path) : read_ascii(data, path);
  file.stored_polygons = file.soup.face_count();
  return file;
}

}  // namespace shadowkit::mesh_io
