#pragma once
/// \brief Triangulation of planar simple polygons (convex or not).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "shadowkit/core/vec.h"

namespace shadowkit {

/// Appends triangles covering the polygon \p loop (indices into \p positions) whose plane
/// normal is \p normal: a fan when the polygon is convex, ear clipping otherwise. Triangles
/// keep the polygon's orientation.
void triangulate_polygon(std::span<const Vec3> positions, std::span<const std::uint32_t> loop,
                         Vec3 normal, std::vector<std::array<std::uint32_t, 3>>& out);

/// Newell's normal of a polygon: its direction is the polygon's normal, its length twice its
/// area. Robust for non-convex and slightly non-planar polygons.
Vec3 newell_normal(std::span<const Vec3> positions, std::span<const std::uint32_t> loop);

}  // namespace shadowkit
