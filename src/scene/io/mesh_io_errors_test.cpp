// Bad input gives an InputError naming the file, and the line when there is one; damaged
// files never crash the readers.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstring>
#include <limits>
#include <random>
#include <tuple>

#include "mesh_io_test_files.h"
#include "readers.h"

namespace shadowkit::mesh_io_test {
namespace {

using ::testing::AllOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;

using MeshIoErrorTest = MeshFileTest;

TEST_F(MeshIoErrorTest, MissingFile) {
  for (const char* name : {"absent.obj", "absent.gltf", "absent.dae", "absent"}) {
    EXPECT_EQ(error_of(dir_ / name), at(name) + "cannot open the file: No such file or directory");
  }
}

TEST_F(MeshIoErrorTest, Directory) {
  for (const char* name : {"folder.obj", "folder.ifc"}) {
    std::filesystem::create_directory(dir_ / name);
    EXPECT_EQ(error_of(dir_ / name), at(name) + "cannot read the file: it is a directory");
  }
}

// A device or a pipe may never end: reading one would fill the memory or wait for ever.
TEST_F(MeshIoErrorTest, DevicesAndPipes) {
  std::filesystem::create_symlink("/dev/zero", dir_ / "zero.obj");
  ASSERT_EQ(mkfifo((dir_ / "pipe.dae").c_str(), 0600), 0);
  for (const char* name : {"zero.obj", "pipe.dae"}) {
    EXPECT_EQ(error_of(dir_ / name), at(name) + "cannot read the file: it is not a regular file");
  }
}

// Formats without a reader of shadowkit's own go to assimp, which refuses what it cannot read.
TEST_F(MeshIoErrorTest, FilesAssimpCannotRead) {
  EXPECT_EQ(error("cube.3ds", cube_obj()),
            at("cube.3ds") + "assimp cannot read it: Chunk is too large");
  EXPECT_THAT(error("notes.txt", "shopping list\n"),
              AllOf(HasSubstr(at("notes.txt") + "assimp cannot read it: "),
                    HasSubstr("No suitable reader found")));
  // assimp's messages quote the file: they are cut short and their control bytes masked.
  auto ifc = [](const std::string& schema) {
    return "ISO-10303-21;\nHEADER;\nFILE_SCHEMA(('" + schema +
           "'));\nENDSEC;\nDATA;\nENDSEC;\nEND-ISO-10303-21;\n";
  };
  const std::string said = "IFC: Unrecognized file schema: ";
  EXPECT_EQ(error("escape.ifc", ifc("RED\x1b[31m")),
            at("escape.ifc") + "assimp cannot read it: " + said + "RED?[31m");
  EXPECT_EQ(error("long.ifc", ifc(std::string(100000, 'B'))),
            at("long.ifc") + "assimp cannot read it: " + said +
                std::string(160 - said.size(), 'B') + "...");
}

TEST_F(MeshIoErrorTest, EmptyFilesAndFilesWithoutFaces) {
  for (const char* name : {"e.obj", "e.ply", "e.off", "e.stl"}) {
    EXPECT_THAT(error(name, ""), AllOf(HasSubstr(at(name)), HasSubstr("holds no faces")));
  }
  EXPECT_THAT(error("points.obj", "v 0 0 0\nv 1 0 0\n"),
              AllOf(HasSubstr(at("points.obj")), HasSubstr("holds no faces")));
  EXPECT_THAT(error("points.off", "OFF\n1 0 0\n0 0 0\n"), HasSubstr("holds no faces"));
  EXPECT_THAT(error("comments.off", "# nothing\n\n"), HasSubstr("holds no faces"));
  EXPECT_THAT(error("points.ply",
                    "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                    "property float y\nproperty float z\nend_header\n0 0 0\n"),
              HasSubstr("holds no faces"));
  EXPECT_THAT(error("empty.stl", "solid empty\nendsolid empty\n"), HasSubstr("holds no faces"));
}

TEST_F(MeshIoErrorTest, ObjMalformedVertex) {
  EXPECT_THAT(error("bad.obj", "# header\nv 0 0 0\nv 1.0 abc 2\nf 1 2 1\n"),
              HasSubstr(at("bad.obj", 3) + "expected a y coordinate, found 'abc'"));
  EXPECT_THAT(error("short.obj", "v 0 0 0\r\nv 1 2\r\n"),
              HasSubstr(at("short.obj", 2) + "expected a z coordinate, found the end of the line"));
  EXPECT_THAT(error("glued.obj", "v 0 0 0\nv 1 2 3x\n"), HasSubstr(at("glued.obj", 2)));
}

TEST_F(MeshIoErrorTest, ObjFaceIndexOutOfRange) {
  std::string obj = cube_obj();  // 2 header lines, 8 vertices, 6 faces
  obj += "f 1 2 9\n";
  EXPECT_THAT(
      error("range.obj", obj),
      HasSubstr(at("range.obj", 17) + "face index 9 is out of range (the file has 8 vertices)"));
  EXPECT_THAT(error("neg.obj", "v 0 0 0\nv 1 0 0\nf 1 2 -3\n"),
              HasSubstr(at("neg.obj", 3) +
                        "face index -3 is out of range (the file has 2 vertices so far)"));
  // A face may name vertices given after it, but only those the file gives.
  EXPECT_THAT(
      error("early.obj", "v 0 0 0\nf 1 2 4\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
      HasSubstr(at("early.obj", 2) + "face index 4 is out of range (the file has 3 vertices)"));
}

TEST_F(MeshIoErrorTest, ObjZeroAndMalformedIndices) {
  EXPECT_THAT(error("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"),
              HasSubstr(at("zero.obj", 4) + "face index 0 is invalid (OBJ indices start at 1)"));
  for (const char* corner : {"x", "1/a", "1/2/3/4", "1//b", "1.5", "/2"}) {
    EXPECT_THAT(error("corner.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 " + std::string(corner)),
                HasSubstr(at("corner.obj", 5) + "face vertex '" + corner + "' is malformed"))
        << corner;
  }
}

TEST_F(MeshIoErrorTest, NonFiniteCoordinatesInTextFormats) {
  EXPECT_THAT(error("nan.obj", "v 0 0 0\nv 1 nan 0\nf 1 2 1\n"),
              HasSubstr(at("nan.obj", 2) + "vertex 2 has a non-finite coordinate (nan)"));
  EXPECT_THAT(error("inf.obj", "v 0 0 -inf\nf 1 1 1\n"),
              HasSubstr(at("inf.obj", 1) + "vertex 1 has a non-finite coordinate (-inf)"));
  EXPECT_THAT(error("huge.obj", "v 0 0 1e999\nf 1 1 1\n"),
              HasSubstr(at("huge.obj", 1) + "vertex 1 has a non-finite coordinate (1e999)"));
  EXPECT_THAT(error("inf.off", "OFF\n3 1 0\n0 0 0\ninf 0 0\n0 1 0\n3 0 1 2\n"),
              HasSubstr(at("inf.off", 4) + "vertex 1 has a non-finite coordinate (inf)"));
  std::string ply = cube_ply_ascii();
  ply.replace(ply.find("0.500000 0.500000 0.500000"), 8, "NaN");
  EXPECT_THAT(error("nan.ply", ply),
              HasSubstr(at("nan.ply", 17) + "vertex 6 has a non-finite coordinate (nan)"));
  std::string stl = cube_stl_ascii();
  stl.replace(stl.find("vertex ") + 7, 9, "infinity");
  EXPECT_THAT(error("inf.stl", stl),
              HasSubstr(at("inf.stl", 4) + "facet 0 has a non-finite coordinate (infinity)"));
}

// Beyond limits::kCoordinate a scene cannot hold a vertex: the reader names its line.
TEST_F(MeshIoErrorTest, CoordinatesBeyondTheRangeNameTheirLine) {
  EXPECT_THAT(error("far.obj", "v 0 0 0\nv 1 2e15 0\nv 0 1 0\nf 1 2 3\n"),
              HasSubstr(at("far.obj", 2) +
                        "vertex 2 has a coordinate beyond +-1e15 (2e15), which is not supported"));
  EXPECT_THAT(error("far.off", "OFF\n3 1 0\n0 0 0\n-1.5e300 0 0\n0 1 0\n3 0 1 2\n"),
              HasSubstr(at("far.off", 4) + "vertex 1 has a coordinate beyond +-1e15 (-1.5e300)"));
  EXPECT_NO_THROW(
      read_mesh_file(write("edge.obj", "v 0 0 0\nv 1e15 0 0\nv 0 -1e15 0\nf 1 2 3\n"), ctx_));
  std::string ply = cube_ply_binary(false);
  const double far = 3e20;
  std::memcpy(&ply[ply.find("end_header\n") + 11 + 3 * 31 + 8 + 2], &far, 8);  // vertex 3's y
  EXPECT_THAT(error("far.ply", ply),
              HasSubstr(at("far.ply") + "vertex 3 has a coordinate beyond +-1e15 (3e+20)"));
}

// After a face's indices OFF allows its colour, at most four numbers, and nothing else.
TEST_F(MeshIoErrorTest, OffFaceLinesEndWithAColourOrNothing) {
  const std::string head = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_THAT(error("junk.off", head + "3 0 1 2 junk\n"),
              HasSubstr(at("junk.off", 6) + "face 0: expected at most a colour (up to 4 numbers) "
                                            "after its vertex indices, found 'junk'"));
  EXPECT_THAT(error("five.off", head + "3 0 1 2 0.1 0.2 0.3 1 7\n"), HasSubstr("found '7'"));
  for (const char* colour : {"", " 4", " 255 0 0", " 0.5 0.5 0.5 1"}) {
    EXPECT_EQ(read_mesh_file(write("colour.off", head + "3 0 1 2" + colour + "\n"), ctx_)
                  .soup.face_count(),
              1u)
        << colour;
  }
}

TEST_F(MeshIoErrorTest, NonFiniteCoordinatesInBinaryFormats) {
  std::string ply = cube_ply_binary(false);
  const std::size_t body = ply.find("end_header\n") + 11;
  const double inf = std::numeric_limits<double>::infinity();
  std::memcpy(&ply[body + 3 * 31 + 8 + 2], &inf, 8);  // vertex 3's y; 31 bytes per vertex
  EXPECT_THAT(error("inf.ply", ply),
              HasSubstr(at("inf.ply") + "vertex 3 has a non-finite coordinate (inf)"));

  std::string stl = cube_stl_binary();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&stl[84 + 5 * 50 + 12 + 4], &nan, 4);  // triangle 5's first y
  EXPECT_THAT(error("nan.stl", stl),
              HasSubstr(at("nan.stl") + "triangle 5 has a non-finite coordinate (nan)"));
}

TEST_F(MeshIoErrorTest, TruncatedBinaryPly) {
  const std::string ply = cube_ply_binary(true);
  EXPECT_THAT(error("cut.ply", ply.substr(0, ply.size() - 20)),
              HasSubstr(at("cut.ply") + "the binary data ends inside face 5, but the header "
                                        "declares 6"));
  const std::size_t body = ply.find("end_header\n") + 11;
  EXPECT_THAT(error("cut-vertex.ply", ply.substr(0, body + 100)),
              HasSubstr("the binary data ends inside vertex 3"));
}

TEST_F(MeshIoErrorTest, TruncatedBinaryStl) {
  const std::string stl = cube_stl_binary();
  EXPECT_THAT(error("cut.stl", stl.substr(0, stl.size() - 30)),
              HasSubstr(at("cut.stl") + "binary STL declares 12 triangles but the file holds "
                                        "only 11"));
  EXPECT_THAT(error("tiny.stl", std::string("\x01\x02\x03", 3)),
              HasSubstr("shorter than the 84-byte header"));
}

TEST_F(MeshIoErrorTest, PlyHeaderProblems) {
  const std::string vertex =
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string ascii = "ply\nformat ascii 1.0\n";
  EXPECT_THAT(
      error("no-indices.ply", ascii + vertex +
                                  "element face 1\nproperty list uchar int corners\n"
                                  "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
      HasSubstr(at("no-indices.ply") + "the face element has no 'vertex_indices' list property"));
  EXPECT_THAT(error("no-z.ply", ascii + "element vertex 1\nproperty float x\nproperty float y\n"
                                        "end_header\n"),
              HasSubstr(at("no-z.ply") + "the vertex element has no 'z' property"));
  EXPECT_THAT(error("type.ply", ascii + "element vertex 1\nproperty real x\n"),
              HasSubstr(at("type.ply", 4) + "unknown property type 'real'"));
  EXPECT_THAT(error("format.ply", "ply\nformat binary_middle_endian 1.0\n"),
              HasSubstr(at("format.ply", 2) + "unknown PLY format 'binary_middle_endian'"));
  EXPECT_THAT(error("count.ply", ascii + "element vertex -3\n"),
              HasSubstr(at("count.ply", 3) + "expected 'element <name> <count>'"));
  // A count past 2^64 - 1 must not read as 0, which would drop the element unread.
  EXPECT_EQ(error("overflow.ply", ascii + vertex + "element face 18446744073709551616\n"),
            at("overflow.ply", 7) +
                "element count '18446744073709551616' is beyond 18446744073709551615");
  EXPECT_THAT(error("end.ply", ascii + vertex), HasSubstr("the header has no 'end_header' line"));
  EXPECT_THAT(error("magic.ply", "solid x\n"), HasSubstr("not a PLY file"));
  EXPECT_THAT(error("float-index.ply", ascii + vertex +
                                           "element face 1\nproperty list uchar float "
                                           "vertex_indices\nend_header\n"),
              HasSubstr("must use integer types"));
}

TEST_F(MeshIoErrorTest, PlyAsciiBodyProblems) {
  std::string ply = cube_ply_ascii();  // 10 header lines, vertices on 11-18, faces on 19-24
  ply.replace(ply.rfind("4 1 2 6 5"), 9, "4 1 2 6 99");
  EXPECT_THAT(error("range.ply", ply),
              HasSubstr(at("range.ply", 24) + "face 5 has vertex index 99 out of range (the "
                                              "file has 8 vertices)"));
  std::string few = cube_ply_ascii();
  few.replace(few.find("4 0 3 2 1"), 9, "4 0 3 2");
  EXPECT_THAT(error("few.ply", few),
              HasSubstr(at("few.ply", 19) +
                        "expected a value for 'vertex_indices', found the end of the line"));
  std::string extra = cube_ply_ascii();
  extra.replace(extra.find("4 0 3 2 1"), 9, "3 0 3 2 1");
  EXPECT_THAT(error("extra.ply", extra),
              AllOf(HasSubstr(at("extra.ply", 19)), HasSubstr("more values")));
  const std::string cube = cube_ply_ascii();
  EXPECT_THAT(error("cut.ply", cube.substr(0, cube.find("4 0 4 7 3"))),
              HasSubstr(at("cut.ply") + "the file ends at face 4, but the header declares 6"));
}

TEST_F(MeshIoErrorTest, BinaryPlyIndexOutOfRange) {
  std::string ply = cube_ply_binary(false);
  // Face 2's second index: after 8 vertices of 31 bytes and two faces of 24 bytes.
  const std::size_t at_index = ply.find("end_header\n") + 11 + 8 * 31 + 2 * 24 + 2 + 4;
  const std::uint32_t bad = 99;
  std::memcpy(&ply[at_index], &bad, 4);
  EXPECT_THAT(error("range.ply", ply),
              HasSubstr(at("range.ply") + "face 2 has vertex index 99 out of range (the file "
                                          "has 8 vertices)"));
}

TEST_F(MeshIoErrorTest, OffProblems) {
  EXPECT_THAT(
      error("counts.off", "OFF\n# counts next\n8 six 12\n"),
      HasSubstr(at("counts.off", 3) + "expected the vertex, face and edge counts, found 'six'"));
  EXPECT_THAT(error("negative.off", "OFF -1 2 0\n"),
              AllOf(HasSubstr(at("negative.off", 1)), HasSubstr("found '-1'")));
  EXPECT_THAT(error("one.off", "OFF\n\n8\n"),
              AllOf(HasSubstr(at("one.off", 3)), HasSubstr("found 1 value")));
  EXPECT_THAT(error("missing.off", "OFF\n"),
              HasSubstr("expected the vertex, face and edge counts, found the end of the file"));
  const std::string off = cube_off();
  EXPECT_THAT(error("cut.off", off.substr(0, off.find("-0.500000 0.500000 0.500000"))),
              HasSubstr(at("cut.off") + "the file ends at vertex 7, but its header declares 8"));
  EXPECT_THAT(error("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
              HasSubstr(at("range.off", 6) +
                        "face 0 has vertex index 3 out of range (the file has 3 vertices)"));
  EXPECT_THAT(error("keyword.off", "PLY\n3 1 0\n"),
              HasSubstr(at("keyword.off", 1) + "not an OFF file"));
  EXPECT_THAT(error("4d.off", "4OFF\n3 1 0\n"), HasSubstr("only 3-dimensional"));
  EXPECT_THAT(error("binary.off", "OFF BINARY\n"), HasSubstr("binary OFF files are not supported"));
}

TEST_F(MeshIoErrorTest, StlAsciiProblems) {
  std::string stl = cube_stl_ascii();
  stl.replace(stl.find("endloop"), 7, "endlop");
  EXPECT_THAT(error("typo.stl", stl),
              HasSubstr(at("typo.stl", 7) + "expected 'vertex' or 'endloop', found 'endlop'"));
  const std::string cube = cube_stl_ascii();
  EXPECT_THAT(error("cut.stl", cube.substr(0, cube.rfind("endsolid"))),
              HasSubstr("expected 'facet' or 'endsolid', found the end of the file"));
  EXPECT_THAT(error("two.stl",
                    "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                    "vertex 1 0 0\nendloop\nendfacet\nendsolid t\n"),
              HasSubstr(at("two.stl", 6) + "facet 0 has 2 vertices; a facet needs 3"));
}

// Every prefix of a valid file, and the file with bytes overwritten, is read or rejected with
// an InputError; nothing else may happen. In memory, through the per-format readers, for speed.
TEST_F(MeshIoErrorTest, DamagedFilesNeverCrash) {
  using Reader = MeshFile (*)(std::string_view, const std::string&, const Context&);
  const std::tuple<const char*, Reader, std::string> files[] = {
      {"cube.obj", &mesh_io::read_obj, cube_obj()},
      {"cube.off", &mesh_io::read_off, cube_off()},
      {"cube.ply", &mesh_io::read_ply, cube_ply_ascii()},
      {"le.ply", &mesh_io::read_ply, cube_ply_binary(false)},
      {"be.ply", &mesh_io::read_ply, cube_ply_binary(true)},
      {"a.stl", &mesh_io::read_stl, cube_stl_ascii()},
      {"b.stl", &mesh_io::read_stl, cube_stl_binary()}};
  std::mt19937 random(7);
  for (const auto& [name, reader, bytes] : files) {
    std::vector<std::string> damaged;
    for (std::size_t n = 0; n < bytes.size(); ++n) damaged.push_back(bytes.substr(0, n));
    for (int k = 0; k < 1000; ++k) {
      std::string copy = bytes;
      for (int hits = 0; hits < 3; ++hits) {
        copy[random() % copy.size()] = static_cast<char>(random() % 256);
      }
      damaged.push_back(copy);
    }
    for (const std::string& d : damaged) {
      try {
        const PolygonSoup soup = reader(d, name, ctx_).soup;
        for (std::uint32_t index : soup.indices) ASSERT_LT(index, soup.positions.size()) << name;
      } catch (const InputError& e) {
        EXPECT_THAT(e.what(), HasSubstr(name));
      }
    }
  }
}

TEST_F(MeshIoErrorTest, MessagesAreOneLine) {
  EXPECT_THAT(error("bad.obj", "v 1 2 \x01\x02\n"), Not(HasSubstr("\n")));
  EXPECT_THAT(
      error("bad.off", "OFF\n1 1 0\n0 0 0\n3 0 0 zzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzzz\n"),
      HasSubstr("zzz...'"));
}

}  // namespace
}  // namespace shadowkit::mesh_io_test
