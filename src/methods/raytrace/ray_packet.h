#pragma once
// Embree's ray packets of 4, 8 and 16 lanes behind one template, and the widest one the CPU
// runs natively: rtcOccluded16 on a CPU without AVX-512 falls back to Embree's ray streams,
// which ignore the packet's valid mask and trace whatever the inactive lanes hold.
#include <embree3/rtcore.h>

namespace shadowkit::raytrace {

template <int kLanes>
struct RayPacket;

template <>
struct RayPacket<4> {
  using Rays = RTCRay4;
  static void occluded(const int* valid, RTCScene s, RTCIntersectContext* c, Rays* r) {
    rtcOccluded4(valid, s, c, r);
  }
};

template <>
struct RayPacket<8> {
  using Rays = RTCRay8;
  static void occluded(const int* valid, RTCScene s, RTCIntersectContext* c, Rays* r) {
    rtcOccluded8(valid, s, c, r);
  }
};

template <>
struct RayPacket<16> {
  using Rays = RTCRay16;
  static void occluded(const int* valid, RTCScene s, RTCIntersectContext* c, Rays* r) {
    rtcOccluded16(valid, s, c, r);
  }
};

/// The widest packet \p device traces natively: 16, 8 or 4 lanes.
inline int native_packet_width(RTCDevice device) {
  if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED)) return 16;
  if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED)) return 8;
  return 4;
}

/// Calls \p fn with RayPacket<W>{} for the packet width \p width (16, 8 or 4).
template <class Fn>
void with_packet_width(int width, Fn&& fn) {
  if (width == 16) {
    fn(RayPacket<16>{});
  } else if (width == 8) {
    fn(RayPacket<8>{});
  } else {
    fn(RayPacket<4>{});
  }
}

}  // namespace shadowkit::raytrace
