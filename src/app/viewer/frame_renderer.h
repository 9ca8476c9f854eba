#pragma once
// The viewer's one loop: a frame request in, an image and its timings out, with each
// method's once-per-scene work kept between frames.
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "frame_request.h"
#include "shadowkit/app/sun_hours.h"
#include "shadowkit/core/context.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::viewer {

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

  /// Renders \p request; nullopt when \p superseded() turned true before the frame was
  /// done (checked between stages: a newer request makes this frame worthless). InputError
  /// when the method refuses the scene or the view (its message says why).
  std::optional<Frame> render(
      const FrameRequest& request, const std::function<bool()>& superseded = [] { return false; });

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
  std::vector<PreparedMethod> methods_;
  std::uint64_t view_count_ = 0;
  std::uint64_t frame_count_ = 0;
};

}  // namespace shadowkit::viewer
