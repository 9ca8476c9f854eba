#pragma once
// What the page learns of the scene before its first frame (GET /api/scene).
#include <nlohmann/json.hpp>
#include <string>

#include "shadowkit/app/viewer.h"

namespace shadowkit::viewer {

/// The scene's name, size, world bounds, camera and lights (scene-format keys), site, the
/// methods with their settings, the viewer's limits and the frame stream's URL \p stream.
nlohmann::json scene_info(const FrameRenderer& renderer, const std::string& stream);

}  // namespace shadowkit::viewer
