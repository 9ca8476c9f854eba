#include "shadowkit/scene/generators.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numeric>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "shadowkit/core/error.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit {
namespace {

using nlohmann::json;

/// A context that records warnings, so tests can require that nothing was dropped or split.
struct RecordingContext {
  std::vector<std::string> warnings;
  Context ctx;
  RecordingContext() {
    ctx.warn = [this](const std::string& message) { warnings.push_back(message); };
  }
};

/// Objects that are open on purpose; everything else generated must be a closed solid.
bool is_open_object(const std::string& name) {
  return name == "ground" || name == "square" || name == "quad" || name == "terrain";
}

/// Faces grouped into components connected through two-face edges (the tetra's small
/// tetrahedra touch only at vertices, so each is its own component).
std::vector<std::vector<std::uint32_t>> edge_components(const Mesh& mesh) {
  std::vector<std::uint32_t> parent(mesh.face_count());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](std::uint32_t f) {
    while (parent[f] != f) f = parent[f] = parent[parent[f]];
    return f;
  };
  for (const MeshEdge& edge : mesh.edges) {
    if (edge.use_count != 2) continue;
    parent[root(mesh.edge_uses[edge.first_use].face)] =
        root(mesh.edge_uses[edge.first_use + 1].face);
  }
  std::vector<std::vector<std::uint32_t>> groups(mesh.face_count());
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f) groups[root(f)].push_back(f);
  std::erase_if(groups, [](const auto& g) { return g.empty(); });
  return groups;
}

/// Mean of the distinct vertices of \p faces.
// The volume enclosed by \p faces (divergence theorem over fan triangles): positive when a
// closed, consistently oriented part faces outward, whether convex or not.
double signed_volume(const Mesh& mesh, const std::vector<std::uint32_t>& faces) {
  double volume = 0;
  for (std::uint32_t f : faces) {
    const Vec3 a = mesh.vertices[mesh.face_vertex(f, 0)];
    for (std::uint32_t k = 1; k + 1 < mesh.face_size(f); ++k) {
      const Vec3 b = mesh.vertices[mesh.face_vertex(f, k)];
      const Vec3 c = mesh.vertices[mesh.face_vertex(f, k + 1)];
      volume += dot(a, cross(b, c)) / 6;
    }
  }
  return volume;
}

/// Every generated solid is a union of convex parts; true when \p p is strictly inside one.
bool inside_some_convex_part(const Mesh& mesh, Vec3 p) {
  for (const auto& component : edge_components(mesh)) {
    bool inside = true;
    for (std::uint32_t f : component) inside = inside && mesh.planes[f].distance(p) < 0;
    if (inside) return true;
  }
  return false;
}

/// Projects \p p with the contract's pinhole camera to [-1, 1]² when it is in the frame.
bool in_frame(const Camera& camera, Vec3 p) {
  const Vec3 d = p - camera.position;
  const double depth = dot(d, camera.forward());
  if (depth <= 0) return false;
  const double t = camera.tan_half_fov();
  const double x = dot(d, camera.right()) / depth / (t * camera.width / camera.height);
  const double y = dot(d, camera.true_up()) / depth / t;
  return std::abs(x) <= 1 && std::abs(y) <= 1;
}

std::vector<std::string> all_scene_specs() {
  std::vector<std::string> specs = builtin_scene_names();
  specs.insert(specs.end(),
               {"cubes:1", "cubes:8", "tetra:0", "tetra:4", "room:14", "square:2", "terrain:1"});
  return specs;
}

std::size_t soup_face_total(const std::vector<GeneratedObject>& objects) {
  std::size_t total = 0;
  for (const GeneratedObject& o : objects) total += o.soup.face_count();
  return total;
}

TEST(BuiltinScenes, CubeField2000HasThePapersPolygonCounts) {
  RecordingContext rc;
  const Scene scene = make_builtin_scene("cubes:2000", rc.ctx);
  EXPECT_EQ(scene.face_count(), 12001u);  // 2000 cubes × 6 quads + one ground quad
  EXPECT_EQ(scene.triangles().triangles.size(), 24002u);
  EXPECT_EQ(scene.camera.width, 1920);
  EXPECT_EQ(scene.camera.height, 1080);
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].type, Light::Type::point);
  EXPECT_TRUE(rc.warnings.empty());
  EXPECT_EQ(make_builtin_scene("cubes", rc.ctx).face_count(), 125u * 6 + 1);
}

