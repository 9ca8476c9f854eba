// What a viewer frame costs past the method, at 1280x720 on the default scene: the shaded
// image, and the image as PNG at each speed (`build/bench/frame_bench`). The `bytes` counter
// is what goes over the frame stream; raw pixels would be width x height x 3.
#include <benchmark/benchmark.h>

#include "shadowkit/app/pipeline.h"
#include "shadowkit/app/shading.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit {
namespace {

struct DefaultFrame {
  Scene scene = load_scene(SHADOWKIT_SOURCE_DIR "/examples/default.json", {});
  CameraPass pass = run_camera_pass(scene, {}, {});
  std::vector<MethodRun> runs =
      run_method(scene, pass.surfaces, "raytrace", {}, {}, {}, OnFailure::stop);
};

const DefaultFrame& default_frame() {
  static const DefaultFrame frame;
  return frame;
}

void BM_ShadedImage(benchmark::State& state) {
  const DefaultFrame& f = default_frame();
  for (auto _ : state) {
    benchmark::DoNotOptimize(shade_image(f.scene, f.pass.surfaces, masks_of(f.runs)).pixels.data());
  }
}
BENCHMARK(BM_ShadedImage)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_EncodePng(benchmark::State& state) {
  const DefaultFrame& f = default_frame();
  const Image<Rgb8> image = shade_image(f.scene, f.pass.surfaces, masks_of(f.runs));
  const PngSpeed speed = state.range(0) ? PngSpeed::fast : PngSpeed::small;
  std::size_t bytes = 0;
  for (auto _ : state) bytes = encode_png(image, speed).size();
  state.counters["bytes"] = double(bytes);
  state.counters["raw_bytes"] = double(image.size() * 3);
  state.SetLabel(state.range(0) ? "fast" : "small");
}
BENCHMARK(BM_EncodePng)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace shadowkit
