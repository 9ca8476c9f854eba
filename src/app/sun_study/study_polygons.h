#pragma once
// The contract's polygons: every input polygon (a face of a mesh as read, in file order),
// the scene faces it became, and its sunlit fraction for one sun direction.
#include <cstdint>
#include <string>
#include <vector>

#include "shadowkit/core/vec.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::sun_study {

/// \brief The input polygons of a scene and the scene faces each became.
struct Polygons {
  struct Row {
    std::uint32_t object = 0, face = 0;  ///< polygons.csv's `object` and `face`
    double area = 0;                     ///< world units
    Vec3 normal;  ///< the sum of its faces' normals times their areas: Newell's normal
  };
  std::vector<Row> rows;
  std::vector<std::uint32_t> row_of_face;  ///< per global scene face
};

Polygons input_polygons(const Scene& scene);

/// polygons.csv.
std::string polygons_csv(const Polygons& polygons);

/// Per polygon, its sunlit fraction (sun-study.md) from the lit area of every scene face
/// (\p lit_areas, world units) for the sun toward \p toward_sun.
void sunlit_fractions(const Polygons& polygons, const std::vector<double>& lit_areas,
                      Vec3 toward_sun, float* out);

}  // namespace shadowkit::sun_study
