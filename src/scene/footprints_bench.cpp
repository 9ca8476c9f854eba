// Crow's footprints alone (shadowed_sub_objects), which every light's build of `volume`,
// `angular` and `svbsp` runs first: on cube fields of 8,000 to 80,000 sub-objects under
// their own point light, whose footprints fall on the faces of a cube around it, and under a
// sun, whose footprints fall on one plane: `build/bench/footprints_bench`.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>
#include <string>

#include "shadowkit/scene/footprints.h"
#include "shadowkit/scene/scene_file.h"

namespace shadowkit {
namespace {

struct Loaded {
  Scene scene;
  SubObjects parts;
};

const Loaded& loaded(const std::string& spec) {
  static std::map<std::string, Loaded> scenes;
  auto it = scenes.find(spec);
  if (it == scenes.end()) {
    Scene scene = load_scene(spec, {});
    SubObjects parts = SubObjects::of(scene);
    it = scenes.emplace(spec, Loaded{std::move(scene), std::move(parts)}).first;
  }
  return it->second;
}

void footprints(benchmark::State& state, const Light& light) {
  const Loaded& field = loaded("cubes:" + std::to_string(state.range(0)));
  std::size_t shadowed = 0;
  for (auto _ : state) {
    const std::vector<char> marked = shadowed_sub_objects(field.parts, light, field.scene.bounds());
    shadowed = std::size_t(std::count(marked.begin(), marked.end(), 1));
  }
  state.counters["sub_objects"] = double(field.parts.size());
  state.counters["shadowed"] = double(shadowed);
}

void BM_FootprintsPointLight(benchmark::State& state) {
  footprints(state, loaded("cubes:" + std::to_string(state.range(0))).scene.lights.at(0));
}
BENCHMARK(BM_FootprintsPointLight)
    ->Arg(8000)
    ->Arg(30000)
    ->Arg(80000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_FootprintsSun(benchmark::State& state) {
  footprints(state, Light::directional({-0.4, -1, -0.3}));
}
BENCHMARK(BM_FootprintsSun)->Arg(8000)->Arg(80000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace shadowkit
