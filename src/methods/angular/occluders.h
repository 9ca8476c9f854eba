#pragma once
// Which faces go into the angular table for one light.
#include <vector>

#include "ridge_edges.h"
#include "shadowkit/scene/scene.h"
#include "shadowkit/scene/sub_objects.h"

namespace shadowkit::angular {

/// \brief Per object: its faces' far sheets for \p light (see FarSheets).
///
/// A segment from the light to a point crosses a closed, consistently oriented mesh an even
/// number of times unless the point and the light lie in different regions of it, and the
/// crossings alternate in direction, so the hidden faces alone catch every shadow. The eye
/// sees the point from the point's region, so that holds when the segment (ray, for a
/// directional light) from the eye to the light misses the mesh's bounding box. Otherwise,
/// and for every open, non-manifold or inconsistently oriented mesh, the mesh is a two-sided
/// thin solid.
std::vector<FarSheets> occluding_sheets(const Scene& scene, const Light& light);

/// Takes the faces of the sub-objects \p shadowed marks (shadowed_sub_objects: wholly in
/// the shadow of nearer ones) out of \p sheets (per object, as occluding_sheets gives them):
/// every ray from the light to them meets a nearer sub-object first, whose own loops cast
/// that shadow. Their side becomes 0, which occludes nothing.
void leave_out_shadowed(const Scene& scene, const SubObjects& parts,
                        const std::vector<char>& shadowed, std::vector<FarSheets>& sheets);

}  // namespace shadowkit::angular
