// The shared scan conversion alone (render_visible_surfaces), on cube fields from 24k to
// 960k triangles: `build/src/raster/scan_bench`. The commands' `bench` times it beside the
// methods; here nothing else runs.
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "shadowkit/raster/visible_surface.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit {
namespace {

const Scene& cube_field(int cubes) {
  static std::map<int, Scene> scenes;
  auto it = scenes.find(cubes);
  if (it == scenes.end()) {
    it = scenes.emplace(cubes, load_scene("cubes:" + std::to_string(cubes), {})).first;
  }
  return it->second;
}

void BM_VisibleSurfaces(benchmark::State& state) {
  const Scene& scene = cube_field(int(state.range(0)));
  VisibleSurfaceBuffer vsb;
  for (auto _ : state) {
    render_visible_surfaces(scene, {}, vsb);
    benchmark::DoNotOptimize(vsb.face.data());
  }
  state.counters["triangles"] = double(scene.triangles().triangles.size());
}
BENCHMARK(BM_VisibleSurfaces)
    ->Arg(2000)
    ->Arg(8000)
    ->Arg(30000)
    ->Arg(80000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace shadowkit
