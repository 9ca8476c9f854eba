#pragma once
// What the viewer's page (or a script) asks for: one frame of one method, for a camera and
// lights of its own (docs/commands.md, "serve").
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::viewer {

/// The most pixels and lights a frame may have: a 4K frame, and a request small enough to
/// read at once. Larger requests are refused before any work.
inline constexpr std::int64_t kMaxFramePixels = 3840 * 2160;
inline constexpr std::size_t kMaxLights = 16;
/// The largest request body or stream message, in bytes.
inline constexpr std::size_t kMaxRequestBytes = 64 * 1024;

/// \brief What the frame's image shows.
enum class FrameView {
  shaded,      ///< the shaded image, every light with its mask (`render --image`)
  mask,        ///< one light's mask as grey (`render --mask`)
  difference,  ///< one light's mask against raytrace's (the report's difference image)
};

/// \brief One frame to render.
struct FrameRequest {
  double id = 0;   ///< echoed in the answer, so that a client can match them
  SceneView view;  ///< world coordinates; what the request leaves out is the scene's
  std::string method = "raytrace";
  MethodOptions settings;
  FrameView image = FrameView::shaded;
  std::size_t light = 0;              ///< the light of the mask and difference views
  bool mismatch = false;              ///< also compare every light's mask with raytrace's
  std::vector<std::string> warnings;  ///< keys of the camera or lights that were ignored
};

/// \p text as a request's JSON object whose keys are all in \p known; InputError for more
/// than kMaxRequestBytes, invalid JSON, nesting deeper than any request, or an unknown key.
nlohmann::json parse_request_json(std::string_view text, const std::vector<std::string>& known);

/// The request's `camera` and `lights` (scene-format keys) over \p scene_view, at most
/// kMaxLights and kMaxFramePixels; keys ignored go to \p warnings.
SceneView parse_request_view(const nlohmann::json& json, const SceneView& scene_view,
                             std::vector<std::string>& warnings);

/// Reads a request (a JSON object, docs/commands.md) over \p scene's own view. Every problem
/// is an InputError whose message names the key: an unknown key, a method or setting, a
/// frame larger than kMaxFramePixels, a light index out of range.
FrameRequest parse_frame_request(std::string_view text, const SceneView& scene_view);

}  // namespace shadowkit::viewer
