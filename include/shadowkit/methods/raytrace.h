#pragma once
/// \brief Embree shadow rays, one per visible point: the exact reference every other method is
/// compared with.
#include <memory>

#include "shadowkit/core/vec.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::raytrace {

/// The method with \p options (its settings, docs/methods/raytrace.md); InputError for an unknown
/// key or a bad value.
std::unique_ptr<ShadowMethod> make_method(const MethodOptions& options);

class EmbreeScene;

/// \brief Exact shadow queries at any point, not only at pixels: the reference for results
/// in object space, such as svbsp's lit and shadowed areas.
class ShadowRays {
 public:
  explicit ShadowRays(const Scene& scene);
  ~ShadowRays();
  ShadowRays(const ShadowRays&) = delete;
  ShadowRays& operator=(const ShadowRays&) = delete;
  /// Whether the segment from \p p toward \p light (to its position, or to infinity against
  /// its direction) hits a face of the scene. \p p should be lifted off its own surface.
  bool occluded(Vec3 p, const Light& light) const;

 private:
  std::unique_ptr<EmbreeScene> embree_;
};

}  // namespace shadowkit::raytrace
