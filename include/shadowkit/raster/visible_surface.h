#pragma once
/// \brief The visible-surface buffer: what the camera sees at each pixel. Every method's
/// camera pass consumes it.
#include <cstdint>
#include <vector>

#include "shadowkit/core/context.h"
#include "shadowkit/core/vec.h"
#include "shadowkit/raster/scan_converter.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit {

/// \brief Per pixel (row-major, row 0 at the top): distance along the pixel's unit ray, the
/// visible point (intersection of the pixel's ray with the face plane, computed in double),
/// the global face id and the object id. Background pixels have face == kNoFace.
struct VisibleSurfaceBuffer {
  int width = 0, height = 0;
  std::vector<float> depth;
  std::vector<Vec3f> point;
  std::vector<std::uint32_t> face;
  std::vector<std::uint32_t> object;

  std::size_t index(int x, int y) const { return std::size_t(y) * width + x; }
  bool covered(std::size_t i) const { return face[i] != kNoFace; }
  std::size_t covered_count() const;
};

/// Scan-converts the scene from its camera and resolves each pixel's visible point.
VisibleSurfaceBuffer render_visible_surfaces(const Scene& scene, const Context& ctx);

/// The near-plane depth used for the camera: small against the scene's extent from the eye,
/// so that nothing a ray could hit is clipped in practice.
double camera_near_plane(const Scene& scene);

}  // namespace shadowkit
