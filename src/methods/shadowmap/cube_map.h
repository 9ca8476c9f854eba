#pragma once
// A point light's shadow map: six 90° perspective depth maps on the faces of a cube around the
// light. Williams 1978 renders a single view from the light; a light that radiates in every
// direction needs views that together see the whole sphere, and six cube faces are the usual
// (environment-map) way to get that with ordinary perspective projections.
#include <array>
#include <cmath>
#include <cstddef>

#include "depth_map.h"
#include "shadowkit/core/context.h"
#include "shadowkit/core/vec.h"
#include "shadowkit/raster/projection.h"
#include "shadowkit/scene/scene.h"

namespace shadowkit::shadowmap {

/// \brief Six square depth maps looking along +X, -X, +Y, -Y, +Z, -Z from a point light.
///
/// Every face's right and up vectors are world axes, so face f sees exactly the pyramid
/// |xv| <= zv, |yv| <= zv around its axis, and the six pyramids tile the sphere: a direction
/// belongs to the face of its dominant axis. A direction on a cube edge or corner belongs to
/// two or three faces equally; face_of() picks one and its projection still lies on the map
/// (on its border, clamped to the edge texel).
class CubeMap {
 public:
  static constexpr int kFaces = 6;

  /// The face for direction \p d from the light: the dominant axis and its sign. Ties go to
  /// x before y before z; the zero vector gets face 0.
  static int face_of(Vec3 d) {
    const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    if (ax >= ay && ax >= az) return d.x >= 0 ? 0 : 1;
    if (ay >= az) return d.y >= 0 ? 2 : 3;
    return d.z >= 0 ? 4 : 5;
  }
  /// The view of face \p face for a light at \p eye: a square 90° perspective view.
  static RasterProjection face_view(int face, Vec3 eye, int resolution, double near);

  /// Renders all six faces of \p scene for a point light at \p light_position: start(), then
  /// every tile of every face drawn.
  void render(const Scene& scene, Vec3 light_position, int resolution, const Context& ctx);
  /// Sets the six faces up for a point light at \p light_position with no tile drawn.
  void start(const Scene& scene, Vec3 light_position, int resolution);

  const DepthMap& face(int f) const { return faces_[f]; }
  DepthMap& face(int f) { return faces_[f]; }
  std::size_t texel_count() const;
  std::size_t covered_texels() const;
  /// The maps' bytes.
  std::size_t memory_bytes() const;

 private:
  std::array<DepthMap, kFaces> faces_;
};

}  // namespace shadowkit::shadowmap
