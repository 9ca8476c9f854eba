#pragma once
// Counting shadow polygons per pixel against the visible surfaces (Crow 1977, Sec. VII).
#include <cstddef>
#include <span>
#include <vector>

#include "shadow_polygon.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/raster/screen_polygon.h"
#include "shadowkit/scene/sub_objects.h"
#include "volume_culling.h"

namespace shadowkit::volume {

/// \brief What one counting pass touched.
struct StencilStats {
  std::size_t fill = 0;             ///< pixels covered by shadow polygons, summed over polygons
  std::size_t negative = 0;         ///< covered pixels whose count came out below zero (an error)
  std::size_t receiver_culled = 0;  ///< (sub-object, tile) pairs skipped by the receiver test
  std::size_t convex_volumes = 0;   ///< sub-objects whose volumes were counted whole
  std::size_t shadowed_cells = 0;   ///< cells settled in shadow (CountingTile::shadowed)
};

/// Walks \p polygons, set up on screen for the camera view as \p screen (face: the polygon's
/// index), and, per covered pixel, adds each polygon's jump where the pixel ray crosses it before
/// the visible point (depth-pass) or subtracts it where it crosses behind (depth-fail), starting
/// from \p eye_count. A pixel is lit when its count is not positive and its face is lit
/// (faces_light). A sub-object's polygons are skipped over tiles whose visible points lie
/// outside its shadow frustum (\p frusta, per sub-object of \p parts). Tiles in parallel;
/// writes \p mask. \p items lends its storage to the pass.
StencilStats count_shadow_polygons(const std::vector<ShadowPolygon>& polygons,
                                   std::span<const raster::ScreenPolygon> screen, int eye_count,
                                   const Scene& scene, const Light& light, const SubObjects& parts,
                                   const ShadowFrusta& frusta, const VisibleSurfaceBuffer& surfaces,
                                   ShadowMask& mask,
                                   std::vector<const raster::ScreenPolygon*>& items);

}  // namespace shadowkit::volume
