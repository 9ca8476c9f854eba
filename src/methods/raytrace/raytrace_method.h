#pragma once
// raytrace: the exact reference. Embree shadow rays from every visible point.
#include <memory>

#include "embree_scene.h"
#include "shadowkit/methods/shadow_method.h"

namespace shadowkit {

/// \brief Shadow rays in 16-wide packets (rtcOccluded16) over 16x16 pixel tiles, with the
/// contract's two-sided rule and a self-intersection offset relative to the point's
/// magnitude. The BVH is built once per scene.
class RaytraceMethod final : public ShadowMethod {
 public:
  explicit RaytraceMethod(const MethodOptions& options);
  std::string_view name() const override { return "raytrace"; }
  void prepare(const Scene& scene, const Context& ctx) override;
  void build(const Scene& scene, std::size_t light, const Context& ctx) override;
  void shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces, ShadowMask& mask,
             const Context& ctx) override;
  std::size_t memory_bytes() const override;
  MethodCounters counters() const override;

 private:
  std::unique_ptr<EmbreeScene> embree_;
  Light light_;
  double rays_ = 0;
};

/// The origin offset that keeps a shadow ray off its own surface: a fixed number of float
/// ulps of the point's largest coordinate (the scene is stored in float by Embree).
double shadow_ray_offset(Vec3 p);

}  // namespace shadowkit
