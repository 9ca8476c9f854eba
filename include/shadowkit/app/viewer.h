#pragma once
/// \brief The viewer (`shadowkit serve`) as a library: a frame request's JSON in, the frame's
/// PNG and timings out, with each method's once-per-scene work kept between frames. What the
/// server answers on /api/frame and its frame stream (docs/commands.md, "serve").
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shadowkit/app/sun_hours.h"
#include "shadowkit/core/context.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/raster/visible_surface.h"
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

/// \brief A rendered frame: the image as PNG and what it cost (docs/commands.md, "serve").
struct Frame {
  std::string png;
  nlohmann::json info;
};

/// \brief Renders frames of one scene, one at a time (callers on several threads wait their
/// turn: the methods use every core themselves).
class FrameRenderer {
 public:
  explicit FrameRenderer(Scene scene);

  /// The scene's own camera and lights, in world coordinates.
  const SceneView& scene_view() const { return scene_view_; }
  const Scene& scene() const { return scene_; }

  /// Renders \p request; nullopt when \p abandoned() is true once the renderer is free to
  /// begin it (nobody is left to show it; a frame begun is finished). InputError when the
  /// method refuses the scene or the view (its message says why).
  std::optional<Frame> render(
      const FrameRequest& request, const std::function<bool()>& abandoned = [] { return false; });

  /// The sun study's heat map (sun_hours_heat_map) from \p camera (world coordinates) over
  /// \p span, as PNG.
  std::string sun_hours(const sun::Site& site, const SunSpan& span, const Camera& camera);

 private:
  /// \brief A method prepared for the scene, kept for the next frames.
  struct PreparedMethod {
    std::string key;  ///< method and settings
    std::unique_ptr<ShadowMethod> method;
    std::uint64_t view = 0;  ///< view_count_ when prepared
    std::uint64_t used = 0;  ///< frame_count_ when last used
  };
  /// The most methods kept prepared: each holds its last build (a shadow map, a tree), and
  /// requests may ask for any number of settings.
  static constexpr std::size_t kKeptMethods = 4;

  ShadowMethod& prepared(const std::string& method, const MethodOptions& settings);

  std::mutex mutex_;
  Scene scene_;
  const SceneView scene_view_;
  SceneView view_;  ///< the view in scene_, in world coordinates
  Context ctx_;
  VisibleSurfaceBuffer surfaces_;          ///< the camera pass of ...
  std::optional<Camera> surfaces_camera_;  ///< ... this camera (world coordinates)
  std::vector<PreparedMethod> methods_;
  std::uint64_t view_count_ = 0;
  std::uint64_t frame_count_ = 0;
};

}  // namespace shadowkit::viewer
