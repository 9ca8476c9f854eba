#include "sun_hours_ply.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <string>
#include <type_traits>

#include "contract_files.h"
#include "shadowkit/core/colour_map.h"
#include "shadowkit/core/error.h"

namespace shadowkit::sun_study {
namespace {

// Bytes gathered before each write to the stream.
constexpr std::size_t kFlushBytes = std::size_t(1) << 20;

// Little-endian bytes whatever the machine's order, as the header promises.
template <class T>
void append_le(std::string& out, T value) {
  using Bits = std::conditional_t<sizeof(T) == 8, std::uint64_t,
                                  std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint8_t>>;
  const auto bits = std::bit_cast<Bits>(value);
  for (std::size_t b = 0; b < sizeof(T); ++b) out.push_back(char((bits >> (8 * b)) & 0xff));
}

void flush_if_full(std::ostream& out, std::string& bytes) {
  if (bytes.size() < kFlushBytes) return;
  out.write(bytes.data(), std::streamsize(bytes.size()));
  bytes.clear();
}

}  // namespace

void write_sun_hours_ply(std::ostream& out, const Scene& scene, const Polygons& polygons,
                         const std::vector<double>& hours) {
  SHADOWKIT_CHECK(hours.size() == polygons.rows.size());
  double largest = 0;
  std::size_t vertices = 0, faces = 0;
  std::uint32_t widest = 0;
  for (std::size_t p = 0; p < hours.size(); ++p) {
    if (polygons.rows[p].area > 0) largest = std::max(largest, hours[p]);
  }
  for (const SceneObject& object : scene.objects) {
    vertices += object.mesh.vertices.size();
    faces += object.mesh.face_count();
    for (std::size_t f = 0; f < object.mesh.face_count(); ++f) {
      widest = std::max(widest, object.mesh.face_size(f));
    }
  }
  const double top = largest > 0 ? largest : 1.0;
  // A uchar count, as most viewers expect, unless a face has more corners than it holds.
  const bool wide = widest > 255;
  out << "ply\nformat binary_little_endian 1.0\n"
      << "comment shadowkit sun study " << scene.name << ": sun hours per face, coloured from 0 to "
      << decimal(top) << " h\n"
      << "element vertex " << vertices << "\nproperty double x\nproperty double y\n"
      << "property double z\nelement face " << faces << "\nproperty list "
      << (wide ? "int" : "uchar") << " int vertex_indices\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "property float sun_hours\nproperty int polygon\nend_header\n";
  std::string bytes;
  for (const SceneObject& object : scene.objects) {
    for (const Vec3 v : object.mesh.vertices) {
      const Vec3 world = scene.frame.to_world(v);
      for (int i = 0; i < 3; ++i) append_le(bytes, world[i]);
      flush_if_full(out, bytes);
    }
  }
  std::uint32_t first_vertex = 0;
  for (const SceneObject& object : scene.objects) {
    const Mesh& mesh = object.mesh;
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      const std::uint32_t row = polygons.row_of_face[object.first_face + f];
      const std::uint32_t size = mesh.face_size(f);
      if (wide) {
        append_le(bytes, std::int32_t(size));
      } else {
        append_le(bytes, std::uint8_t(size));
      }
      for (std::uint32_t k = 0; k < size; ++k) {
        append_le(bytes, std::int32_t(first_vertex + mesh.face_vertex(f, k)));
      }
      const Rgb8 colour = sequential_colour(hours[row] / top);
      for (const std::uint8_t channel : {colour.r, colour.g, colour.b}) append_le(bytes, channel);
      append_le(bytes, float(hours[row]));
      append_le(bytes, std::int32_t(row));
      flush_if_full(out, bytes);
    }
    first_vertex += std::uint32_t(mesh.vertices.size());
  }
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

}  // namespace shadowkit::sun_study