TEST(BuiltinScenes, TerrainIsOneOpenHeightFieldOfTwoTrianglesACell) {
  RecordingContext rc;
  const Scene scene = make_builtin_scene("terrain:40", rc.ctx);
  EXPECT_TRUE(rc.warnings.empty());
  ASSERT_EQ(scene.objects.size(), 1u);
  const Mesh& mesh = scene.objects[0].mesh;
  EXPECT_EQ(mesh.face_count(), 2u * 40 * 40);
  EXPECT_EQ(scene.triangles().triangles.size(), 2u * 40 * 40);
  EXPECT_EQ(mesh.vertices.size(), 41u * 41);
  EXPECT_EQ(mesh.boundary_edge_count(), 4u * 40);
  EXPECT_EQ(edge_components(mesh).size(), 1u);  // one sub-object, as a scanned surface is
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].type, Light::Type::directional);
  EXPECT_LT(-scene.lights[0].direction.y, 0.35);  // a low sun: long shadows
  // In the generator's own units (the scene's working frame moves and scales them).
  const auto positions = [](int cells) {
    return generate_objects({{"generator", "terrain"}, {"cells", cells}}, "terrain")[0]
        .soup.positions;
  };
  const std::vector<Vec3> coarse = positions(40);
  Bounds3 box;
  for (const Vec3& v : coarse) box.add(v);
  EXPECT_EQ(box.lo.x, -10);
  EXPECT_EQ(box.hi.z, 10);
  EXPECT_GT(box.hi.y - box.lo.y, 2);  // hills, not a plane
  EXPECT_LT(box.hi.y, 3);
  // The same landscape at every resolution: the coarse grid's vertices are the fine one's.
  std::set<std::tuple<double, double, double>> fine;
  for (const Vec3& v : positions(80)) fine.insert({v.x, v.y, v.z});
  for (const Vec3& v : coarse) EXPECT_TRUE(fine.contains({v.x, v.y, v.z}));
  EXPECT_EQ(make_builtin_scene("terrain", rc.ctx).face_count(), 2u * 160 * 160);
}

TEST(BuiltinScenes, TetraLevelsMatchChinFeinerTable1) {
  RecordingContext rc;
  const Scene tetra256 = make_builtin_scene("tetra", rc.ctx);
  EXPECT_EQ(tetra256.face_count(), 258u);  // Tetra256: 256 triangles + 2 ground triangles
  EXPECT_EQ(tetra256.triangles().triangles.size(), 258u);
  EXPECT_EQ(make_builtin_scene("tetra:3", rc.ctx).face_count(), 258u);
  EXPECT_EQ(make_builtin_scene("tetra:4", rc.ctx).face_count(), 1026u);  // Tetra1024
  EXPECT_EQ(make_builtin_scene("tetra:0", rc.ctx).face_count(), 6u);
  EXPECT_TRUE(rc.warnings.empty());
  // 4^L tetrahedra meeting only at corners.
  EXPECT_EQ(edge_components(tetra256.objects[0].mesh).size(), 64u);
}

TEST(BuiltinScenes, NothingIsDroppedOrSplitWhenMeshed) {
  for (const std::string& spec : builtin_scene_names()) {
    RecordingContext rc;
    const Scene scene = make_builtin_scene(spec, rc.ctx);
    EXPECT_EQ(scene.face_count(), soup_face_total(generate_objects({{"generator", spec}}, spec)))
        << spec;
    EXPECT_TRUE(rc.warnings.empty()) << spec << ": " << rc.warnings.front();
    EXPECT_EQ(scene.name, spec);
  }
}

