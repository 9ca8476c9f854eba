#pragma once
// The eye's own count (Crow 1977, Sec. VII: "the eye itself may be in shadow").
#include <cstdint>
#include <optional>
#include <span>

#include "shadowkit/scene/scene.h"

namespace shadowkit::volume {

/// How many of \p mesh's faces \p faces lie between the eye and the light (for a directional
/// light: along the ray from the eye toward it): the number of their per-face shadow volumes
/// holding the eye, where depth-pass counting starts. Empty when the segment passes too close
/// to an edge or the eye too close to a face plane to tell, relative to \p box, the faces'
/// bounds; the caller then counts depth-fail.
std::optional<int> faces_between_eye_and_light(const Mesh& mesh,
                                               std::span<const std::uint32_t> faces,
                                               const Bounds3& box, Vec3 eye, const Light& light);

}  // namespace shadowkit::volume
