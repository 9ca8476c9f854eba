// glTF 2.0: nodes place meshes with matrices and TRS; lists, strips and fans in every index
// type; sparse accessors; .glb; and errors that name the JSON path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "mesh_io_test_files.h"

namespace shadowkit::mesh_io_test {
namespace {

using ::testing::AllOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

std::string base64(const std::string& bytes) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t chunk = 0;
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    for (std::size_t k = 0; k < 3; ++k) {
      chunk = chunk << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0);
    }
    for (std::size_t k = 0; k < 4; ++k) {
      out += k <= n ? kDigits[(chunk >> (18 - 6 * k)) & 63] : '=';
    }
  }
  return out;
}

/// \brief A glTF built piece by piece: one buffer, views and accessors appended in order.
class GltfBuilder {
 public:
  /// Appends float VEC3 positions; returns the accessor's index.
  int positions(const std::vector<Vec3>& points) {
    ByteWriter w;
    for (const Vec3& p : points) w.put(float(p.x)).put(float(p.y)).put(float(p.z));
    return accessor(w.bytes(), 5126, "VEC3", points.size());
  }
  /// Appends indices of \p component_type (5121, 5123 or 5125).
  int indices(const std::vector<std::uint32_t>& values, int component_type) {
    ByteWriter w;
    for (std::uint32_t v : values) {
      if (component_type == 5121) w.put(std::uint8_t(v));
      if (component_type == 5123) w.put(std::uint16_t(v));
      if (component_type == 5125) w.put(v);
    }
    return accessor(w.bytes(), component_type, "SCALAR", values.size());
  }
  /// A raw accessor entry, for tests that need one the helpers do not make.
  void add_accessor(const std::string& json) { accessors_.push_back(json); }

  /// The whole file, buffer embedded as a data URI.
  std::string gltf(const std::string& meshes, const std::string& nodes,
                   const std::string& scenes = R"([{"nodes": [0]}])") const {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": )" + scenes + R"(, "nodes": )" +
           nodes + R"(, "meshes": )" + meshes + R"(, "accessors": [)" + join(accessors_) +
           R"(], "bufferViews": [)" + join(views_) + R"(], "buffers": [{"byteLength": )" +
           std::to_string(buffer_.size()) + R"(, "uri": "data:application/octet-stream;base64,)" +
           base64(buffer_) + "\"}]}";
  }

  /// The same as a .glb: the JSON chunk and the buffer as the BIN chunk.
  std::string glb(const std::string& meshes, const std::string& nodes) const {
    std::string json =
        R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": )" +
        nodes + R"(, "meshes": )" + meshes + R"(, "accessors": [)" + join(accessors_) +
        R"(], "bufferViews": [)" + join(views_) + R"(], "buffers": [{"byteLength": )" +
        std::to_string(buffer_.size()) + "}]}";
    while (json.size() % 4 != 0) json += ' ';
    std::string bin = buffer_;
    while (bin.size() % 4 != 0) bin += '\0';
    ByteWriter w;
    w.text("glTF").put(std::uint32_t(2)).put(std::uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    w.put(std::uint32_t(json.size())).text("JSON").text(json);
    w.put(std::uint32_t(bin.size())).text("BIN").put(std::uint8_t(0)).text(bin);
    return w.bytes();
  }

 private:
  int accessor(const std::string& bytes, int component_type, const char* type, std::size_t count) {
    while (buffer_.size() % 4 != 0) buffer_ += '\0';
    views_.push_back(R"({"buffer": 0, "byteOffset": )" + std::to_string(buffer_.size()) +
                     R"(, "byteLength": )" + std::to_string(bytes.size()) + "}");
    buffer_ += bytes;
    accessors_.push_back(R"({"bufferView": )" + std::to_string(views_.size() - 1) +
                         R"(, "componentType": )" + std::to_string(component_type) +
                         R"(, "type": ")" + type + R"(", "count": )" + std::to_string(count) + "}");
    return static_cast<int>(accessors_.size() - 1);
  }
  static std::string join(const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
    return out;
  }

  std::string buffer_;
  std::vector<std::string> views_, accessors_;
};

const std::vector<Vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

std::string mesh_of(int position, int indices = -1, int mode = 4) {
  return R"({"primitives": [{"attributes": {"POSITION": )" + std::to_string(position) + "}" +
         (indices >= 0 ? R"(, "indices": )" + std::to_string(indices) : std::string()) +
         R"(, "mode": )" + std::to_string(mode) + "}]}";
}

class GltfTest : public MeshFileTest {
 protected:
  MeshFile read(const std::string& name, const std::string& bytes) {
    return read_mesh_file(write(name, bytes), ctx_);
  }
};

void expect_near(Vec3 a, Vec3 b) {
  EXPECT_NEAR(a.x, b.x, 1e-6);
  EXPECT_NEAR(a.y, b.y, 1e-6);
  EXPECT_NEAR(a.z, b.z, 1e-6);
}

