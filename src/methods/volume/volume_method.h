#pragma once
// volume: Crow 1977 shadow volumes, counted per pixel against the visible surfaces.
#include <vector>

#include "shadow_polygon.h"
#include "shadowkit/methods/shadow_method.h"
#include "shadowkit/scene/sub_objects.h"
#include "stencil_count.h"
#include "volume_culling.h"

namespace shadowkit::volume {

/// \brief Crow's third class (Sec. VII): per light, contour edges chained into loops, one
/// shadow polygon per contour edge, and a per-pixel count of the shadow polygons between
/// the eye and the visible point (depth-pass, starting from the eye's own count) or behind
/// it (depth-fail, with light and dark caps), chosen per sub-object. Option `count`:
/// auto (default), pass or fail.
class VolumeMethod final : public ShadowMethod {
 public:
  enum class Counting { automatic, depth_pass, depth_fail };

  explicit VolumeMethod(const MethodOptions& options);
  std::string_view name() const override { return "volume"; }
  void prepare(const Scene& scene, const Context& ctx) override;
  void build(const Scene& scene, std::size_t light, const Context& ctx) override;
  void shade(const Scene& scene, const VisibleSurfaceBuffer& surfaces, ShadowMask& mask,
             const Context& ctx) override;
  std::size_t memory_bytes() const override;
  MethodCounters counters() const override;

 private:
  void cut_frusta(const Scene& scene, const std::vector<char>& complete);

  Counting counting_ = Counting::automatic;
  SubObjects parts_;
  Light light_;
  ShadowFrusta frusta_;                        ///< per sub-object, for the current light
  std::vector<ShadowPolygon> polygons_;        ///< grouped by sub-object
  std::vector<raster::ScreenPolygon> screen_;  ///< the polygons on screen, in their order
  int eye_count_ = 0;  ///< per-face volumes holding the eye, over depth-pass sub-objects
  std::vector<const raster::ScreenPolygon*> items_;  ///< the counting pass's, kept for its capacity
  double contour_edges_ = 0, contour_loops_ = 0, open_loops_ = 0;
  double depth_fail_sub_objects_ = 0, culled_sub_objects_ = 0, shadowed_sub_objects_ = 0;
  double fill_ = 0, negative_counts_ = 0, receiver_culled_ = 0, convex_volumes_ = 0,
         shadowed_cells_ = 0;
};

}  // namespace shadowkit::volume