TEST(BuiltinScenes, SolidsAreClosedManifoldAndOutward) {
  for (const std::string& spec : all_scene_specs()) {
    RecordingContext rc;
    const Scene scene = make_builtin_scene(spec, rc.ctx);
    for (const SceneObject& object : scene.objects) {
      const Mesh& mesh = object.mesh;
      SCOPED_TRACE(spec + " / " + object.name);
      EXPECT_TRUE(mesh.manifold());
      EXPECT_TRUE(mesh.consistently_oriented());
      if (is_open_object(object.name)) {
        EXPECT_GT(mesh.boundary_edge_count(), 0u);
        for (const Plane& plane : mesh.planes) {
          if (object.name == "terrain") {
            EXPECT_GT(plane.normal.y, 0);  // a height field, faces turned up
          } else {
            EXPECT_NEAR(plane.normal.y, 1, 1e-12);
          }
        }
        continue;
      }
      EXPECT_TRUE(mesh.closed());
      // Each part faces out of the volume it encloses; the room's walls face into it.
      const double sign = object.name == "room" ? -1 : 1;
      for (const auto& component : edge_components(mesh)) {
        EXPECT_GT(sign * signed_volume(mesh, component), 0);
      }
    }
  }
}

TEST(BuiltinScenes, CameraAndLightsArePlacedSafely) {
  for (const std::string& spec : all_scene_specs()) {
    RecordingContext rc;
    const Scene scene = make_builtin_scene(spec, rc.ctx);
    SCOPED_TRACE(spec);
    const double tolerance = 1e-6 * scene.bounds().diagonal();
    ASSERT_FALSE(scene.lights.empty());
    for (const Light& light : scene.lights) {
      if (light.type == Light::Type::directional) {
        EXPECT_NEAR(length(light.direction), 1, 1e-12);
        EXPECT_LT(light.direction.y, 0);  // shining down onto the ground
        continue;
      }
      // A light in a face's plane would make that face neither lit nor shadowed.
      for (std::uint32_t f = 0; f < scene.face_count(); ++f) {
        ASSERT_GT(std::abs(scene.face_plane(f).distance(light.position)), tolerance) << f;
      }
      for (const SceneObject& object : scene.objects) {
        if (object.name == "room") continue;
        EXPECT_FALSE(inside_some_convex_part(object.mesh, light.position)) << object.name;
      }
    }
    for (const SceneObject& object : scene.objects) {
      if (object.name == "room") {
        // The room's inward walls: the camera and the light are on their inner side.
        for (const Plane& plane : object.mesh.planes) {
          EXPECT_GT(plane.distance(scene.camera.position), 0);
          EXPECT_GT(plane.distance(scene.lights[0].position), 0);
        }
        continue;
      }
      EXPECT_FALSE(inside_some_convex_part(object.mesh, scene.camera.position)) << object.name;
      if (object.name == "ground" || object.name == "terrain") continue;
      // Every object is in view (the ground, the terrain and the room's walls extend past
      // the frame).
      for (const Vec3& v : object.mesh.vertices) {
        EXPECT_TRUE(in_frame(scene.camera, v)) << object.name;
        if (!in_frame(scene.camera, v)) break;
      }
    }
  }
}

TEST(BuiltinScenes, SquareIsTheAnalyticCase) {
  RecordingContext rc;
  const Scene scene = make_builtin_scene("square", rc.ctx);
  ASSERT_EQ(scene.face_count(), 2u);
  ASSERT_EQ(scene.lights.size(), 1u);
  // In world coordinates, as the generator places them.
  const WorldFrame& frame = scene.frame;
  EXPECT_EQ(frame.to_world(scene.lights[0].position), (Vec3{0, 4, 0}));
  const SceneObject& square = scene.objects[0];
  ASSERT_EQ(square.name, "square");
  const Bounds3 b = square.mesh.bounds();
  EXPECT_EQ(frame.to_world(b.lo), (Vec3{-1, 1, -1}));
  EXPECT_EQ(frame.to_world(b.hi), (Vec3{1, 1, 1}));
  const auto objects =
      generate_objects({{"generator", "square"}, {"height", 2}, {"light_height", 5}}, "t");
  EXPECT_EQ(objects[0].soup.positions[0].y, 2);
  const Scene raised = make_builtin_scene("square:1.5", rc.ctx);
  EXPECT_EQ(raised.frame.to_world(raised.objects[0].mesh.vertices[0]).y, 1.5);
}

