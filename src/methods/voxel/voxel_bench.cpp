// Speed and memory of the voxel method (Lai & Cheng 2007): voxelization plus shadow
// determination of a ~1,000-face Catmull-Clark control mesh at M = 256 and 512, the frame
// buffer's memory at M = 1024, and a new view drawn from an existing frame buffer (§5.2).
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cmath>

#include "subpatch_render.h"
#include "testing/test_scenes.h"
#include "voxel_method.h"

namespace shadowkit::voxel {
namespace {

// A box whose faces are each split into n x n quads: 6 n^2 faces, eight extraordinary
// vertices (valence 3) at its corners.
PolygonSoup gridded_box(int n) {
  PolygonSoup soup;
  const auto face = [&](Vec3 origin, Vec3 du, Vec3 dv) {
    const auto first = std::uint32_t(soup.positions.size());
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i)
        soup.positions.push_back(origin + du * (i / double(n)) + dv * (j / double(n)));
    }
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const std::uint32_t a = first + std::uint32_t(j * (n + 1) + i);
        soup.add_face({a, a + 1, a + std::uint32_t(n) + 2, a + std::uint32_t(n) + 1});
      }
    }
  };
  const double s = 2;
  face({-s, -s, s}, {2 * s, 0, 0}, {0, 2 * s, 0});   // +z
  face({s, -s, -s}, {-2 * s, 0, 0}, {0, 2 * s, 0});  // -z
  face({s, -s, s}, {0, 0, -2 * s}, {0, 2 * s, 0});   // +x
  face({-s, -s, -s}, {0, 0, 2 * s}, {0, 2 * s, 0});  // -x
  face({-s, s, s}, {2 * s, 0, 0}, {0, 0, -2 * s});   // +y
  face({-s, -s, -s}, {2 * s, 0, 0}, {0, 0, 2 * s});  // -y
  return soup;
}

// The 1,014-face control mesh (13 x 13 per side, welded by the surface) over a ground.
const Scene& benchmark_scene() {
  static const Scene scene = [] {
    Scene s = testing::make_scene(testing::camera({3, 7, 12}, {0, 0, 0}, 640, 360),
                                  {testing::point_light({-4, 12, 5})},
                                  {testing::horizontal_quad(-12, 12, -12, 12, -2.6)});
    auto surface = SubdivisionSurface::build(gridded_box(13), "gridded box");
    s.objects.push_back(
        {"gridded box", Mesh::build(surface->tessellate(4), "box", {}), 0, surface});
    s.finalize();
    return s;
  }();
  return scene;
}

double counter_of(const ShadowMethod& method, const std::string& name) {
  for (const auto& [key, value] : method.counters()) {
    if (key == name) return value;
  }
  return -1;
}

// The process's peak resident memory so far, MB: run one case alone
// (--benchmark_filter) for the peak of that case, transient structures included.
double peak_resident_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1e3;
}

VoxelMethod method_at(int resolution, const char* test) {
  return VoxelMethod(
      MethodOptions("voxel", {{"resolution", std::to_string(resolution)}, {"test", test}}));
}

// §3 + §4: prepare (voxelization into the frame buffer) and build (shadow determination).
void BM_VoxelizeAndShadows(benchmark::State& state, const char* test) {
  const Scene& scene = benchmark_scene();
  VoxelMethod method = method_at(int(state.range(0)), test);
  for (auto _ : state) {
    method.prepare(scene, {});
    method.build(scene, 0, {});
  }
  state.counters["voxels"] = counter_of(method, "voxels");
  state.counters["subpatches"] = counter_of(method, "subpatches");
  state.counters["frame_buffer_MB"] = counter_of(method, "frame_buffer_bytes") / 1e6;
  state.counters["method_MB"] = double(method.memory_bytes()) / 1e6;
  state.counters["peak_rss_MB"] = peak_resident_mb();
}
BENCHMARK_CAPTURE(BM_VoxelizeAndShadows, topology, "topology")
    ->Arg(256)
    ->Arg(512)
    ->Arg(1024)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_VoxelizeAndShadows, offset, "offset")
    ->Arg(256)
    ->Arg(512)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// §5.2: with the frame buffer and the subpatches' shadow states kept, a new view is the
// rendering alone.
void BM_NewViewFromTheFrameBuffer(benchmark::State& state) {
  const Scene& scene = benchmark_scene();
  VoxelMethod method = method_at(int(state.range(0)), "topology");
  voxel::SubpatchImage image = voxel::make_subpatch_image(scene, method, {});
  Camera camera = scene.camera;
  double angle = 0;
  for (auto _ : state) {
    angle += 0.2;
    camera.position = {12 * std::sin(angle), 7, 12 * std::cos(angle)};
    benchmark::DoNotOptimize(image.render(camera));
  }
  state.counters["triangles"] = double(image.triangle_count());
}
BENCHMARK(BM_NewViewFromTheFrameBuffer)->Arg(256)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace shadowkit::voxel