TEST_F(GltfTest, NodesComposeTranslationRotationScaleAndMatrices) {
  GltfBuilder b;
  const int p = b.positions(kTriangle);
  // Node 0 moves by (10, 0, 0); its child turns 90 degrees about y and doubles the size; the
  // grandchild's matrix moves by (0, 0, 1) in the child's frame.
  const std::string nodes = R"([{"translation": [10, 0, 0], "children": [1]},
    {"rotation": [0, 0.7071067811865476, 0, 0.7071067811865476], "scale": [2, 2, 2], "mesh": 0,
     "children": [2]},
    {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,1,1], "mesh": 0}])";
  const MeshFile file = read("nodes.gltf", b.gltf("[" + mesh_of(p) + "]", nodes));
  ASSERT_EQ(file.soup.face_count(), 2u);
  EXPECT_EQ(file.stored_polygons, 1u) << "one mesh, placed twice, is stored once";
  // (1, 0, 0) turned about y is (0, 0, -1), doubled, moved: (10, 0, -2).
  expect_near(file.soup.positions[1], {10, 0, -2});
  expect_near(file.soup.positions[2], {10, 2, 0});
  // The grandchild's (0, 0, 1) offset is turned and doubled too: (2, 0, 0) on top.
  expect_near(file.soup.positions[3], {12, 0, 0});
  expect_near(file.soup.positions[4], {12, 0, -2});
}

TEST_F(GltfTest, ListsStripsAndFansInEveryIndexType) {
  GltfBuilder b;
  const int p = b.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 0, 0}});
  const int list8 = b.indices({0, 1, 2, 2, 1, 3}, 5121);
  // A strip with a repeated index joining two runs: its degenerate triangles make no face.
  const int strip16 = b.indices({0, 1, 2, 3, 3, 4, 4, 1}, 5123);
  const int fan32 = b.indices({1, 4, 3, 2}, 5125);
  const MeshFile lists = read(
      "modes.gltf", b.gltf(R"([{"primitives": [{"attributes": {"POSITION": )" + std::to_string(p) +
                               R"(}, "indices": )" + std::to_string(list8) +
                               R"(}, {"attributes": {"POSITION": )" + std::to_string(p) +
                               R"(}, "indices": )" + std::to_string(strip16) +
                               R"(, "mode": 5}, {"attributes": {"POSITION": )" + std::to_string(p) +
                               R"(}, "indices": )" + std::to_string(fan32) + R"(, "mode": 6}]}])",
                           R"([{"mesh": 0}])"));
  // 2 listed; the strip's 6 triangles less the 4 that repeat an index; the fan's 2.
  EXPECT_EQ(lists.soup.face_count(), 2u + 2u + 2u);
  EXPECT_EQ(lists.stored_polygons, 2u + 6u + 2u);
  auto face = [&](std::size_t f) {
    const std::uint32_t base = 5 * static_cast<std::uint32_t>(f < 2 ? 0 : f < 4 ? 1 : 2);
    std::vector<std::uint32_t> corners;
    for (std::uint32_t k = lists.soup.face_start[f]; k < lists.soup.face_start[f + 1]; ++k) {
      corners.push_back(lists.soup.indices[k] - base);
    }
    return corners;
  };
  EXPECT_THAT(face(1), ElementsAre(2, 1, 3));
  // Strip triangles alternate: (0 1 2), (2 1 3) reversed back to the strip's winding.
  EXPECT_THAT(face(2), ElementsAre(0, 1, 2));
  EXPECT_THAT(face(3), ElementsAre(2, 1, 3));
  EXPECT_THAT(face(4), ElementsAre(1, 4, 3));
  EXPECT_THAT(face(5), ElementsAre(1, 3, 2));
}

TEST_F(GltfTest, PointsAndLinesAreSkippedAndCounted) {
  GltfBuilder b;
  b.positions(kTriangle);
  const MeshFile file =
      read("mixed.gltf", b.gltf(R"([{"primitives": [{"attributes": {"POSITION": 0}, "mode": 0},
                                 {"attributes": {"POSITION": 0}, "mode": 3},
                                 {"attributes": {"POSITION": 0}}]}])",
                                R"([{"mesh": 0}])"));
  EXPECT_EQ(file.soup.face_count(), 1u);
  EXPECT_EQ(file.skipped_primitives, 3u + 2u);
  EXPECT_THAT(
      warnings_,
      ElementsAre(at("mixed.gltf") + "skipped 1 point primitive(s) (they bound no surface)",
                  at("mixed.gltf") + "skipped 1 line primitive(s) (they bound no surface)"));
}

TEST_F(GltfTest, SparseAccessorsReplaceTheirElements) {
  GltfBuilder b;
  b.positions(kTriangle);
  b.indices({2}, 5125);      // accessor 1: which element
  b.positions({{0, 5, 0}});  // accessor 2: its new value
  b.add_accessor(R"({"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 3,
    "sparse": {"count": 1, "indices": {"bufferView": 1, "componentType": 5125},
               "values": {"bufferView": 2}}})");
  const MeshFile file = read("sparse.gltf", b.gltf("[" + mesh_of(3) + "]", R"([{"mesh": 0}])"));
  expect_near(file.soup.positions[2], {0, 5, 0});
  expect_near(file.soup.positions[1], {1, 0, 0});
}

