#include "face_culling.h"

#include <tbb/parallel_for.h>

#include <span>

#include "shadowkit/core/error.h"

namespace shadowkit::shadowmap {
namespace {

constexpr int kFaceBits = 5;
constexpr std::uint32_t kFaceMask = (1u << kFaceBits) - 1;

std::uint32_t pyramid_outside(const RasterProjection& view, Vec3 d) {
  const Vec3 v = AxisFrame(view).to_view(d);
  return std::uint32_t(v.z < view.near) | std::uint32_t(v.x > v.z) << 1 |
         std::uint32_t(-v.x > v.z) << 2 | std::uint32_t(v.y > v.z) << 3 |
         std::uint32_t(-v.y > v.z) << 4;
}

}  // namespace

AxisFrame::AxisFrame(const RasterProjection& view) {
  const Vec3 axes[3] = {view.right, view.up, view.forward};
  for (int k = 0; k < 3; ++k) {
    index_[k] = axes[k].x != 0 ? 0 : (axes[k].y != 0 ? 1 : 2);
    sign_[k] = axes[k][index_[k]];
  }
}

FaceCulling::FaceCulling(const Scene& scene, std::span<const RasterProjection> views)
    : scene_(scene), outside_(scene.triangles().positions.size()) {
  SHADOWKIT_CHECK(views.size() * kFaceBits <= 32);
  const std::vector<Vec3>& positions = scene.triangles().positions;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, positions.size(), 4096), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      std::uint32_t bits = 0;
      for (std::size_t f = 0; f < views.size(); ++f) {
        bits |= pyramid_outside(views[f], positions[i] - views[f].eye) << (kFaceBits * f);
      }
      outside_[i] = bits;
    }
  });
}

bool FaceCulling::reaches(std::size_t t, int face) const {
  const auto& tri = scene_.triangles().triangles[t];
  const std::uint32_t all = outside_[tri[0]] & outside_[tri[1]] & outside_[tri[2]];
  return ((all >> (kFaceBits * face)) & kFaceMask) == 0;
}

}  // namespace shadowkit::shadowmap
