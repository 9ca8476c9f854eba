// What real tools write is read, and what is skipped is said once per kind: byte order marks,
// Blender 2.47's PLY header, OBJ lines, points and forward references, PLY triangle strips,
// files without a last newline; and the formats assimp reads, with their node transforms.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <iterator>

#include "mesh_io_test_files.h"

namespace shadowkit::mesh_io_test {
namespace {

using ::testing::ElementsAre;

class RealFilesTest : public MeshFileTest {
 protected:
  MeshFile read(const std::string& name, std::string_view bytes) {
    return read_mesh_file(write(name, bytes), ctx_);
  }
};

constexpr std::string_view kBom = "\xEF\xBB\xBF";

TEST_F(RealFilesTest, AUtf8ByteOrderMarkIsSkippedInEveryTextFormat) {
  // Before, the mark hid an OBJ's first vertex and made an ASCII STL read as binary.
  const std::pair<const char*, std::string> files[] = {{"bom.obj", cube_obj()},
                                                       {"bom.ply", cube_ply_ascii()},
                                                       {"bom.off", cube_off()},
                                                       {"bom.stl", cube_stl_ascii()}};
  for (const auto& [name, text] : files) {
    const MeshFile with = read(name, std::string(kBom) + text);
    const MeshFile without = read(std::string("plain-") + name, text);
    EXPECT_EQ(with.soup.positions, without.soup.positions) << name;
    EXPECT_EQ(with.soup.indices, without.soup.indices) << name;
  }
  EXPECT_TRUE(warnings_.empty());
}

TEST_F(RealFilesTest, Utf16TextIsRefusedByName) {
  EXPECT_EQ(error("wide.obj", std::string("\xFF\xFEv\0 \0", 6)),
            at("wide.obj") + "is UTF-16 text; save it as UTF-8 or ASCII");
}

TEST_F(RealFilesTest, Blender247PlyHeaderLineIsAWarning) {
  // Blender 2.47 wrote this line without the 'comment' keyword; Blender, MeshLab and assimp
  // read the file.
  const std::string ply =
      "ply\nformat ascii 1.0\nCreated by Blender3D 247 - www.blender.org, source file: \n"
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar uint vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const MeshFile file = read("Wuson.ply", ply);
  EXPECT_EQ(file.soup.face_count(), 1u);
  EXPECT_THAT(
      warnings_,
      ElementsAre(at("Wuson.ply") + "skipped 1 header line(s) that PLY does not define at line 3"));
}

TEST_F(RealFilesTest, PlyTriangleStripsKeepTheirWinding) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
      "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 0 0\n6 0 1 2 3 -1 4\n";
  const MeshFile file = read("strips.ply", ply);
  // (0 1 2), then (2 1 3) for the second triangle's reversed winding; the run after -1 is
  // too short for a triangle.
  EXPECT_THAT(file.soup.indices, ElementsAre(0, 1, 2, 2, 1, 3));
}

TEST_F(RealFilesTest, ObjLinesAndPointsAreSkippedAndCountedAsImportersCountThem) {
  const MeshFile file = read("mixed.obj",
                             "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                             "l 1 2 3 4\nl 2 3\np 1 2 3\nf 1 2 3\nf\ncurv 0 1 1 2\nxyz 1\n");
  // The empty face line keeps its place in the file's numbering, as a face without corners.
  ASSERT_EQ(file.soup.face_count(), 2u);
  EXPECT_EQ(file.soup.face_start[2] - file.soup.face_start[1], 0u);
  EXPECT_EQ(file.stored_polygons, 1u);
  EXPECT_EQ(file.skipped_primitives, 3u + 1u + 3u) << "segments and points";
  EXPECT_THAT(warnings_,
              ElementsAre(at("mixed.obj") + "skipped 2 line statement(s) 'l' (lines bound no "
                                            "surface) (the first at line 5)",
                          at("mixed.obj") + "skipped 1 point statement(s) 'p' (points bound no "
                                            "surface) at line 7",
                          at("mixed.obj") + "skipped 1 free-form curve or surface statement(s) "
                                            "(not supported) at line 10",
                          at("mixed.obj") + "skipped 1 unknown statement(s) at line 11"));
}

TEST_F(RealFilesTest, ObjFacesMayNameLaterVerticesAndLeaveIndicesOut) {
  const MeshFile file =
      read("late.obj", "f 1/ 2// 3/1/\nv 0 0 0\nv 1 0 0\nv 0 1 0");  // no last newline
  EXPECT_THAT(file.soup.indices, ElementsAre(0, 1, 2));
  EXPECT_EQ(file.soup.positions.size(), 3u);
}

// A quad placed at x = 5 by its node's translation, as COLLADA writes it.
std::string quad_dae(const std::string& translate = "5 0 0") {
  return R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><up_axis>Y_UP</up_axis></asset>
  <library_geometries><geometry id="quad"><mesh>
    <source id="p"><float_array id="pa" count="12">0 0 0 1 0 0 1 1 0 0 1 0</float_array>
      <technique_common><accessor source="#pa" count="4" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
    <polylist count="1"><input semantic="VERTEX" source="#v" offset="0"/><vcount>4</vcount><p>0 1 2 3</p></polylist>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s">
    <node id="n"><translate>)" +
         translate + R"(</translate><instance_geometry url="#quad"/></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>)";
}

Bounds3 bounds(const PolygonSoup& soup) {
  Bounds3 box;
  for (const Vec3& p : soup.positions) box.add(p);
  return box;
}

// COLLADA through assimp: the node's matrix places the polygon, which stays whole.
TEST_F(RealFilesTest, AssimpFormatsKeepPolygonsWholeAndApplyNodeTransforms) {
  const MeshFile file = read("quad.dae", quad_dae());
  ASSERT_EQ(file.soup.face_count(), 1u);
  EXPECT_THAT(file.soup.face_start, ElementsAre(0, 4)) << "a quad, not two triangles";
  EXPECT_EQ(bounds(file.soup).lo, (Vec3{5, 0, 0}));
  EXPECT_EQ(bounds(file.soup).hi, (Vec3{6, 1, 0}));
}

// The import cache answers for a file as long as its path, size and time are unchanged.
TEST_F(RealFilesTest, AssimpImportsAreCachedPerVersionOfTheFile) {
  const std::filesystem::path cache = dir_ / "cache";
  setenv("SHADOWKIT_CACHE_DIR", cache.c_str(), 1);
  const std::filesystem::path dae = write("quad.dae", quad_dae("5 0 0"));
  EXPECT_EQ(bounds(read_mesh_file(dae, ctx_).soup).lo, (Vec3{5, 0, 0}));
  ASSERT_EQ(std::distance(std::filesystem::directory_iterator(cache), {}), 1);
  // Same size and time, other content: the cache still answers, so it was asked.
  const auto time = std::filesystem::last_write_time(dae);
  write("quad.dae", quad_dae("7 0 0"));
  std::filesystem::last_write_time(dae, time);
  EXPECT_EQ(bounds(read_mesh_file(dae, ctx_).soup).lo, (Vec3{5, 0, 0}));
  // A new time is a new version of the file.
  std::filesystem::last_write_time(dae, time + std::chrono::seconds(1));
  EXPECT_EQ(bounds(read_mesh_file(dae, ctx_).soup).lo, (Vec3{7, 0, 0}));
  // A damaged entry is imported afresh, not trusted.
  for (const auto& entry : std::filesystem::directory_iterator(cache)) {
    std::filesystem::resize_file(entry.path(), std::filesystem::file_size(entry.path()) / 2);
  }
  EXPECT_EQ(bounds(read_mesh_file(dae, ctx_).soup).lo, (Vec3{7, 0, 0}));
  setenv("SHADOWKIT_CACHE_DIR", "", 1);
}

}  // namespace
}  // namespace shadowkit::mesh_io_test