TEST(CubeField, CubesStayInsideTheFixedVolume) {
  for (const int count : {1, 125, 2000, 8000}) {
    SCOPED_TRACE(count);
    const auto objects = generate_objects({{"generator", "cubes"}, {"count", count}}, "t");
    ASSERT_EQ(objects.size(), 2u);
    const PolygonSoup& cubes = objects[0].soup;
    EXPECT_EQ(cubes.face_count(), 6u * count);
    EXPECT_EQ(objects[1].soup.face_count(), 1u);
    Bounds3 bounds;
    for (const Vec3& p : cubes.positions) bounds.add(p);
    EXPECT_GE(bounds.lo.x, -5);
    EXPECT_GE(bounds.lo.y, 0.5);
    EXPECT_GE(bounds.lo.z, -5);
    EXPECT_LE(bounds.hi.x, 5);
    EXPECT_LE(bounds.hi.y, 10.5);
    EXPECT_LE(bounds.hi.z, 5);
    // The cubes never touch: welding keeps them apart.
    RecordingContext rc;
    EXPECT_EQ(edge_components(Mesh::build(cubes, "cubes", rc.ctx)).size(), std::size_t(count));
  }
}

TEST(CubeField, CubesShrinkAsTheirNumberGrows) {
  const auto edge = [](int count) {
    const auto o = generate_objects({{"generator", "cubes"}, {"count", count}}, "t");
    const auto& p = o[0].soup.positions;
    return length(p[1] - p[0]);  // corners 0 and 1 of the first cube share an edge
  };
  EXPECT_NEAR(edge(1), 5, 1e-12);            // one 10-unit slot, edge = slot / 2
  EXPECT_NEAR(edge(125), 1, 1e-12);          // 5³ slots of 2 units
  EXPECT_NEAR(edge(2000), 5.0 / 13, 1e-12);  // 13³ = 2197 slots
}

TEST(CubeField, CubesComeBackToFront) {
  const auto objects = generate_objects({{"generator", "cubes"}, {"count", 1000}}, "t");
  const Scene scene = make_builtin_scene("cubes:1", Context{});
  const Vec3 eye = scene.frame.to_world(scene.camera.position);
  const auto& p = objects[0].soup.positions;
  double previous = INFINITY;
  for (std::size_t cube = 0; cube < 1000; ++cube) {
    Vec3 center;
    for (std::size_t k = 0; k < 8; ++k) center += p[cube * 8 + k] / 8;
    const double distance = length(center - eye);
    // Jitter moves a centre by at most 0.06 √3 slot (slot = 1 here).
    EXPECT_LE(distance, previous + 2 * 0.06 * std::sqrt(3.0)) << cube;
    previous = distance;
  }
}

TEST(CubeField, SameSeedSameScene) {
  const auto make = [](int seed) {
    return generate_objects({{"generator", "cubes"}, {"count", 64}, {"seed", seed}}, "t")[0]
        .soup.positions;
  };
  EXPECT_EQ(make(7), make(7));
  EXPECT_NE(make(7), make(8));
  EXPECT_EQ(make(1), generate_objects({{"generator", "cubes"}, {"count", 64}}, "t")[0]
                         .soup.positions);  // seed defaults to 1
}

TEST(Primitives, SolidsAreClosedAndFaceOutward) {
  const json solids[] = {
      {{"generator", "box"}, {"size", json::array({2, 1, 3})}},
      {{"generator", "box"}},
      {{"generator", "tetrahedron"}, {"size", 2}},
      {{"generator", "sphere"}, {"radius", 1.5}, {"segments", 12}, {"rings", 7}},
  };
  for (const json& params : solids) {
    SCOPED_TRACE(params.dump());
    const auto objects = generate_objects(params, "t");
    ASSERT_EQ(objects.size(), 1u);
    RecordingContext rc;
    const Mesh mesh = Mesh::build(objects[0].soup, objects[0].name, rc.ctx);
    EXPECT_TRUE(rc.warnings.empty());
    EXPECT_EQ(mesh.face_count(), objects[0].soup.face_count());
    EXPECT_TRUE(mesh.closed());
    EXPECT_TRUE(mesh.consistently_oriented());
    const Bounds3 b = mesh.bounds();
    EXPECT_NEAR(length(b.center()), 0, 1e-12);  // centred at the origin
    for (const Plane& plane : mesh.planes) EXPECT_LT(plane.distance(b.center()), 0);
  }
  const auto box = generate_objects({{"generator", "box"}, {"size", json::array({2, 1, 3})}}, "t");
  Bounds3 b;
  for (const Vec3& p : box[0].soup.positions) b.add(p);
  EXPECT_EQ(b.extent(), (Vec3{2, 1, 3}));
  EXPECT_EQ(box[0].soup.face_count(), 6u);
}

