// raytrace against raw Embree on the same visible points, measured side by side: the
// method's overhead over the bare minimum of native-width packets on 16x16 tiles.
#include <benchmark/benchmark.h>
#include <tbb/parallel_for.h>

#include <limits>

#include "ray_packet.h"
#include "raytrace_method.h"
#include "testing/method_testing.h"

namespace shadowkit::raytrace {
namespace {

using Fixture = testing::RenderedScene;

const Fixture& cubes() {
  static const Fixture f("cubes:2000");
  return f;
}

// The bare minimum: packets of the native width along each tile row, fixed offset, no
// two-sided rule.
void BM_RawEmbree(benchmark::State& state) {
  const Fixture& f = cubes();
  const EmbreeScene embree(f.scene);
  const Vec3 light = f.scene.lights[0].position - embree.origin();
  const int tiles_x = (f.vsb.width + 15) / 16, tiles_y = (f.vsb.height + 15) / 16;
  with_packet_width(embree.packet_width(), [&]<int kLanes>(RayPacket<kLanes>) {
    for (auto _ : state) {
      tbb::parallel_for(0, tiles_x * tiles_y, [&](int tile) {
        const int x0 = (tile % tiles_x) * 16, y0 = (tile / tiles_x) * 16;
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        alignas(64) typename RayPacket<kLanes>::Rays rays;
        alignas(64) int valid[kLanes];
        for (int y = y0; y < std::min(y0 + 16, f.vsb.height); ++y) {
          for (int xp = x0; xp < x0 + 16; xp += kLanes) {
            for (int k = 0; k < kLanes; ++k) {
              const int x = xp + k;
              const std::size_t i = f.vsb.index(std::min(x, f.vsb.width - 1), y);
              valid[k] = x < f.vsb.width && f.vsb.covered(i) ? -1 : 0;
              if (!valid[k]) continue;
              const Vec3 n = f.scene.face_plane(f.vsb.face[i]).normal;
              const Vec3 o = f.vsb.point(i) - embree.origin() + n * 1e-4;
              const Vec3 d = light - o;
              rays.org_x[k] = float(o.x), rays.org_y[k] = float(o.y), rays.org_z[k] = float(o.z);
              rays.dir_x[k] = float(d.x), rays.dir_y[k] = float(d.y), rays.dir_z[k] = float(d.z);
              rays.tnear[k] = 0, rays.tfar[k] = 1.0f - 1e-6f, rays.time[k] = 0;
              rays.mask[k] = ~0u, rays.id[k] = unsigned(k), rays.flags[k] = 0;
            }
            RayPacket<kLanes>::occluded(valid, embree.handle(), &ctx, &rays);
            benchmark::DoNotOptimize(rays.tfar[0]);
          }
        }
      });
    }
  });
}
BENCHMARK(BM_RawEmbree)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

void BM_RaytraceMethod(benchmark::State& state) {
  const Fixture& f = cubes();
  RaytraceMethod method({});
  method.prepare(f.scene, {});
  method.build(f.scene, 0, {});
  ShadowMask mask(f.vsb.width, f.vsb.height);
  for (auto _ : state) method.shade(f.scene, f.vsb, mask, {});
}
BENCHMARK(BM_RaytraceMethod)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

}  // namespace
}  // namespace shadowkit::raytrace
