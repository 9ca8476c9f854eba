#pragma once
// RAII ownership of an Embree device and a scene BVH over every triangle of a Scene.
#include <embree3/rtcore.h>

#include "shadowkit/scene/scene.h"

namespace shadowkit::raytrace {

/// \brief One Embree device and one committed scene; triangle primID i is the scene's
/// triangle i, so primID maps to a face through TriangleList::triangle_face. Embree works in
/// float, so positions are stored relative to origin() (the centre of the scene's bounds):
/// their precision then depends on the scene's size, not on where it sits.
class EmbreeScene {
 public:
  explicit EmbreeScene(const Scene& scene);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  RTCScene handle() const { return scene_; }
  /// Subtract from world positions before handing them to Embree.
  Vec3 origin() const { return origin_; }
  /// Lanes of the widest ray packet the CPU traces natively (ray_packet.h).
  int packet_width() const { return packet_width_; }
  /// Bytes Embree reports for its BVH and buffers.
  std::size_t memory_bytes() const { return memory_bytes_; }

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::size_t memory_bytes_ = 0;
  int packet_width_ = 4;
  Vec3 origin_;
};

}  // namespace shadowkit::raytrace