TEST(Primitives, QuadAndGroundAreOneUpwardQuad) {
  for (const json& params : {json{{"generator", "quad"}, {"size", json::array({3, 2})}},
                             json{{"generator", "ground"}, {"size", 20}}}) {
    const auto objects = generate_objects(params, "t");
    ASSERT_EQ(objects.size(), 1u);
    RecordingContext rc;
    const Mesh mesh = Mesh::build(objects[0].soup, objects[0].name, rc.ctx);
    ASSERT_EQ(mesh.face_count(), 1u);
    EXPECT_EQ(mesh.planes[0].normal, (Vec3{0, 1, 0}));
    EXPECT_EQ(mesh.boundary_edge_count(), 4u);
  }
  const auto ground = generate_objects({{"generator", "ground"}, {"size", 20}}, "t");
  Bounds3 b;
  for (const Vec3& p : ground[0].soup.positions) b.add(p);
  EXPECT_EQ(b.lo, (Vec3{-10, 0, -10}));
  EXPECT_EQ(b.hi, (Vec3{10, 0, 10}));
}

TEST(Primitives, FullScenesGiveTheirGeometryOnly) {
  const auto objects = generate_objects({{"generator", "table"}}, "t");
  ASSERT_EQ(objects.size(), 6u);  // table, four chairs, ground
  EXPECT_EQ(objects[0].name, "table");
  EXPECT_EQ(objects[0].soup.face_count(), 30u);  // top and four legs
  EXPECT_EQ(objects[1].soup.face_count(), 36u);  // seat, four legs, back
  EXPECT_EQ(generate_objects({{"generator", "tetra"}, {"level", 2}}, "t")[0].soup.face_count(),
            64u);
}

