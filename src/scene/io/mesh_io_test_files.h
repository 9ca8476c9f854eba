#pragma once
// Test helpers: a scratch directory per test, a byte writer for binary formats, and one unit
// cube written in every supported format.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "shadowkit/core/error.h"
#include "shadowkit/scene/mesh_io.h"

namespace shadowkit {

// Readable failure output for geometry comparisons.
inline void PrintTo(const Vec3& p, std::ostream* out) {
  *out << "(" << p.x << ", " << p.y << ", " << p.z << ")";
}

namespace mesh_io_test {

/// Gives each test an empty directory of its own and removes it afterwards.
class MeshFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ =
        std::filesystem::temp_directory_path() / ("shadowkit-mesh-io-" + std::string(info->name()) +
                                                  "-" + std::to_string(std::random_device()()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }

  std::filesystem::path write(const std::string& name, std::string_view bytes) const {
    const std::filesystem::path path = dir_ / name;
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::ssize(bytes));
    return path;
  }

  /// The message read_mesh_file() throws for \p path; fails the test when it throws nothing.
  std::string error_of(const std::filesystem::path& path) const {
    try {
      read_mesh_file(path, ctx_);
    } catch (const InputError& error) {
      return error.what();
    }
    ADD_FAILURE() << "reading " << path << " did not throw";
    return {};
  }

  /// The message read_mesh_file() throws for a file \p name holding \p bytes.
  std::string error(const std::string& name, std::string_view bytes) const {
    return error_of(write(name, bytes));
  }
  /// The location prefix of messages about \p name, at \p line.
  std::string at(const std::string& name, int line) const {
    return (dir_ / name).string() + ":" + std::to_string(line) + ": ";
  }
  std::string at(const std::string& name) const { return (dir_ / name).string() + ": "; }

  std::filesystem::path dir_;
  /// Warnings of the readers, in order.
  std::vector<std::string> warnings_;
  Context ctx_{.threads = 0, .warn = [this](const std::string& w) { warnings_.push_back(w); }};
};

/// Builds binary file contents value by value in either byte order.
class ByteWriter {
 public:
  explicit ByteWriter(bool big_endian = false) : big_endian_(big_endian) {}

