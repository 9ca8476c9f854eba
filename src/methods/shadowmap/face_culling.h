#pragma once
// Which faces of a cube map each triangle can reach: raster::setup_triangles run for every
// face with every triangle would transform, clip and set up the scene six times, though most
// triangles reach one face.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "shadowkit/core/vec.h"
#include "shadowkit/raster/projection.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::shadowmap {

/// \brief The frame of a view whose right, up and forward vectors are signed world axes, as a
/// cube face's are. A point's view coordinates are then signed components of p - eye: what
/// RasterProjection::to_view computes, without its products (but for the sign of a zero,
/// which no projection or depth comparison sees).
class AxisFrame {
 public:
  AxisFrame() = default;
  explicit AxisFrame(const RasterProjection& view);
  /// The view coordinates of the point eye + \p d.
  Vec3 to_view(Vec3 d) const {
    return {sign_[0] * d[index_[0]], sign_[1] * d[index_[1]], sign_[2] * d[index_[2]]};
  }

 private:
  std::array<int, 3> index_{};
  std::array<double, 3> sign_{};
};

/// \brief Where each scene vertex lies against the pyramids |xv| <= zv, |yv| <= zv of cube
/// faces (CubeMap::face_view), in front of their near planes.
///
/// A triangle whose three vertices lie beyond one plane of a face's pyramid (or all behind its
/// near plane) lies beyond it whole: it projects past the face's edge, at least half a texel
/// from the nearest texel centre, and covers none.
class FaceCulling {
 public:
  /// \p views: at most six views whose right, up and forward vectors are signed world axes.
  FaceCulling(const Scene& scene, std::span<const RasterProjection> views);

  /// Whether triangle \p t of the scene's TriangleList can cover a texel of view \p face.
  bool reaches(std::size_t t, int face) const;

 private:
  const Scene& scene_;
  /// Per vertex, five bits per face: behind the near plane, xv > zv, -xv > zv, yv > zv,
  /// -yv > zv.
  std::vector<std::uint32_t> outside_;
};

}  // namespace shadowkit::shadowmap
