// Wavefront OBJ: "v" and "f" (or the older "fo") statements make the polygons. Points ("p")
// and lines ("l") bound no surface and free-form geometry is not supported: both are skipped
// with a warning. Grouping, smoothing and material statements are ignored.
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "readers.h"
#include "skipped_items.h"
#include "text_cursor.h"

namespace shadowkit::mesh_io {
namespace {

// Statements that only name, group or decorate what "v" and "f" define.
constexpr std::string_view kIgnored[] = {"vt",       "vn",       "g",          "o",         "s",
                                         "mg",       "usemtl",   "mtllib",     "lod",       "bevel",
                                         "c_interp", "d_interp", "shadow_obj", "trace_obj", "ctech",
                                         "stech",    "maplib",   "usemap"};
// Free-form curves and surfaces (OBJ spec, "Free-form curve/surface attributes").
constexpr std::string_view kFreeForm[] = {"vp",   "cstype", "deg",  "bmat", "step",
                                          "curv", "curv2",  "surf", "parm", "trim",
                                          "hole", "scrv",   "sp",   "end",  "con"};

bool one_of(std::string_view word, std::span<const std::string_view> words) {
  for (std::string_view w : words) {
    if (w == word) return true;
  }
  return false;
}

[[noreturn]] void fail_corner(const TextCursor& in, std::string_view corner) {
  in.fail("face vertex " + quote(corner) + " is malformed (expected i, i/t, i//n or i/t/n)");
}

// The position index of a corner "i", "i/t", "i//n" or "i/t/n", as written (1-based, or
// negative counting back from the latest vertex). Texture and normal indices only have to be
// well-formed where they are present.
std::int64_t corner_index(const TextCursor& in, std::string_view corner) {
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
  for (int k = 1; k < part_count; ++k) {
    if (!parts[k].empty() && !parse_int(parts[k], ignored)) fail_corner(in, corner);
  }
  if (index == 0) in.fail("face index 0 is invalid (OBJ indices start at 1)");
  return index;
}

/// \brief The file's faces as written; positive indices may point at vertices defined further
/// down (assimp and Blender accept that), so they are checked once the whole file is read.
class ObjFaces {
 public:
  void add(const TextCursor& in, const std::vector<std::int64_t>& corners,
           std::size_t vertices_so_far, PolygonSoup& soup) {
    face_.clear();
    for (std::int64_t index : corners) {
      // Negative indices count back from the latest vertex, so they resolve now.
      const std::int64_t resolved =
          index > 0 ? index - 1 : static_cast<std::int64_t>(vertices_so_far) + index;
      if (resolved < 0) {
        in.fail("face index " + std::to_string(index) + " is out of range (the file has " +
                std::to_string(vertices_so_far) + " vertices so far)");
      }
      if (resolved >= max_index_ + 1) {
        max_index_ = resolved;
        max_index_line_ = in.line_number();
      }
      if (resolved > std::numeric_limits<std::uint32_t>::max()) {
        in.fail("face index " + std::to_string(index) + " is beyond 4294967295");
      }
      face_.push_back(static_cast<std::uint32_t>(resolved));
    }
    soup.add_face(face_);
  }

  /// Throws when a face names a vertex the file never defines.
  void check(const std::string& path, std::size_t vertex_count) const {
    if (max_index_ >= static_cast<std::int64_t>(vertex_count)) {
      throw InputError(path + ":" + std::to_string(max_index_line_),
                       "face index " + std::to_string(max_index_ + 1) +
                           " is out of range (the file has " + std::to_string(vertex_count) +
                           " vertices)");
    }
  }

 private:
  std::vector<std::uint32_t> face_;
  std::int64_t max_index_ = -1;
  std::size_t max_index_line_ = 0;
};

}  // namespace

MeshFile read_obj(std::string_view data, const std::string& path, const Context& ctx) {
  refuse_utf16(data, path);
  TextCursor in(data, path, {.comment = '#', .continuations = true});
  MeshFile file;
  PolygonSoup& soup = file.soup;
  ObjFaces faces;
  SkippedItems skipped;
  std::vector<std::int64_t> corners;
  std::size_t empty_faces = 0;
  while (in.next_line()) {
    const std::string_view keyword = in.token();
    if (keyword.empty() || one_of(keyword, kIgnored)) continue;
    if (keyword == "v") {
      if (soup.positions.size() == std::numeric_limits<std::uint32_t>::max()) {
        in.fail("too many vertices (at most 4294967295 are supported)");
      }
      soup.positions.push_back(in.read_point("vertex", soup.positions.size() + 1));
      // An optional w, or r g b colours some exporters add: ignored but still checked.
      while (!in.line_done()) in.read_double("a number");
      continue;
    }
    corners.clear();
    const bool polygon = keyword == "f" || keyword == "fo";
    if (polygon || keyword == "l" || keyword == "p") {
      for (std::string_view corner = in.token(); !corner.empty(); corner = in.token()) {
        corners.push_back(corner_index(in, corner));
      }
    }
    if (corners.empty() && (keyword == "l" || keyword == "p")) {
      skipped.add("statement(s) without vertex indices", in.line_number());
    } else if (polygon) {
      // A face line keeps its place in the file's numbering even without corners (the sun
      // study's polygons are the faces in file order): a degenerate face, dropped later.
      empty_faces += corners.empty();
      faces.add(in, corners, soup.positions.size(), soup);
    } else if (keyword == "l") {
      // Counted as importers count them: one primitive per segment.
      file.skipped_primitives += corners.size() > 1 ? corners.size() - 1 : 1;
      skipped.add("line statement(s) 'l' (lines bound no surface)", in.line_number());
    } else if (keyword == "p") {
      file.skipped_primitives += corners.size();
      skipped.add("point statement(s) 'p' (points bound no surface)", in.line_number());
    } else if (one_of(keyword, kFreeForm)) {
      skipped.add("free-form curve or surface statement(s) (not supported)", in.line_number());
    } else {
      skipped.add("unknown statement(s)", in.line_number());
    }
  }
  faces.check(path, soup.positions.size());
  file.stored_polygons = soup.face_count() - empty_faces;  // as importers count them
  skipped.warn(path, ctx);
  return file;
}

}  // namespace shadowkit::mesh_io
