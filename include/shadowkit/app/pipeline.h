#pragma once
/// \brief Runs methods over a scene's lights and times them: scene -> per-light build ->
/// camera pass -> masks.
#include <cstddef>
#include <exception>
#include <string>
#include <vector>

#include "shadowkit/core/context.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/raster/visible_surface.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// \brief One method on one light: median times over the repetitions, memory, counters and
/// the mask of the last repetition; or why the method could not do the light.
struct MethodRun {
  std::string method;
  std::size_t light = 0;
  double prepare_ms = 0;  ///< light-independent structures, once per scene
  double build_ms = 0;
  double shade_ms = 0;
  std::size_t memory_bytes = 0;
  MethodCounters counters;
  ShadowMask mask;
  std::string failure;  ///< what prepare, build or shade threw; empty when the light ran
  bool failed() const { return !failure.empty(); }
};

/// \brief What run_method does when the method's prepare, build or shade throws.
enum class OnFailure {
  stop,    ///< the exception goes on to the caller
  record,  ///< the light's run records it (every light's, when prepare threw); the rest run
};

/// What failed, in the words the command line uses for the same exception: an input error's
/// message, "out of memory", or "internal error: ...".
std::string failure_reason(const std::exception& e);

/// Each run's mask, in the runs' order: one per light for shade_image.
std::vector<const ShadowMask*> masks_of(const std::vector<MethodRun>& runs);

/// \brief How often to run each stage when timing.
struct Repetitions {
  int warmup = 0;
  int timed = 1;
};

/// Milliseconds since an arbitrary origin, from a steady clock.
double now_ms();
/// Median of \p samples (empty: 0).
double median(std::vector<double> samples);

/// The visible-surface buffer and the median time to compute it.
struct CameraPass {
  VisibleSurfaceBuffer surfaces;
  double scan_ms = 0;
};
CameraPass run_camera_pass(const Scene& scene, const Repetitions& reps, const Context& ctx);

/// Runs \p method, already prepared for \p scene, over every light of \p scene; the runs'
/// prepare_ms is 0.
std::vector<MethodRun> run_prepared(ShadowMethod& method, const Scene& scene,
                                    const VisibleSurfaceBuffer& surfaces, const Repetitions& reps,
                                    const Context& ctx, OnFailure on_failure);

/// Runs \p method_name (with its options) over every light of \p scene.
std::vector<MethodRun> run_method(const Scene& scene, const VisibleSurfaceBuffer& surfaces,
                                  const std::string& method_name, const MethodOptions& options,
                                  const Repetitions& reps, const Context& ctx,
                                  OnFailure on_failure);

}  // namespace shadowkit
