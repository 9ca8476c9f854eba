#include "cube_map.h"

#include <algorithm>
#include <cmath>

namespace shadowkit::shadowmap {
namespace {

struct FaceAxes {
  Vec3 forward, up;
};

// +X, -X, +Y, -Y, +Z, -Z. Any up vector along another world axis gives axis-aligned right and
// up vectors (right = forward x up), hence the exact pyramid of each face.
constexpr std::array<FaceAxes, CubeMap::kFaces> kFaceAxes{{
    {{1, 0, 0}, {0, 1, 0}},
    {{-1, 0, 0}, {0, 1, 0}},
    {{0, 1, 0}, {0, 0, 1}},
    {{0, -1, 0}, {0, 0, 1}},
    {{0, 0, 1}, {0, 1, 0}},
    {{0, 0, -1}, {0, 1, 0}},
}};
}  // namespace

RasterProjection CubeMap::face_view(int face, Vec3 eye, int resolution, double near) {
  const FaceAxes& axes = kFaceAxes[face];
  return RasterProjection::perspective(eye, axes.forward, axes.up, 90.0, resolution, resolution,
                                       near);
}

void CubeMap::render(const Scene& scene, Vec3 light_position, int resolution, const Context& ctx) {
  start(scene, light_position, resolution);
  for (DepthMap& face : faces_) face.draw(scene, ctx);
}

void CubeMap::start(const Scene& scene, Vec3 light_position, int resolution) {
  const double near = near_plane_for(scene.bounds(), light_position);
  for (int f = 0; f < kFaces; ++f) faces_[f].start(face_view(f, light_position, resolution, near));
}

std::size_t CubeMap::texel_count() const {
  std::size_t n = 0;
  for (const DepthMap& m : faces_) n += m.texel_count();
  return n;
}

std::size_t CubeMap::covered_texels() const {
  std::size_t n = 0;
  for (const DepthMap& m : faces_) n += m.covered_texels();
  return n;
}

std::size_t CubeMap::memory_bytes() const {
  std::size_t n = 0;
  for (const DepthMap& m : faces_) n += m.memory_bytes();
  return n;
}

}  // namespace shadowkit::shadowmap