TEST_F(GltfTest, BinaryGlbReadsLikeTheJson) {
  GltfBuilder b;
  const int p = b.positions(kTriangle);
  const MeshFile file = read(
      "triangle.glb", b.glb("[" + mesh_of(p) + "]", R"([{"mesh": 0, "translation": [0, 0, 3]}])"));
  ASSERT_EQ(file.soup.face_count(), 1u);
  expect_near(file.soup.positions[2], {0, 1, 3});
}

TEST_F(GltfTest, ErrorsNameTheJsonPath) {
  GltfBuilder b;
  const int p = b.positions(kTriangle);
  const int bad = b.indices({0, 1, 9}, 5123);
  EXPECT_EQ(
      error("range.gltf", b.gltf("[" + mesh_of(p, bad) + "]", R"([{"mesh": 0}])")),
      at("range.gltf") + "key 'accessors[1]': index 9 is out of range (POSITION has 3 elements)");
  EXPECT_EQ(error("cycle.gltf", b.gltf("[" + mesh_of(p) + "]",
                                       R"([{"children": [1]}, {"mesh": 0, "children": [0]}])")),
            at("cycle.gltf") + "key 'nodes[1].children': names node 0, its own ancestor");
  EXPECT_EQ(error("node.gltf", b.gltf("[" + mesh_of(p) + "]", R"([{"mesh": 4}])")),
            at("node.gltf") + "key 'nodes[0].mesh': index 4 is out of range (1 defined)");
  b.add_accessor(
      R"({"bufferView": 0, "byteOffset": 8, "componentType": 5126, "type": "VEC3", "count": 3})");
  EXPECT_EQ(error("view.gltf", b.gltf("[" + mesh_of(2) + "]", R"([{"mesh": 0}])")),
            at("view.gltf") +
                "key 'accessors[2]': 3 elements from byte 8 do not fit its buffer view's 36 bytes");
  EXPECT_EQ(
      error("scale.gltf", b.gltf("[" + mesh_of(p) + "]", R"([{"mesh": 0, "scale": [1, 2]}])")),
      at("scale.gltf") + "key 'nodes[0].scale': expected 3 numbers");
  EXPECT_EQ(error("deep.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"extras\": " +
                                   std::string(10000, '[') + std::string(10000, ']') + "}"),
            at("deep.gltf", 1) + "JSON nested deeper than 100 levels");
  EXPECT_THAT(error("broken.gltf", "{\"asset\": "),
              HasSubstr(at("broken.gltf") + "not a valid glTF 2.0 file: "));
}

// tinygltf's messages quote the file: a damaged data URI of any length, or control bytes. The
// message stays one short line that a terminal prints as it is.
TEST_F(GltfTest, TinygltfMessagesAreCutShortAndPrintable) {
  const std::string said = "Failed to decode 'uri' : ";
  const std::string uri = "data:application/octet-stream;base64," + std::string(100000, 'A') + "!";
  const std::string buffers = R"(, "buffers": [{"byteLength": 4, "uri": ")" + uri + "\"}]";
  EXPECT_EQ(error("long.gltf", R"({"asset": {"version": "2.0"})" + buffers + "}"),
            at("long.gltf") + "not a valid glTF 2.0 file: " + said +
                uri.substr(0, 160 - said.size()) + "...");
  EXPECT_EQ(error("escape.gltf", R"({"asset": {"version": "2.0"},
    "buffers": [{"byteLength": 4, "uri": "red\u001b[31m\u0007.bin"}]})"),
            at("escape.gltf") + "not a valid glTF 2.0 file: File not found : red?[31m?.bin");
}

TEST_F(GltfTest, AMissingBufferFileIsNamed) {
  const std::string gltf =
      R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 36, "uri": "gone.bin"}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 3}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "nodes": [{"mesh": 0}]})";
  EXPECT_THAT(
      error("external.gltf", gltf),
      AllOf(HasSubstr(at("external.gltf") + "not a valid glTF 2.0 file: "), HasSubstr("gone.bin")));
  ByteWriter w;
  for (const Vec3& v : kTriangle) w.put(float(v.x)).put(float(v.y)).put(float(v.z));
  write("gone.bin", w.bytes());
  EXPECT_EQ(read("external.gltf", gltf).soup.face_count(), 1u) << "found beside the file";
}

// A buffer in a device or a pipe may never end: reading it would fill the memory.
TEST_F(GltfTest, ABufferInADeviceIsRefused) {
  std::filesystem::create_symlink("/dev/zero", dir_ / "zero.bin");
  const std::string gltf =
      R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 36, "uri": "zero.bin"}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 3}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "nodes": [{"mesh": 0}]})";
  EXPECT_EQ(error("zero.gltf", gltf),
            at("zero.gltf") + "not a valid glTF 2.0 file: File read error : " +
                (dir_ / "zero.bin").string() + " : it is not a regular file");
}

}  // namespace
}  // namespace shadowkit::mesh_io_test
