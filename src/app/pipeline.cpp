#include "shadowkit/app/pipeline.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <new>

#include "shadowkit/core/error.h"
#include "shadowkit/methods/registry.h"

namespace shadowkit {

double now_ms() {
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double, std::milli>(clock::now().time_since_epoch()).count();
}

std::vector<const ShadowMask*> masks_of(const std::vector<MethodRun>& runs) {
  std::vector<const ShadowMask*> masks;
  for (const MethodRun& run : runs) masks.push_back(&run.mask);
  return masks;
}

double median(std::vector<double> samples) {
  if (samples.empty()) return 0;
  const std::size_t mid = samples.size() / 2;
  std::nth_element(samples.begin(), samples.begin() + std::ptrdiff_t(mid), samples.end());
  if (samples.size() % 2) return samples[mid];
  const double upper = samples[mid];
  return 0.5 * (upper + *std::max_element(samples.begin(), samples.begin() + std::ptrdiff_t(mid)));
}

std::string failure_reason(const std::exception& e) {
  if (dynamic_cast<const InputError*>(&e)) return e.what();
  if (dynamic_cast<const std::bad_alloc*>(&e)) return "out of memory";
  return std::string("internal error: ") + e.what();
}

namespace {

// Runs fn warmup + timed times and returns the median of the timed runs.
template <class Fn>
double timed_median(const Repetitions& reps, Fn&& fn) {
  for (int i = 0; i < reps.warmup; ++i) fn();
  std::vector<double> samples;
  for (int i = 0; i < std::max(1, reps.timed); ++i) {
    const double start = now_ms();
    fn();
    samples.push_back(now_ms() - start);
  }
  return median(samples);
}

// Runs \p step; with OnFailure::record, what it throws comes back as the failure's reason.
template <class Step>
std::string attempt(OnFailure on_failure, Step&& step) {
  if (on_failure == OnFailure::stop) {
    step();
    return {};
  }
  try {
    step();
    return {};
  } catch (const std::exception& e) {
    return failure_reason(e);
  }
}

}  // namespace

CameraPass run_camera_pass(const Scene& scene, const Repetitions& reps, const Context& ctx) {
  CameraPass pass;
  pass.scan_ms = timed_median(reps, [&] { render_visible_surfaces(scene, ctx, pass.surfaces); });
  return pass;
}

std::vector<MethodRun> run_prepared(ShadowMethod& method, const Scene& scene,
                                    const VisibleSurfaceBuffer& surfaces, const Repetitions& reps,
                                    const Context& ctx, OnFailure on_failure) {
  std::vector<MethodRun> runs;
  for (std::size_t light = 0; light < scene.lights.size(); ++light) {
    MethodRun run;
    run.method = method.name();
    run.light = light;
    run.failure = attempt(on_failure, [&] {
      run.build_ms = timed_median(reps, [&] { method.build(scene, light, ctx); });
      run.mask = ShadowMask(surfaces.width, surfaces.height, kMaskBackground);
      run.shade_ms = timed_median(reps, [&] {
        std::fill(run.mask.pixels.begin(), run.mask.pixels.end(), kMaskBackground);
        method.shade(scene, surfaces, run.mask, ctx);
      });
      run.memory_bytes = method.memory_bytes();
      run.counters = method.counters();
    });
    // A failed light keeps no half-made mask.
    if (run.failed()) run.mask = ShadowMask();
    runs.push_back(std::move(run));
  }
  return runs;
}

std::vector<MethodRun> run_method(const Scene& scene, const VisibleSurfaceBuffer& surfaces,
                                  const std::string& method_name, const MethodOptions& options,
                                  const Repetitions& reps, const Context& ctx,
                                  OnFailure on_failure) {
  std::unique_ptr<ShadowMethod> method = make_method(method_name, options);
  const double start = now_ms();
  const std::string prepare_failure = attempt(on_failure, [&] { method->prepare(scene, ctx); });
  const double prepare_ms = now_ms() - start;
  std::vector<MethodRun> runs;
  if (prepare_failure.empty()) {
    runs = run_prepared(*method, scene, surfaces, reps, ctx, on_failure);
  } else {
    runs.resize(scene.lights.size());
    for (std::size_t light = 0; light < runs.size(); ++light) {
      runs[light].method = method_name;
      runs[light].light = light;
      runs[light].failure = prepare_failure;
    }
  }
  for (MethodRun& run : runs) run.prepare_ms = prepare_ms;
  return runs;
}

}  // namespace shadowkit
