#pragma once
// The scene's faces with their polygons' sun hours, as a binary PLY that MeshLab, Blender and
// CloudCompare open in colour.
#include <ostream>
#include <vector>

#include "shadowkit/scene/scene.h"
#include "study_polygons.h"

namespace shadowkit::sun_study {

/// Writes every face of \p scene's meshes in world coordinates (the input's) as binary
/// little-endian PLY: per vertex double x, y, z; per face its vertex_indices, uchar red, green
/// and blue (sequential_colour() of its polygon's sun hours over the largest of any polygon
/// with area), float sun_hours and int polygon, the row of polygons.csv it belongs to.
/// \p hours holds the sun hours of each row of polygons.csv.
void write_sun_hours_ply(std::ostream& out, const Scene& scene, const Polygons& polygons,
                         const std::vector<double>& hours);

}  // namespace shadowkit::sun_study
