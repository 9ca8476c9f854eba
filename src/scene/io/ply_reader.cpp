// PLY, ASCII or binary of either byte order. Only the vertex positions, the face index lists
// and triangle strips are kept; every other element and property is skipped, and so are
// header lines PLY does not define (old Blender exporters wrote one), with a warning.
#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "readers.h"
#include "skipped_items.h"
#include "text_cursor.h"

namespace shadowkit::mesh_io {
namespace {

enum class Scalar : std::uint8_t {
  kInt8,
  kUint8,
  kInt16,
  kUint16,
  kInt32,
  kUint32,
  kFloat,
  kDouble
};

std::size_t size_of(Scalar type) {
  static constexpr std::size_t kSizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
  return kSizes[static_cast<int>(type)];
}

std::optional<Scalar> scalar_named(std::string_view name) {
  static constexpr std::pair<std::string_view, Scalar> kNames[] = {
      {"char", Scalar::kInt8},     {"int8", Scalar::kInt8},     {"uchar", Scalar::kUint8},
      {"uint8", Scalar::kUint8},   {"short", Scalar::kInt16},   {"int16", Scalar::kInt16},
      {"ushort", Scalar::kUint16}, {"uint16", Scalar::kUint16}, {"int", Scalar::kInt32},
      {"int32", Scalar::kInt32},   {"uint", Scalar::kUint32},   {"uint32", Scalar::kUint32},
      {"float", Scalar::kFloat},   {"float32", Scalar::kFloat}, {"double", Scalar::kDouble},
      {"float64", Scalar::kDouble}};
  for (const auto& [key, type] : kNames) {
    if (key == name) return type;
  }
  return std::nullopt;
}

// What a property means to the reader; kX, kY and kZ are 1 + the axis.
enum class Role : std::uint8_t { kSkip, kX, kY, kZ, kIndices, kStrip };

struct Property {
  std::string name;
  Scalar type = Scalar::kFloat;  // of the items, for a list
  bool list = false;
  Scalar count_type = Scalar::kUint8;
  Role role = Role::kSkip;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

enum class Encoding { kAscii, kLittleEndian, kBigEndian };

struct Header {
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  Encoding encoding = Encoding::kAscii;
  std::vector<Element> elements;
  std::size_t vertex = kNone;  // positions in elements
  std::size_t face = kNone;
  std::size_t strips = kNone;  // "tristrips": strips of triangles, -1 between strips
};

Property* find_property(Element& element, std::string_view name) {
  for (Property& p : element.properties) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

// The list of vertex indices of a face or strip element, which must hold integers.
Property& index_list(Element& element, const std::string& path) {
  Property* p = find_property(element, "vertex_indices");
  if (p == nullptr) p = find_property(element, "vertex_index");
  if (p == nullptr || !p->list) {
    throw InputError(path,
                     "the " + element.name + " element has no 'vertex_indices' list property");
  }
  if (p->type >= Scalar::kFloat || p->count_type >= Scalar::kFloat) {
    throw InputError(path,
                     "the " + element.name + " property '" + p->name + "' must use integer types");
  }
  return *p;
}

// Marks the properties that matter and checks that the ones needed exist.
void assign_roles(Header& header, const std::string& path) {
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    Element& element = header.elements[e];
    if (element.name == "vertex" && header.vertex == Header::kNone) {
      static constexpr std::pair<Role, std::string_view> kAxes[] = {
          {Role::kX, "x"}, {Role::kY, "y"}, {Role::kZ, "z"}};
      for (const auto& [role, name] : kAxes) {
        Property* p = find_property(element, name);
        if (p == nullptr) {
          throw InputError(path, "the vertex element has no '" + std::string(name) + "' property");
        }
        if (p->list) {
          throw InputError(path, "the vertex property '" + std::string(name) + "' is a list");
        }
        p->role = role;
      }
      header.vertex = e;
    } else if (element.name == "face" && header.face == Header::kNone) {
      index_list(element, path).role = Role::kIndices;
      header.face = e;
    } else if (element.name == "tristrips" && header.strips == Header::kNone) {
      index_list(element, path).role = Role::kStrip;
      header.strips = e;
    }
  }
  if (header.vertex == Header::kNone) {
    throw InputError(path, "the header declares no vertex element");
  }
  if (header.face == Header::kNone && header.strips == Header::kNone) {
    throw InputError(path, "holds no faces (the header declares no face element)");
  }
  const std::uint64_t vertex_count = header.elements[header.vertex].count;
  if (vertex_count > std::numeric_limits<std::uint32_t>::max()) {
    throw InputError(path, "declares " + std::to_string(vertex_count) +
                               " vertices; at most 4294967295 are supported");
  }
}

Header read_header(TextCursor& in, SkippedItems& skipped) {
  Header header;
  if (!in.next_line() || in.token() != "ply" || !in.line_done()) {
    throw InputError(in.path(), "not a PLY file: the first line is not 'ply'");
  }
  bool have_format = false;
  while (true) {
    if (!in.next_line()) throw InputError(in.path(), "the header has no 'end_header' line");
    const std::string_view keyword = in.token();
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") break;
    if (keyword == "format") {
      const std::string_view format = in.token();
      if (format == "ascii") {
        header.encoding = Encoding::kAscii;
      } else if (format == "binary_little_endian") {
        header.encoding = Encoding::kLittleEndian;
      } else if (format == "binary_big_endian") {
        header.encoding = Encoding::kBigEndian;
      } else {
        in.fail("unknown PLY format " + quote(format));
      }
      have_format = true;
    } else if (keyword == "element") {
      Element element;
      element.name = in.token();
      const std::string_view count = in.token();
      const char* end = count.data() + count.size();
      const auto [stop, error] = std::from_chars(count.data(), end, element.count);
      if (element.name.empty() || stop != end || count.empty()) {
        in.fail("expected 'element <name> <count>'");
      }
      // from_chars leaves the count at 0 when it overflows: the element would vanish unread.
      if (error == std::errc::result_out_of_range) {
        in.fail("element count " + quote(count) + " is beyond " +
                std::to_string(std::numeric_limits<std::uint64_t>::max()));
      }
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) in.fail("a property comes before any element");
      Property property;
      std::string_view type = in.token();
      if (type == "list") {
        property.list = true;
        const std::string_view count_type = in.token();
        const auto parsed = scalar_named(count_type);
        if (!parsed) in.fail("unknown property type " + quote(count_type));
        property.count_type = *parsed;
        type = in.token();
      }
      const auto parsed = scalar_named(type);
      if (!parsed) in.fail("unknown property type " + quote(type));
      property.type = *parsed;
      property.name = in.token();
      if (property.name.empty()) in.fail("the property has no name");
      header.elements.back().properties.push_back(std::move(property));
    } else {
      skipped.add("header line(s) that PLY does not define", in.line_number());
    }
  }
  if (!have_format) throw InputError(in.path(), "the header has no 'format' line");
  assign_roles(header, in.path());
  return header;
}

// Values of the ASCII body, one element per line.
class AsciiSource {
 public:
  explicit AsciiSource(TextCursor& in) : in_(in) {}

