#pragma once
// Crow's footprints (1977, Sec. VI): sub-objects wholly in the shadow of nearer ones.
#include <vector>

#include "shadowkit/scene/scene.h"
#include "shadowkit/scene/sub_objects.h"

namespace shadowkit {

/// Which sub-objects of \p parts lie wholly in the shadow of nearer ones (Crow
/// Sec. VI: "whenever an object's bounding box lies wholly within the footprint of an object
/// of higher priority, the former is in shadow"). Taken nearest the light first, the closed
/// convex sub-objects (SubObjects::convex) add their footprints, seen from the light, with
/// how far from it they reach; a sub-object whose box lies within them and beyond them is
/// marked. Every ray from the light to a marked sub-object meets a nearer one first, so its
/// volume lies within theirs: it adds no shadow, and dropping it changes no pixel.
///
/// The footprints are kept in grids seen from the light (one plane for a directional light,
/// the six faces of a cube for a point light), each cell holding the nearest far reach of
/// the footprints that cover it wholly; a box is tested against every cell it touches. A
/// face's grid spans only where the footprints fall on it, with about 16 cells per
/// footprint (128 to 2048 across): a box behind the seam of two overlapping footprints is
/// found hidden only where cells fit between their outlines. Both sides are rounded toward
/// keeping a sub-object.
std::vector<char> shadowed_sub_objects(const SubObjects& parts, const Light& light,
                                       const Bounds3& scene_bounds);

}  // namespace shadowkit
