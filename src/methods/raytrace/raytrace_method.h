#pragma once
// raytrace: the exact reference. Embree shadow rays from every visible point.
#include <memory>
#include <vector>

#include "embree_scene.h"
#include "shadowkit/methods/shadow_method.h"

namespace shadowkit::raytrace {

/// \brief Shadow rays in packets of the widest width the CPU traces natively (16 lanes with
/// AVX-512, else 8) over 16x16 pixel tiles, with the
/// contract's two-sided rule and a self-intersection offset along the face normal. The BVH
/// and the per-face offsets are built once per scene.
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
  template <int kLanes>
  void shade_in_packets(const Scene& scene, const VisibleSurfaceBuffer& surfaces, ShadowMask& mask);

  std::unique_ptr<EmbreeScene> embree_;
  std::vector<float> face_offset_;  ///< per face, from prepare()
  /// Per face for the current light: the offset signed toward the side the camera and the
  /// light share, or 0 when they are on opposite sides (contract condition 1).
  std::vector<float> lit_side_offset_;
  /// Per triangle for the current light: its face's plane passes exactly through the light
  /// (or, for a directional light, along it), so it lies between no point and the light.
  std::vector<char> through_light_;
  bool any_through_light_ = false;
  Light light_;
  double rays_ = 0;
};

/// The smallest origin offset along the normal that keeps shadow rays off a face: Embree
/// stores and intersects the face's triangles in float, so their error grows with the
/// largest coordinate of the face's vertices; a face that is planar only within the mesh
/// tolerance adds its deviation from its plane.
/// Coordinates are taken relative to \p origin, as Embree stores them.
double face_offset(const Mesh& mesh, std::size_t face, Vec3 origin);

/// The offset for a point \p p (relative to Embree's origin) on a face with face_offset()
/// \p face_part: float storage of the point itself errs in proportion to its largest
/// coordinate.
double shadow_ray_offset(Vec3 p, double face_part);

}  // namespace shadowkit::raytrace
