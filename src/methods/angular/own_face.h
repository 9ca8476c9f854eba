#pragma once
// How far a visible point lies outside the face the scan converter saw at its pixel.
#include <cstdint>

#include "light_frame.h"
#include "shadowkit/scene/mesh.h"

namespace shadowkit::angular {

/// \brief The face a run's visible points lie on, as the scan converter chose it.
///
/// A visible point is the pixel ray's point on its face's plane, but the face is the one whose
/// snapped edges cover the pixel centre: a centre within the snapping of an edge can lie just
/// outside its face, beyond the edge, where the neighbour across it is the surface truly seen.
/// Only the rare lookup that needs it asks how far (AngularLookup's `shadows`).
struct OwnFace {
  const Mesh* mesh = nullptr;
  std::uint32_t face = 0;  ///< the mesh's own face index
  const LightFrame* frame = nullptr;
  Vec3 eye;  ///< the camera, light frame

  /// How far \p local (light frame, on the face's plane) lies outside the face's polygon: 0
  /// inside it, else its distance from the polygon's outline.
  double outside(Vec3 local) const;
};

}  // namespace shadowkit::angular