  template <typename T>
  ByteWriter& put(T value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    if (big_endian_ != (std::endian::native == std::endian::big))
      std::reverse(raw, raw + sizeof(T));
    bytes_.append(raw, sizeof(T));
    return *this;
  }
  ByteWriter& text(std::string_view s) {
    bytes_.append(s);
    return *this;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  bool big_endian_;
  std::string bytes_;
};

// A cube with corners at ±0.5 (exact in float) and outward quads.
inline const std::vector<Vec3> kCubePositions = {
    {-0.5, -0.5, -0.5}, {0.5, -0.5, -0.5}, {0.5, 0.5, -0.5}, {-0.5, 0.5, -0.5},
    {-0.5, -0.5, 0.5},  {0.5, -0.5, 0.5},  {0.5, 0.5, 0.5},  {-0.5, 0.5, 0.5}};
inline const std::vector<std::vector<std::uint32_t>> kCubeQuads = {
    {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};

inline std::string cube_obj() {
  std::string s = "# unit cube\no cube\n";
  for (Vec3 p : kCubePositions) {
    s += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  }
  for (const auto& quad : kCubeQuads) {
    s += "f";
    for (std::uint32_t i : quad) s += " " + std::to_string(i + 1);
    s += "\n";
  }
  return s;
}

// "x y z" lines for the cube's vertices, then "4 a b c d" lines for its faces: the body that
// OFF and ASCII PLY share.
inline std::string cube_vertex_and_face_lines() {
  std::string s;
  for (Vec3 p : kCubePositions) {
    s += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  }
  for (const auto& quad : kCubeQuads) {
    s += "4";
    for (std::uint32_t i : quad) s += " " + std::to_string(i);
    s += "\n";
  }
  return s;
}

inline std::string cube_off() {
  std::string s = "OFF\n# unit cube\n8 6 12\n";
  return s + cube_vertex_and_face_lines();
}

inline std::string cube_ply_ascii() {
  std::string s =
      "ply\nformat ascii 1.0\ncomment unit cube\nelement vertex 8\nproperty float x\n"
      "property float y\nproperty float z\nelement face 6\nproperty list uchar int "
      "vertex_indices\nend_header\n";
  return s + cube_vertex_and_face_lines();
}

/// A binary PLY cube that also exercises skipped properties: a normal, a list on the
/// vertices, a second list on the faces and an edge element.
inline std::string cube_ply_binary(bool big_endian) {
  ByteWriter w(big_endian);
  w.text("ply\nformat ");
  w.text(big_endian ? "binary_big_endian" : "binary_little_endian");
  w.text(
      " 1.0\nelement vertex 8\nproperty float64 x\nproperty short tag\nproperty double y\n"
      "property list uint8 float texcoords\nproperty float32 z\nelement face 6\n"
      "property uchar flags\nproperty list uchar uint vertex_index\n"
      "property list int ushort extra\nelement edge 1\nproperty int vertex1\n"
      "property int vertex2\nend_header\n");
  for (Vec3 p : kCubePositions) {
    w.put<double>(p.x).put<std::int16_t>(-7).put<double>(p.y);
    w.put<std::uint8_t>(2).put<float>(0.25f).put<float>(0.75f).put<float>(static_cast<float>(p.z));
  }
  for (const auto& quad : kCubeQuads) {
    w.put<std::uint8_t>(1).put<std::uint8_t>(4);
    for (std::uint32_t i : quad) w.put<std::uint32_t>(i);
    w.put<std::int32_t>(1).put<std::uint16_t>(9);
  }
  w.put<std::int32_t>(0).put<std::int32_t>(1);
  return w.bytes();
}

/// The cube's faces split into triangle fans, as STL needs.
inline std::vector<std::vector<std::uint32_t>> cube_triangles() {
  std::vector<std::vector<std::uint32_t>> triangles;
  for (const auto& q : kCubeQuads) {
    triangles.push_back({q[0], q[1], q[2]});
    triangles.push_back({q[0], q[2], q[3]});
  }
  return triangles;
}

inline std::string cube_stl_ascii() {
  std::string s = "solid cube\n";
  for (const auto& t : cube_triangles()) {
    s += "  facet normal 0 0 0\n    outer loop\n";
    for (std::uint32_t i : t) {
      const Vec3 p = kCubePositions[i];
      s += "      vertex " + std::to_string(p.x) + " " + std::to_string(p.y) + " " +
           std::to_string(p.z) + "\n";
    }
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid cube\n";
}

/// A binary STL whose header starts with "solid", as many exporters write it.
inline std::string cube_stl_binary() {
  ByteWriter w;
  std::string header = "solid cube written by a binary exporter";
  header.resize(80, ' ');
  w.text(header);
  w.put<std::uint32_t>(12);
  for (const auto& t : cube_triangles()) {
    w.put<float>(0).put<float>(0).put<float>(0);
    for (std::uint32_t i : t) {
      const Vec3 p = kCubePositions[i];
      w.put<float>(static_cast<float>(p.x))
          .put<float>(static_cast<float>(p.y))
          .put<float>(static_cast<float>(p.z));
    }
    w.put<std::uint16_t>(0);
  }
  return w.bytes();
}

/// Each face as the list of its corner positions: geometry independent of vertex sharing.
inline std::vector<std::vector<Vec3>> face_corners(const PolygonSoup& soup) {
  std::vector<std::vector<Vec3>> faces;
  for (std::size_t f = 0; f < soup.face_count(); ++f) {
    faces.emplace_back();
    for (std::uint32_t k = soup.face_start[f]; k < soup.face_start[f + 1]; ++k) {
      faces.back().push_back(soup.positions.at(soup.indices.at(k)));
    }
  }
  return faces;
}

inline std::vector<std::vector<Vec3>> face_corners(
    const std::vector<Vec3>& positions, const std::vector<std::vector<std::uint32_t>>& faces) {
  std::vector<std::vector<Vec3>> result;
  for (const auto& face : faces) {
    result.emplace_back();
    for (std::uint32_t i : face) result.back().push_back(positions[i]);
  }
  return result;
}

}  // namespace mesh_io_test
}  // namespace shadowkit
