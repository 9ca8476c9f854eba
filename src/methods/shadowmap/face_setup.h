#pragma once
// Triangle setup for the six faces of a cube map, each triangle set up only for the faces it
// can reach. raster::setup_triangles run once per face would transform, clip and set up every
// triangle of the scene six times, though most triangles reach one face.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "shadowkit/core/vec.h"
#include "shadowkit/raster/projection.h"
#include "shadowkit/raster/triangle_setup.h"
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

/// \brief One cube face's triangle setup: the triangles of a scene that a FaceCulling lets
/// reach the face, set up for the face's view bit for bit as raster::setup_triangles sets them
/// up (fixed-point vertices, fill-rule biases, depth planes), so that the face's map is the
/// scan converter's. Its buffers are kept from one setup to the next: a new light's setup
/// then neither allocates nor faults in memory.
class FaceSetup {
 public:
  /// Sets up the triangles of \p scene that reach cube face \p face, whose view is \p view.
  void run(const Scene& scene, const FaceCulling& culling, int face, const RasterProjection& view);
  /// The triangles of the last run(), in no particular order.
  const std::vector<raster::ScreenTriangle>& triangles() const { return triangles_; }
  std::size_t memory_bytes() const;

 private:
  std::vector<std::vector<std::uint32_t>> reaching_;  ///< per chunk of the scene's triangles
  std::vector<std::uint8_t> used_, inside_;           ///< per vertex
  std::vector<raster::FixedPoint> fixed_;             ///< per vertex
  std::vector<std::vector<raster::ScreenTriangle>> chunks_;
  std::vector<raster::ScreenTriangle> triangles_;
};

}  // namespace shadowkit::shadowmap
