#pragma once
// Which faces go into the angular table for one light.
#include <vector>

#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// \brief Per global face: does it bound the shadow volume as a hidden face (Sec. 5)?
///
/// A segment from the light to a point crosses a closed, consistently oriented mesh an even
/// number of times unless the point and the light lie in different regions of it, and the
/// crossings alternate in direction, so the hidden faces (light behind the plane) alone
/// catch every shadow. The eye sees the point from the point's region, so that holds when
/// the segment (ray, for a directional light) from the eye to the light misses the mesh's
/// bounding box. Otherwise, and for every open, non-manifold or inconsistently oriented mesh
/// (a two-sided thin solid: each face's back sheet is hidden), every face whose plane misses
/// the light is kept.
std::vector<char> occluding_faces(const Scene& scene, const Light& light);

}  // namespace shadowkit
