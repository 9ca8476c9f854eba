#pragma once
// Crow's sub-objects (1977, Sec. VI): the parts of an object that bound shadow volumes of
// their own, each with its bounding box.
#include <cstdint>
#include <vector>

#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// \brief The scene's faces grouped into sub-objects: the edge-connected parts of each
/// object's mesh. No edge joins two sub-objects, so the shadow polygons of a sub-object's
/// contour edges, with its faces, close its own per-face volumes: a point outside them gets
/// nothing from that sub-object, whatever the rest of the scene does.
struct SubObjects {
  std::vector<std::uint32_t> of_face;  ///< sub-object per global face id
  std::vector<Bounds3> bounds;         ///< per sub-object, of its faces' vertices

  static SubObjects of(const Scene& scene);
  std::size_t size() const { return bounds.size(); }
};

}  // namespace shadowkit
