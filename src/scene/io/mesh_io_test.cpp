// The readers agree on the same cube in every format and accept the variants real files use.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mesh_io_test_files.h"

namespace shadowkit::mesh_io_test {
namespace {

using ::testing::ElementsAre;

class MeshIoTest : public MeshFileTest {
 protected:
  PolygonSoup read(const std::string& name, std::string_view bytes) const {
    return read_mesh_file(write(name, bytes), ctx_).soup;
  }
  // The shared-vertex formats must give the cube's exact positions and index lists.
  static void expect_indexed_cube(const PolygonSoup& soup) {
    EXPECT_EQ(soup.positions, kCubePositions);
    ASSERT_EQ(soup.face_count(), 6u);
    EXPECT_THAT(soup.face_start, ElementsAre(0, 4, 8, 12, 16, 20, 24));
    std::vector<std::uint32_t> indices;
    for (const auto& quad : kCubeQuads) indices.insert(indices.end(), quad.begin(), quad.end());
    EXPECT_EQ(soup.indices, indices);
  }
  // STL gives each triangle its own three positions.
  static void expect_triangle_cube(const PolygonSoup& soup) {
    EXPECT_EQ(soup.positions.size(), 36u);
    ASSERT_EQ(soup.face_count(), 12u);
    EXPECT_EQ(face_corners(soup), face_corners(kCubePositions, cube_triangles()));
  }
};

TEST_F(MeshIoTest, ObjCubeWithQuads) {
  expect_indexed_cube(read("cube.obj", cube_obj()));
}
TEST_F(MeshIoTest, PlyAsciiCube) {
  expect_indexed_cube(read("cube.ply", cube_ply_ascii()));
}
TEST_F(MeshIoTest, PlyBinaryLittleEndianCube) {
  expect_indexed_cube(read("cube.ply", cube_ply_binary(false)));
}
TEST_F(MeshIoTest, PlyBinaryBigEndianCube) {
  expect_indexed_cube(read("cube.ply", cube_ply_binary(true)));
}
TEST_F(MeshIoTest, OffCube) {
  expect_indexed_cube(read("cube.off", cube_off()));
}
TEST_F(MeshIoTest, StlAsciiCube) {
  expect_triangle_cube(read("cube.stl", cube_stl_ascii()));
}
TEST_F(MeshIoTest, StlBinaryCubeWhoseHeaderStartsWithSolid) {
  expect_triangle_cube(read("cube.stl", cube_stl_binary()));
}

TEST_F(MeshIoTest, ExtensionIsCaseInsensitive) {
  expect_indexed_cube(read("CUBE.OBJ", cube_obj()));
  expect_indexed_cube(read("Cube.Ply", cube_ply_ascii()));
}

TEST_F(MeshIoTest, ObjNegativeIndicesCountBackFromTheLatestVertex) {
  const PolygonSoup soup = read("neg.obj",
                                "v 0 0 0\nv 1 0 0\nv 1 1 0\n"
                                "f -3 -2 -1\n"
                                "v 0 1 0\n"
                                "f 1 -2 -1\n");
  ASSERT_EQ(soup.face_count(), 2u);
  EXPECT_THAT(soup.indices, ElementsAre(0, 1, 2, 0, 2, 3));
}

TEST_F(MeshIoTest, ObjFaceCornerForms) {
  const PolygonSoup soup = read("forms.obj",
                                "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n"
                                "f 1 2/2 3//1 4/3/1\n"
                                "f 4/3/1 3/2/1 2/1/1\n");
  ASSERT_EQ(soup.face_count(), 2u);
  EXPECT_THAT(soup.indices, ElementsAre(0, 1, 2, 3, 3, 2, 1));
}

TEST_F(MeshIoTest, ObjIgnoresOtherStatementsAndComments) {
  const PolygonSoup soup = read("other.obj",
                                "mtllib a.mtl\n# comment\n\no thing\ng group\ns off\n"
                                "usemtl red\nv 0 0 0 1.0  # with w\nv 1 0 0\nv 0 1 0\n"
                                "vp 0.5\nl 1 2\ncstype bezier\nf 1 2 3 # trailing\n");
  EXPECT_EQ(soup.positions.size(), 3u);
  EXPECT_THAT(soup.indices, ElementsAre(0, 1, 2));
}

TEST_F(MeshIoTest, ObjLineContinuation) {
  const PolygonSoup soup = read("cont.obj", "v 0 0 \\\n 0\nv 1 0 0\nv 0 1 0\nf 1 \\\n2 3\n");
  EXPECT_EQ(soup.positions.size(), 3u);
  EXPECT_THAT(soup.indices, ElementsAre(0, 1, 2));
}

TEST_F(MeshIoTest, ObjKeepsShortFacesAsGiven) {
  const PolygonSoup soup = read("short.obj", "v 0 0 0\nv 1 0 0\nf 1 2\nf 1\n");
  EXPECT_THAT(soup.face_start, ElementsAre(0, 2, 3));
}

TEST_F(MeshIoTest, CrlfLineEndings) {
  auto crlf = [](std::string s) {
    std::string out;
    for (char c : s) out += c == '\n' ? std::string("\r\n") : std::string(1, c);
    return out;
  };
  expect_indexed_cube(read("crlf.obj", crlf(cube_obj())));
  expect_indexed_cube(read("crlf.off", crlf(cube_off())));
  expect_indexed_cube(read("crlf.ply", crlf(cube_ply_ascii())));
  expect_triangle_cube(read("crlf.stl", crlf(cube_stl_ascii())));
}

TEST_F(MeshIoTest, PolygonsKeepAllTheirVertices) {
  const std::string obj =
      "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nv 4 2 0\n"
      "f 1 2 3 4 5\nf 1 2 3 6 4 5\n";
  for (const PolygonSoup& soup :
       {read("poly.obj", obj), read("poly.off",
                                    "OFF 6 2 0\n0 0 0\n2 0 0\n3 1 0\n1 2 0\n-1 1 0\n4 2 0\n"
                                    "5 0 1 2 3 4\n6 0 1 2 5 3 4 255 0 0\n")}) {
    EXPECT_THAT(soup.face_start, ElementsAre(0, 5, 11));
    EXPECT_THAT(soup.indices, ElementsAre(0, 1, 2, 3, 4, 0, 1, 2, 5, 3, 4));
  }
}

TEST_F(MeshIoTest, OffHeaderVariants) {
  // Counts on the keyword line, a colour per vertex and per face, no edge count.
  const PolygonSoup coff = read("c.off",
                                "COFF 3 1\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n"
                                "0 1 0 0 0 255 255\n3 0 1 2 0.5 0.5 0.5\n");
  EXPECT_EQ(coff.positions.size(), 3u);
  EXPECT_THAT(coff.indices, ElementsAre(0, 1, 2));
  // Some writers glue the vertex count onto the keyword.
  const PolygonSoup glued = read("g.off", "OFF3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 2 1 0\n");
  EXPECT_THAT(glued.indices, ElementsAre(2, 1, 0));
  const PolygonSoup noff = read("n.off",
                                "NOFF\n3 1 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n"
                                "0 1 0 0 0 1\n3 0 1 2\n");
  EXPECT_EQ(noff.positions[1], (Vec3{1, 0, 0}));
}

TEST_F(MeshIoTest, PlyAsciiSkipsOtherElementsAndProperties) {
  const PolygonSoup soup = read("extra.ply",
                                "ply\nformat ascii 1.0\nobj_info made by hand\n"
                                "element material 1\nproperty uchar red\n"
                                "element vertex 3\nproperty int16 id\nproperty double x\n"
                                "property double y\nproperty list uchar float uv\n"
                                "property double z\n"
                                "element face 1\nproperty list uint8 uint32 vertex_indices\n"
                                "property int flags\nend_header\n"
                                "200\n"
                                "7 0 0 2 0.5 0.5 0\n8 1e0 0 0 1\n9 0 +1 1 0.25 0\n"
                                "3 0 1 2 5\n");
  EXPECT_THAT(soup.positions, ElementsAre(Vec3{0, 0, 0}, Vec3{1, 0, 1}, Vec3{0, 1, 0}));
  EXPECT_THAT(soup.indices, ElementsAre(0, 1, 2));
}

TEST_F(MeshIoTest, PlyElementsWithoutPropertiesTakeNoTime) {
  ByteWriter w;
  w.text(
      "ply\nformat binary_little_endian 1.0\nelement nothing 1000000000000000000\n"
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n");
  w.put<float>(0).put<float>(0).put<float>(0).put<float>(1).put<float>(0).put<float>(0);
  w.put<float>(0).put<float>(1).put<float>(0);
  w.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
  EXPECT_THAT(read("nothing.ply", w.bytes()).indices, ElementsAre(0, 1, 2));
}

TEST_F(MeshIoTest, StlAsciiWithSeveralSolidsAndUppercaseKeywords) {
  const PolygonSoup soup = read("two.stl",
                                "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                                "vertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid a\n"
                                "SOLID b\nFACET NORMAL 0 0 1\nOUTER LOOP\nVERTEX 0 0 1\n"
                                "VERTEX 1 0 1\nVERTEX 0 1 1\nENDLOOP\nENDFACET\nENDSOLID b\n");
  ASSERT_EQ(soup.face_count(), 2u);
  EXPECT_EQ(soup.positions.size(), 6u);
  EXPECT_EQ(soup.positions[5], (Vec3{0, 1, 1}));
}

TEST_F(MeshIoTest, ReadsTheExampleModels) {
  const std::filesystem::path models =
      std::filesystem::path(SHADOWKIT_SOURCE_DIR) / "examples" / "models";
  const PolygonSoup pebble = read_mesh_file(models / "pebble.obj", ctx_).soup;
  for (const char* name : {"pebble.ply", "pebble.off"}) {
    const PolygonSoup soup = read_mesh_file(models / name, ctx_).soup;
    EXPECT_EQ(soup.positions, pebble.positions) << name;
    EXPECT_EQ(soup.indices, pebble.indices) << name;
    EXPECT_EQ(soup.face_start, pebble.face_start) << name;
  }
  const PolygonSoup stl = read_mesh_file(models / "pebble.stl", ctx_).soup;
  std::size_t triangles = 0;
  for (std::size_t f = 0; f < pebble.face_count(); ++f) {
    triangles += pebble.face_start[f + 1] - pebble.face_start[f] - 2;
  }
  EXPECT_EQ(stl.face_count(), triangles);
  EXPECT_GT(read_mesh_file(models / "torus-knot.obj", ctx_).soup.face_count(), 1000u);
  EXPECT_GT(read_mesh_file(models / "open-sheet.obj", ctx_).soup.face_count(), 400u);
}

}  // namespace
}  // namespace shadowkit::mesh_io_test
