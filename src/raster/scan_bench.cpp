// The shared scan conversion alone (render_visible_surfaces), on cube fields from 1.5k to
// 960k triangles, where the near cubes hide most of the rest, on terrains of 51k and 500k
// triangles, nearly all in view, and on the IFC house of Debian's assimp-testmodels (36k
// triangles), a real model that leaves most of the view to the sky: `build/bench/scan_bench`.
// The commands' `bench` times it beside the methods; here nothing else runs.
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "shadowkit/raster/visible_surface.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit {
namespace {

const Scene& loaded(const std::string& spec) {
  static std::map<std::string, Scene> scenes;
  auto it = scenes.find(spec);
  if (it == scenes.end()) it = scenes.emplace(spec, load_scene(spec, {})).first;
  return it->second;
}

void visible_surfaces(benchmark::State& state, const std::string& spec) {
  const Scene& scene = loaded(spec);
  VisibleSurfaceBuffer vsb;
  for (auto _ : state) {
    render_visible_surfaces(scene, {}, vsb);
    benchmark::DoNotOptimize(vsb.face.data());
  }
  state.counters["triangles"] = double(scene.triangles().triangles.size());
}

void BM_VisibleSurfaces(benchmark::State& state) {
  visible_surfaces(state, "cubes:" + std::to_string(state.range(0)));
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
  visible_surfaces(state, "terrain:" + std::to_string(state.range(0)));
}
BENCHMARK(BM_VisibleSurfacesTerrain)
    ->Arg(160)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_VisibleSurfacesIfcHouse(benchmark::State& state) {
  visible_surfaces(state, "/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc");
}
BENCHMARK(BM_VisibleSurfacesIfcHouse)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace shadowkit
