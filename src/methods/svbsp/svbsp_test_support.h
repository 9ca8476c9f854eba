#pragma once
// Shared by the svbsp tests: one light's fragments and their areas per face.
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "multi_light.h"
#include "shadow_generator.h"
#include "shadowkit/scene/generators.h"
#include "svbsp_method.h"

namespace shadowkit::svbsp {

/// Lit and shadowed area of one face.
struct FaceAreas {
  double lit = 0, shadowed = 0;
};

/// The fragments of light \p light of \p scene.
inline svbsp::LightFragments light_fragments(const Scene& scene, std::size_t light) {
  const svbsp::SceneBsp bsp = svbsp::SceneBsp::build(scene);
  return svbsp::generate_shadows(bsp, scene, scene.lights[light]);
}

/// \p soup with every face turned around.
inline PolygonSoup inside_out(const PolygonSoup& soup) {
  PolygonSoup out;
  out.positions = soup.positions;
  for (std::size_t f = 0; f < soup.face_count(); ++f) {
    std::vector<std::uint32_t> loop(soup.indices.begin() + soup.face_start[f],
                                    soup.indices.begin() + soup.face_start[f + 1]);
    out.add_face(std::vector<std::uint32_t>(loop.rbegin(), loop.rend()));
  }
  return out;
}

/// A unit UV sphere of \p segments x \p rings faces, closed and outward.
inline PolygonSoup sphere(int segments, int rings) {
  const nlohmann::json params = {
      {"generator", "sphere"}, {"radius", 1}, {"segments", segments}, {"rings", rings}};
  return generate_objects(params, "test").front().soup;
}

/// \brief One light's build of the svbsp method: its fragments and Table 1's counters.
struct MethodRun {
  std::vector<Fragment> fragments;
  double svbsp_nodes = 0, convex_units = 0, light_facing = 0;
};

/// Light \p light of \p scene built by the svbsp method with \p settings (svbsp.KEY=VALUE).
inline MethodRun run_method(const Scene& scene, std::size_t light,
                            const std::map<std::string, std::string>& settings = {}) {
  SvbspMethod method({"svbsp", settings});
  method.prepare(scene, {});
  method.build(scene, light, {});
  std::map<std::string, double> counters;
  for (const auto& [key, value] : method.counters()) counters[key] = value;
  return {method.fragments(), counters.at("svbsp_nodes"), counters.at("convex_units"),
          counters.at("light_facing")};
}

/// Lit and shadowed area per global face id.
inline std::map<std::uint32_t, FaceAreas> face_areas(
    const std::vector<svbsp::Fragment>& fragments) {
  std::map<std::uint32_t, FaceAreas> areas;
  for (const svbsp::Fragment& f : fragments) {
    (f.lit ? areas[f.polygon.face].lit : areas[f.polygon.face].shadowed) += area(f.polygon);
  }
  return areas;
}

/// Lit and shadowed area per global face id for light \p light of a multi-light result.
inline std::map<std::uint32_t, FaceAreas> face_areas(
    const std::vector<svbsp::MaskedFragment>& fragments, std::size_t light) {
  std::map<std::uint32_t, FaceAreas> areas;
  for (const svbsp::MaskedFragment& f : fragments) {
    FaceAreas& a = areas[f.polygon.face];
    ((f.lit_mask >> light) & 1 ? a.lit : a.shadowed) += area(f.polygon);
  }
  return areas;
}

/// Area of global face \p face of \p scene.
inline double face_area(const Scene& scene, std::uint32_t face) {
  return scene.objects[scene.object_of_face(face)].mesh.areas[scene.local_face(face)];
}

}  // namespace shadowkit::svbsp
