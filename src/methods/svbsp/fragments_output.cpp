#include "fragments_output.h"

#include <fstream>

#include "scene_bsp.h"
#include "shadowkit/core/error.h"
#include "shadowkit/methods/svbsp.h"

namespace shadowkit::svbsp {
namespace {

// Output is in world units: the scene's working frame is scaled by frame.scale.
double world_area(const Scene& scene, double working_area) {
  return working_area * scene.frame.scale * scene.frame.scale;
}

double polygon_area(const Scene& scene, std::uint32_t face) {
  return world_area(scene,
                    scene.objects[scene.object_of_face(face)].mesh.areas[scene.local_face(face)]);
}

void write_header(std::ostream& out, const Scene& scene, const MultiLightFragments& result) {
  std::size_t corners = 0;
  for (const MaskedFragment& f : result.fragments) corners += f.polygon.vertices.size();
  out << "ply\nformat ascii 1.0\ncomment shadowkit svbsp fragments of " << scene.name << "\n"
      << "element vertex " << corners << "\n"
      << "property double x\nproperty double y\nproperty double z\n"
      << "element face " << result.fragments.size() << "\n"
      << "property list uchar uint vertex_indices\nproperty uint polygon\n";
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    out << "property uchar lit_L" << l << "\n";
  }
  out << "end_header\n";
}

}  // namespace

void write_fragments_ply(const std::filesystem::path& path, const Scene& scene,
                         const MultiLightFragments& result) {
  std::ofstream out(path);
  if (!out) throw InputError(path.string(), "cannot open for writing");
  out.precision(17);
  write_header(out, scene, result);
  for (const MaskedFragment& f : result.fragments) {
    for (const Vec3& working : f.polygon.vertices) {
      const Vec3 v = scene.frame.to_world(working);
      out << v.x << ' ' << v.y << ' ' << v.z << '\n';
    }
  }
  std::size_t next = 0;
  for (const MaskedFragment& f : result.fragments) {
    out << f.polygon.vertices.size();
    for (std::size_t k = 0; k < f.polygon.vertices.size(); ++k) out << ' ' << next++;
    out << ' ' << f.polygon.face;
    for (std::size_t l = 0; l < scene.lights.size(); ++l) out << ' ' << ((f.lit_mask >> l) & 1);
    out << '\n';
  }
  out.close();  // the buffer's last bytes go out here: a full disk may show only now
  if (!out) throw InputError(path.string(), "write failed");
}

nlohmann::json fragment_areas_json(const Scene& scene, const MultiLightFragments& result) {
  const std::size_t lights = scene.lights.size();
  std::vector<std::vector<double>> lit(scene.face_count(), std::vector<double>(lights));
  std::vector<std::vector<double>> shadowed = lit;
  std::vector<std::size_t> count(scene.face_count());
  for (const MaskedFragment& f : result.fragments) {
    const double a = world_area(scene, area(f.polygon));
    ++count[f.polygon.face];
    for (std::size_t l = 0; l < lights; ++l) {
      ((f.lit_mask >> l) & 1 ? lit : shadowed)[f.polygon.face][l] += a;
    }
  }
  nlohmann::json j;
  j["scene"] = scene.name;
  j["lights"] = lights;
  j["fragments"] = result.fragments.size();
  j["passes"] = nlohmann::json::array();
  for (const LightPass& p : result.passes) {
    j["passes"].push_back({{"light", p.light},
                           {"front_facing_polygons", p.front_facing.polygons},
                           {"front_facing_edges", p.front_facing.edges},
                           {"svbsp_nodes", p.svbsp_nodes},
                           {"fragments", p.fragments}});
  }
  j["polygons"] = nlohmann::json::array();
  for (std::uint32_t face = 0; face < scene.face_count(); ++face) {
    j["polygons"].push_back({{"polygon", face},
                             {"object", scene.objects[scene.object_of_face(face)].name},
                             {"area", polygon_area(scene, face)},
                             {"fragments", count[face]},
                             {"lit_area", lit[face]},
                             {"shadowed_area", shadowed[face]}});
  }
  return j;
}

FragmentsWritten write_fragments(const Scene& scene, const std::filesystem::path& ply,
                                 const std::filesystem::path& json) {
  const MultiLightFragments result = generate_multi_light_shadows(SceneBsp::build(scene), scene);
  write_fragments_ply(ply, scene, result);
  std::ofstream out(json);
  out << fragment_areas_json(scene, result).dump(2) << "\n";
  out.close();
  if (!out) throw InputError(json.string(), "cannot write");
  return {result.fragments.size()};
}

}  // namespace shadowkit::svbsp
