#include "study_polygons.h"

#include <algorithm>

#include "contract_files.h"
#include "shadowkit/core/error.h"

namespace shadowkit::sun_study {
namespace {

// "The sun is behind or in the polygon's plane", with svbsp's tolerance for a directional
// light in a face's plane (SceneBsp::kRelativeTolerance): a face whose plane holds the sun
// within it has no lit area either.
constexpr double kInPlane = 1e-9;

}  // namespace

Polygons input_polygons(const Scene& scene) {
  Polygons polygons;
  polygons.row_of_face.resize(scene.face_count());
  const double scale2 = scene.frame.scale * scene.frame.scale;
  for (const SceneObject& object : scene.objects) {
    const Mesh& mesh = object.mesh;
    SHADOWKIT_CHECK(mesh.input_faces.size() == mesh.face_count());
    const auto first_row = std::uint32_t(polygons.rows.size());
    for (std::size_t k = 0; k < mesh.input_face_count(); ++k) {
      polygons.rows.push_back(
          {object.input_object, object.input_first_face + std::uint32_t(k), 0, {}});
    }
    // A planar face is its polygon; a warped polygon's triangles sum to its area and, as
    // vector areas, to its Newell normal. A dropped (degenerate) face keeps area 0.
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      const std::uint32_t row = first_row + mesh.input_faces[f];
      polygons.row_of_face[object.first_face + f] = row;
      polygons.rows[row].area += mesh.areas[f] * scale2;
      polygons.rows[row].normal += mesh.planes[f].normal * mesh.areas[f];
    }
  }
  return polygons;
}

std::string polygons_csv(const Polygons& polygons) {
  std::string text = kPolygonsHeader;
  for (std::size_t p = 0; p < polygons.rows.size(); ++p) {
    const Polygons::Row& row = polygons.rows[p];
    text += std::to_string(p) + "," + std::to_string(row.object) + "," + std::to_string(row.face) +
            "," + decimal(row.area) + "\n";
  }
  return text;
}

void sunlit_fractions(const Polygons& polygons, const std::vector<double>& lit_areas,
                      Vec3 toward_sun, float* out) {
  std::vector<double> sum(polygons.rows.size(), 0.0);
  for (std::size_t face = 0; face < lit_areas.size(); ++face)
    sum[polygons.row_of_face[face]] += lit_areas[face];
  for (std::size_t p = 0; p < polygons.rows.size(); ++p) {
    const Polygons::Row& row = polygons.rows[p];
    // The front side only: the sun behind or in the polygon's plane gives 0 (the contract),
    // although svbsp's two-sided surfaces light the back.
    const bool front = dot(row.normal, toward_sun) > kInPlane * length(row.normal);
    out[p] = front && row.area > 0 ? float(std::clamp(sum[p] / row.area, 0.0, 1.0)) : 0.0f;
  }
}

}  // namespace shadowkit::sun_study
