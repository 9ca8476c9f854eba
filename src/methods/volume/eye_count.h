#pragma once
// The eye's own count (Crow 1977, Sec. VII: "the eye itself may be in shadow").
#include <optional>

#include "shadowkit/scene/scene.h"

namespace shadowkit::volume {

/// How many of \p mesh's faces lie between the eye and the light (for a directional light:
/// along the ray from the eye toward it): the number of per-face shadow volumes holding the
/// eye, where depth-pass counting starts. Empty when the segment passes too close to an edge
/// or the eye too close to a face plane to tell; the caller then counts depth-fail.
std::optional<int> faces_between_eye_and_light(const Mesh& mesh, Vec3 eye, const Light& light);

}  // namespace shadowkit::volume
