#include "embree_scene.h"

#include <atomic>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "ray_packet.h"

namespace shadowkit::raytrace {
namespace {

bool track_memory(void* user, ssize_t bytes, bool /*post*/) {
  static_cast<std::atomic<std::ptrdiff_t>*>(user)->fetch_add(bytes);
  return true;
}

// Nothing may be thrown through Embree's C frames: report here, check the error code after.
void report_error(void* /*user*/, RTCError code, const char* message) {
  std::fprintf(stderr, "shadowkit: Embree error %d: %s\n", int(code), message ? message : "");
}

}  // namespace

EmbreeScene::EmbreeScene(const Scene& scene) {
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw std::runtime_error("cannot create an Embree device");
  rtcSetDeviceErrorFunction(device_, report_error, nullptr);
  packet_width_ = native_packet_width(device_);
  std::atomic<std::ptrdiff_t> bytes{0};
  rtcSetDeviceMemoryMonitorFunction(device_, track_memory, &bytes);

  scene_ = rtcNewScene(device_);
  // Robust mode avoids the optimisations that can let a ray slip through a shared edge; a
  // shadow ray's context may carry a filter (RaytraceMethod: faces through the light).
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);

  const TriangleList& list = scene.triangles();
  origin_ = scene.bounds().empty() ? Vec3{} : scene.bounds().center();
  if (!list.triangles.empty()) {
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                          RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                          list.positions.size()));
    for (std::size_t i = 0; i < list.positions.size(); ++i) {
      const Vec3 p = list.positions[i] - origin_;
      v[3 * i] = float(p.x);
      v[3 * i + 1] = float(p.y);
      v[3 * i + 2] = float(p.z);
    }
    auto* idx = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), list.triangles.size()));
    std::memcpy(idx, list.triangles.data(), list.triangles.size() * 3 * sizeof(unsigned));
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
  }
  rtcCommitScene(scene_);
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) {
    throw std::runtime_error("Embree could not build the scene (see the message above)");
  }
  memory_bytes_ = std::size_t(std::max<std::ptrdiff_t>(0, bytes.load()));
  rtcSetDeviceMemoryMonitorFunction(device_, nullptr, nullptr);
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

}  // namespace shadowkit::raytrace
