// The angular method's two costs apart, on the papers' scalability simulation (Sec. 9): the
// table construction for N cubes, and the shading (all lookups) of the 2000-cube field next
// to raytrace. Process CPU time beside wall time: the machine is shared, and CPU time counts
// the work on both cores however busy they are.
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "angular_method.h"
#include "testing/method_testing.h"
#include "view_theta.h"

namespace shadowkit::angular {
namespace {

using Fixture = testing::RenderedScene;

const Fixture& cube_field(int count) {
  static std::map<int, Fixture> fields;
  auto it = fields.find(count);
  if (it == fields.end()) it = fields.emplace(count, "cubes:" + std::to_string(count)).first;
  return it->second;
}

void report(benchmark::State& state, const ShadowMethod& method) {
  for (const auto& [key, value] : method.counters()) state.counters[key] = value;
  state.counters["memory_MB"] = double(method.memory_bytes()) / 1e6;
}

void BM_TableConstruction(benchmark::State& state) {
  const Fixture& f = cube_field(int(state.range(0)));
  AngularMethod method({});
  method.prepare(f.scene, {});
  for (auto _ : state) method.build(f.scene, 0, {});
  report(state, method);
  state.counters["polygons"] = double(f.scene.face_count());
}
BENCHMARK(BM_TableConstruction)
    ->Arg(125)
    ->Arg(500)
    ->Arg(1000)
    ->Arg(2000)
    ->Arg(4000)
    ->Arg(8000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

// The automatic R's share of the construction: the receivers' integral (entry_theta).
void BM_EntryTheta(benchmark::State& state) {
  const Fixture& f = cube_field(int(state.range(0)));
  const Bounds3& box = f.scene.bounds();
  const LightFrame frame(f.scene.lights[0], f.scene.camera, (box.lo + box.hi) * 0.5);
  for (auto _ : state) benchmark::DoNotOptimize(entry_theta(f.scene, frame));
  state.counters["polygons"] = double(f.scene.face_count());
}
BENCHMARK(BM_EntryTheta)
    ->Arg(2000)
    ->Arg(8000)
    ->Arg(30000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

void BM_Shade(benchmark::State& state, const char* name) {
  const Fixture& f = cube_field(2000);
  const auto method = make_method(name, {});
  method->prepare(f.scene, {});
  method->build(f.scene, 0, {});
  ShadowMask mask(f.vsb.width, f.vsb.height);
  for (auto _ : state) method->shade(f.scene, f.vsb, mask, {});
  report(state, *method);
}
BENCHMARK_CAPTURE(BM_Shade, angular, "angular")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_Shade, raytrace, "raytrace")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

}  // namespace
}  // namespace shadowkit::angular
