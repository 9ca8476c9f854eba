#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "shadowkit/app/commands.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit {
namespace {

nlohmann::json vec_json(Vec3 v) {
  return {v.x, v.y, v.z};
}

nlohmann::json scene_info(const Scene& scene) {
  nlohmann::json j;
  j["scene"] = scene.name;
  j["polygons"] = scene.face_count();
  j["triangles"] = scene.triangles().triangles.size();
  // Positions as the input gives them, not in the scene's working frame.
  const WorldFrame& frame = scene.frame;
  j["camera"] = {{"position", vec_json(frame.to_world(scene.camera.position))},
                 {"look_at", vec_json(frame.to_world(scene.camera.look_at))},
                 {"width", scene.camera.width},
                 {"height", scene.camera.height}};
  for (const Light& l : scene.lights) {
    j["lights"].push_back(
        l.type == Light::Type::point
            ? nlohmann::json{{"type", "point"}, {"position", vec_json(frame.to_world(l.position))}}
            : nlohmann::json{{"type", "directional"}, {"direction", vec_json(l.direction)}});
  }
  std::size_t closed = 0, boundary = 0, nonmanifold = 0;
  for (const SceneObject& o : scene.objects) {
    const Mesh& m = o.mesh;
    closed += m.closed();
    boundary += m.boundary_edge_count();
    nonmanifold += m.nonmanifold_edge_count();
    j["objects"].push_back({{"name", o.name},
                            {"polygons", m.face_count()},
                            {"vertices", m.vertices.size()},
                            {"edges", m.edges.size()},
                            {"closed", m.closed()},
                            {"manifold", m.manifold()},
                            {"consistently_oriented", m.consistently_oriented()},
                            {"boundary_edges", m.boundary_edge_count()},
                            {"nonmanifold_edges", m.nonmanifold_edge_count()},
                            {"nonplanar_polygons_split", m.split_face_count()},
                            {"degenerate_polygons_dropped", m.dropped_face_count()}});
    if (o.subdivision) {
      j["objects"].back()["subdivision"] = {{"scheme", "catmull-clark"},
                                            {"control_faces", o.subdivision->control_face_count()},
                                            {"patches", o.subdivision->patch_count()}};
    }
  }
  j["closed_meshes"] = closed;
  j["open_meshes"] = scene.objects.size() - closed;
  j["boundary_edges"] = boundary;
  j["nonmanifold_edges"] = nonmanifold;
  const Bounds3 bounds = scene.world_bounds();
  j["bounds"] = {vec_json(bounds.lo), vec_json(bounds.hi)};
  return j;
}

void print_info(const nlohmann::json& j) {
  std::printf("scene %s: %zu polygons (%zu triangles), %zu light(s), camera %dx%d\n",
              j["scene"].get<std::string>().c_str(), j["polygons"].get<std::size_t>(),
              j["triangles"].get<std::size_t>(), j.value("lights", nlohmann::json::array()).size(),
              j["camera"]["width"].get<int>(), j["camera"]["height"].get<int>());
  std::printf("meshes: %zu closed, %zu open; %zu boundary edges, %zu non-manifold edges\n",
              j["closed_meshes"].get<std::size_t>(), j["open_meshes"].get<std::size_t>(),
              j["boundary_edges"].get<std::size_t>(), j["nonmanifold_edges"].get<std::size_t>());
  std::printf("%-24s %9s %9s %9s %-8s %-9s %9s %12s\n", "object", "polygons", "vertices", "edges",
              "closed", "manifold", "boundary", "non-manifold");
  for (const auto& o : j.value("objects", nlohmann::json::array())) {
    std::printf("%-24s %9zu %9zu %9zu %-8s %-9s %9zu %12zu\n", o["name"].get<std::string>().c_str(),
                o["polygons"].get<std::size_t>(), o["vertices"].get<std::size_t>(),
                o["edges"].get<std::size_t>(), o["closed"].get<bool>() ? "yes" : "no",
                o["manifold"].get<bool>() ? "yes" : "no", o["boundary_edges"].get<std::size_t>(),
                o["nonmanifold_edges"].get<std::size_t>());
  }
  for (const auto& o : j.value("objects", nlohmann::json::array())) {
    if (!o.contains("subdivision")) continue;
    std::printf("%s: Catmull-Clark surface, %zu control faces, %zu patches\n",
                o["name"].get<std::string>().c_str(),
                o["subdivision"]["control_faces"].get<std::size_t>(),
                o["subdivision"]["patches"].get<std::size_t>());
  }
}

}  // namespace

int run_info(const CommandOptions& options, const Context& ctx) {
  const nlohmann::json j = scene_info(load_scene(options.scene, ctx));
  if (options.json) {
    std::cout << j.dump(2) << "\n";
  } else {
    print_info(j);
  }
  return 0;
}

}  // namespace shadowkit
