#include <limits>

#include "embree_scene.h"
#include "shadowkit/methods/raytrace.h"

namespace shadowkit::raytrace {

ShadowRays::ShadowRays(const Scene& scene) : embree_(std::make_unique<EmbreeScene>(scene)) {}

ShadowRays::~ShadowRays() = default;

bool ShadowRays::occluded(Vec3 p, const Light& light) const {
  const Vec3 o = p - embree_->origin();
  const bool point = light.type == Light::Type::point;
  const Vec3 d = point ? light.position - p : -light.direction;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = float(o.x), ray.org_y = float(o.y), ray.org_z = float(o.z);
  ray.dir_x = float(d.x), ray.dir_y = float(d.y), ray.dir_z = float(d.z);
  ray.tnear = 0;
  // Short of a point light: the light's own position is not an occluder.
  ray.tfar = point ? 1 - 1e-6f : std::numeric_limits<float>::infinity();
  ray.mask = ~0u;
  rtcOccluded1(embree_->handle(), &context, &ray);
  return ray.tfar < 0;
}

}  // namespace shadowkit::raytrace