  void begin_item(const Element& element, std::uint64_t index) {
    if (!in_.next_nonblank_line()) {
      throw InputError(in_.path(), "the file ends at " + element.name + " " +
                                       std::to_string(index) + ", but the header declares " +
                                       std::to_string(element.count));
    }
  }
  void end_item(const Element& element) {
    if (!in_.line_done()) {
      in_.fail("the line holds more values than the header declares for a " + element.name);
    }
  }
  double value(const Property& p, Scalar /*type*/) {
    const std::string_view text = in_.token();
    double value = 0;
    if (!parse_double(text, value)) in_.fail_expected("a value for '" + p.name + "'", text);
    return value;
  }
  void skip(const Property& p, Scalar /*type*/, std::uint64_t n) {
    for (std::uint64_t k = 0; k < n; ++k) {
      if (in_.token().empty()) in_.fail_expected("a value for '" + p.name + "'", {});
    }
  }
  [[noreturn]] void fail(const std::string& what) const { in_.fail(what); }

 private:
  TextCursor& in_;
};

// Values of a binary body; running out of bytes names the element being read.
class BinarySource {
 public:
  BinarySource(std::string_view bytes, bool swap, const std::string& path)
      : next_(bytes.data()), end_(bytes.data() + bytes.size()), swap_(swap), path_(path) {}

  void begin_item(const Element& element, std::uint64_t index) {
    element_ = &element;
    index_ = index;
  }
  void end_item(const Element& /*element*/) {}

  double value(const Property& /*p*/, Scalar type) {
    const char* bytes = take(size_of(type), 1);
    switch (type) {
      case Scalar::kInt8:
        return load<std::int8_t>(bytes);
      case Scalar::kUint8:
        return load<std::uint8_t>(bytes);
      case Scalar::kInt16:
        return load<std::int16_t>(bytes);
      case Scalar::kUint16:
        return load<std::uint16_t>(bytes);
      case Scalar::kInt32:
        return load<std::int32_t>(bytes);
      case Scalar::kUint32:
        return load<std::uint32_t>(bytes);
      case Scalar::kFloat:
        return load<float>(bytes);
      case Scalar::kDouble:
        return load<double>(bytes);
    }
    return 0;
  }
  void skip(const Property& /*p*/, Scalar type, std::uint64_t n) { take(size_of(type), n); }
  [[noreturn]] void fail(const std::string& what) const { throw InputError(path_, what); }

 private:
  const char* take(std::size_t size, std::uint64_t n) {
    if (n > static_cast<std::uint64_t>(end_ - next_) / size) {
      fail("the binary data ends inside " + element_->name + " " + std::to_string(index_) +
           ", but the header declares " + std::to_string(element_->count));
    }
    const char* bytes = next_;
    next_ += size * n;
    return bytes;
  }

  template <typename T>
  T load(const char* bytes) const {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, bytes, sizeof(T));
    if (swap_) std::reverse(raw, raw + sizeof(T));
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