/// The InputError message of generate_objects(\p params), or "" when it does not throw.
std::string error_of(const json& params) {
  try {
    generate_objects(params, "scene.json: key 'objects[2]'");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(GeneratorErrors, BadParametersNameTheirKey) {
  const std::pair<json, std::string> cases[] = {
      {{{"generator", "cubes"}, {"count", -1}}, "count"},
      {{{"generator", "cubes"}, {"count", 0}}, "count"},
      {{{"generator", "cubes"}, {"count", 100001}}, "count"},
      {{{"generator", "cubes"}, {"count", 18446744073709551615ULL}}, "count"},
      {{{"generator", "cubes"}, {"count", "abc"}}, "count"},
      {{{"generator", "cubes"}, {"count", 2.5}}, "count"},
      {{{"generator", "cubes"}, {"count", true}}, "count"},
      {{{"generator", "cubes"}, {"seed", -3}}, "seed"},
      {{{"generator", "cubes"}, {"cuont", 8}}, "cuont"},
      {{{"generator", "tetra"}, {"level", 8}}, "level"},
      {{{"generator", "terrain"}, {"cells", 0}}, "cells"},
      {{{"generator", "terrain"}, {"cells", 1025}}, "cells"},
      {{{"generator", "terrain"}, {"cells", 2.5}}, "cells"},
      {{{"generator", "tetra"}, {"level", -1}}, "level"},
      {{{"generator", "room"}, {"size", -2}}, "size"},
      {{{"generator", "room"}, {"size", json::array({1, 2})}}, "size"},
      {{{"generator", "square"}, {"height", 5}}, "height"},
      {{{"generator", "square"}, {"light_height", "high"}}, "light_height"},
      {{{"generator", "table"}, {"count", 3}}, "count"},
      {{{"generator", "box"}, {"size", json::array({1, 0, 1})}}, "size"},
      {{{"generator", "box"}, {"size", "big"}}, "size"},
      {{{"generator", "quad"}, {"size", json::array({1, 2, 3})}}, "size"},
      {{{"generator", "sphere"}, {"segments", 2}}, "segments"},
      {{{"generator", "nope"}}, "generator"},
      {{{"generator", 3}}, "generator"},
      {{{"count", 3}}, "generator"},
  };
  for (const auto& [params, key] : cases) {
    const std::string message = error_of(params);
    EXPECT_NE(message.find("scene.json: key 'objects[2]." + key + "'"), std::string::npos)
        << params.dump() << " -> '" << message << "'";
  }
  EXPECT_NE(error_of(json::array()).find("objects[2]"), std::string::npos);
  // The loader's own keys pass through.
  EXPECT_EQ(error_of({{"generator", "box"}, {"transform", {{"scale", 2}}}, {"name", "b"}}), "");
}

TEST(GeneratorErrors, BadSpecStringsNameTheScene) {
  const std::pair<std::string, std::string> cases[] = {
      {"cubes:abc", "scene 'cubes:abc'"}, {"cubes:", "scene 'cubes:'"},
      {"cubes:12x", "scene 'cubes:12x'"}, {"cubes:200000", "scene 'cubes:200000': key 'count'"},
      {"cubes:-5", "key 'count'"},        {"tetra:8", "scene 'tetra:8': key 'level'"},
      {"tetra:2.5", "scene 'tetra:2.5'"}, {"table:3", "takes no parameter"},
      {"square:9", "key 'height'"},       {"nope", "unknown built-in scene 'nope'"},
      {"terrain:x", "scene 'terrain:x'"}, {"terrain:5000", "scene 'terrain:5000': key 'cells'"},
      {"", "unknown built-in scene"},
  };
  for (const auto& [spec, expected] : cases) {
    try {
      make_builtin_scene(spec, Context{});
      ADD_FAILURE() << spec << " did not throw";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos)
          << spec << " -> " << e.what();
    }
  }
}

TEST(GeneratorErrors, PlainWhereGetsAKeySuffix) {
  try {
    generate_objects({{"generator", "cubes"}, {"count", -1}}, "scene 'cubes:-1'");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("scene 'cubes:-1': key 'count': ", 0), 0u) << e.what();
  }
}

TEST(BuiltinScenes, NamesAreListed) {
  const std::vector<std::string> expected{"cubes",        "terrain", "tetra", "room",  "table",
                                          "three-lights", "square",  "coil",  "holed", "hole-like"};
  EXPECT_EQ(builtin_scene_names(), expected);
  RecordingContext rc;
  EXPECT_EQ(make_builtin_scene("three-lights", rc.ctx).lights.size(), 3u);
  EXPECT_EQ(make_builtin_scene("table", rc.ctx).lights.size(), 2u);
}

TEST(Examples, EverySceneFileLoadsWithSafeLights) {
  const std::filesystem::path dir = std::filesystem::path(SHADOWKIT_SOURCE_DIR) / "examples";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    ++files;
    RecordingContext rc;  // the example models may warn (split faces); that is fine here
    const Scene scene = load_scene_file(entry.path(), rc.ctx);
    EXPECT_GT(scene.face_count(), 0u);
    ASSERT_FALSE(scene.lights.empty());
    const double tolerance = 1e-6 * scene.bounds().diagonal();
    for (const Light& light : scene.lights) {
      if (light.type != Light::Type::point) continue;
      for (std::uint32_t f = 0; f < scene.face_count(); ++f) {
        // A tessellation for the view fans pixel-sized facets along each light's terminator,
        // edge-on to the light by construction; the contract's in-plane rule decides them.
        if (scene.objects[scene.object_of_face(f)].subdivision) continue;
        ASSERT_GT(std::abs(scene.face_plane(f).distance(light.position)), tolerance) << f;
      }
    }
  }
  EXPECT_GE(files, 6);
}

}  // namespace
}  // namespace shadowkit
