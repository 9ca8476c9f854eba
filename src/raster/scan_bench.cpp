// The shared scan conversion alone (render_visible_surfaces), on cube fields from 24k to
// 960k triangles, where the near cubes hide most of the rest, and on terrains of 51k and
// 500k triangles, nearly all in view: `build/bench/scan_bench`. The commands' `bench` times
// it beside the methods; here nothing else runs.
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "shadowkit/raster/visible_surface.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit {
namespace {

const Scene& builtin(const std::string& spec) {
  static std::map<std::string, Scene> scenes;
  auto it = scenes.find(spec);
  if (it == scenes.end()) it = scenes.emplace(spec, load_scene(spec, {})).first;
  return it->second;
}

void visible_surfaces(benchmark::State& state, const std::string& scene_name) {
  const Scene& scene = builtin(scene_name + ":" + std::to_string(state.range(0)));
  VisibleSurfaceBuffer vsb;
  for (auto _ : state) {
    render_visible_surfaces(scene, {}, vsb);
    benchmark::DoNotOptimize(vsb.face.data());
  }
  state.counters["triangles"] = double(scene.triangles().triangles.size());
}

void BM_VisibleSurfaces(benchmark::State& state) {
  visible_surfaces(state, "cubes");
}
BENCHMARK(BM_VisibleSurfaces)
    ->Arg(125)
    ->Arg(2000)
    ->Arg(8000)
    ->Arg(30000)
    ->Arg(80000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_VisibleSurfacesTerrain(benchmark::State& state) {
  visible_surfaces(state, "terrain");
}
BENCHMARK(BM_VisibleSurfacesTerrain)
    ->Arg(160)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace shadowkit