  const char* next_;
  const char* end_;
  bool swap_;
  const std::string& path_;
  const Element* element_ = nullptr;
  std::uint64_t index_ = 0;
};

// Reads a list length, which must be a non-negative whole number.
template <typename Source>
std::uint64_t read_list_count(Source& in, const Property& p, const Element& e, std::uint64_t i) {
  const double n = in.value(p, p.count_type);
  if (!(n >= 0) || n != std::floor(n) || n > 1e15) {
    in.fail(e.name + " " + std::to_string(i) + " has an invalid length (" + format_number(n) +
            ") for its list '" + p.name + "'");
  }
  return static_cast<std::uint64_t>(n);
}

constexpr std::uint32_t kStripRestart = std::numeric_limits<std::uint32_t>::max();

// Adds the triangles of \p strip, whose runs are separated by kStripRestart; every second
// triangle of a run is reversed so that all keep the strip's orientation.
void add_strip_triangles(const std::vector<std::uint32_t>& strip, PolygonSoup& soup) {
  std::size_t run = 0;  // vertices of the current run seen so far
  for (std::size_t k = 0; k < strip.size(); ++k) {
    if (strip[k] == kStripRestart) {
      run = 0;
      continue;
    }
    if (++run < 3) continue;
    const std::uint32_t a = strip[k - 2], b = strip[k - 1], c = strip[k];
    run % 2 == 1 ? soup.add_face({a, b, c}) : soup.add_face({b, a, c});
  }
}

template <typename Source>
void read_body(const Header& header, Source& in, MeshFile& file) {
  PolygonSoup& soup = file.soup;
  const std::uint64_t vertex_count = header.elements[header.vertex].count;
  std::vector<std::uint32_t> face;
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const Element& element = header.elements[e];
    const bool is_vertex = e == header.vertex;
    const bool is_face = e == header.face;
    const bool is_strips = e == header.strips;
    // Items without properties take no bytes; counting through them could take forever.
    if (element.properties.empty()) continue;
    for (std::uint64_t i = 0; i < element.count; ++i) {
      in.begin_item(element, i);
      Vec3 point;
      face.clear();
      for (const Property& p : element.properties) {
        if (!p.list) {
          if (p.role == Role::kSkip) {
            in.skip(p, p.type, 1);
          } else {
            point[static_cast<int>(p.role) - 1] = in.value(p, p.type);
          }
          continue;
        }
        const std::uint64_t n = read_list_count(in, p, element, i);
        if (p.role != Role::kIndices && p.role != Role::kStrip) {
          in.skip(p, p.type, n);
          continue;
        }
        const std::string item = element.name + " " + std::to_string(i);
        for (std::uint64_t k = 0; k < n; ++k) {
          const double index = in.value(p, p.type);
          if (p.role == Role::kStrip && index == -1) {
            face.push_back(kStripRestart);
            continue;
          }
          if (index != std::floor(index)) {
            in.fail(item + " has vertex index " + format_number(index) +
                    ", which is not a whole number");
          }
          if (!(index >= 0 && index < static_cast<double>(vertex_count))) {
            in.fail(item + " has vertex index " + format_number(index) +
                    " out of range (the file has " + std::to_string(vertex_count) + " vertices)");
          }
          face.push_back(static_cast<std::uint32_t>(index));
        }
      }
      in.end_item(element);
      if (is_vertex) {
        for (int axis = 0; axis < 3; ++axis) {
          if (const std::string fault = coordinate_fault(point[axis], format_number(point[axis]));
              !fault.empty()) {
            in.fail("vertex " + std::to_string(i) + " has " + fault);
          }
        }
        soup.positions.push_back(point);
      } else if (is_face && !face.empty()) {
        soup.add_face(face);
      } else if (is_strips) {
        add_strip_triangles(face, soup);
      }
    }
  }
}

// The fewest bytes one item can take, so that a lying count cannot make us reserve too much.
std::uint64_t min_item_bytes(const Element& element, Encoding encoding) {
  std::uint64_t bytes = 0;
  for (const Property& p : element.properties) {
    if (encoding == Encoding::kAscii) {
      bytes += 2;  // a digit and a separator
    } else {
      bytes += size_of(p.list ? p.count_type : p.type);
    }
  }
  return std::max<std::uint64_t>(bytes, 1);
}

}  // namespace

MeshFile read_ply(std::string_view data, const std::string& path, const Context& ctx) {
  refuse_utf16(data, path);
  TextCursor in(data, path);
  SkippedItems skipped;
  const Header header = read_header(in, skipped);
  skipped.warn(path, ctx);
  const std::string_view body = data.substr(std::min(in.offset(), data.size()));

  MeshFile file;
  const Element& vertex = header.elements[header.vertex];
  file.soup.positions.reserve(
      std::min<std::uint64_t>(vertex.count, body.size() / min_item_bytes(vertex, header.encoding)));
  if (header.encoding == Encoding::kAscii) {
    AsciiSource source(in);
    read_body(header, source, file);
  } else {
    const bool big_endian_file = header.encoding == Encoding::kBigEndian;
    BinarySource source(body, big_endian_file != (std::endian::native == std::endian::big), path);
    read_body(header, source, file);
  }
  file.stored_polygons = file.soup.face_count();
  return file;
}

}  // namespace shadowkit::mesh_io
