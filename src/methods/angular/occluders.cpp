#include "occluders.h"

#include <algorithm>
#include <limits>

namespace shadowkit::angular {
namespace {

// Slab test of the segment origin + t dir, t in [0, t_max], against \p box grown by a margin.
bool segment_meets_box(Vec3 origin, Vec3 dir, double t_max, const Bounds3& box) {
  const double margin = 1e-6 * std::max(box.diagonal(), 1e-12);
  double t0 = 0, t1 = t_max;
  for (int a = 0; a < 3; ++a) {
    const double lo = box.lo[a] - margin, hi = box.hi[a] + margin;
    if (dir[a] == 0) {
      if (origin[a] < lo || origin[a] > hi) return false;
      continue;
    }
    double ta = (lo - origin[a]) / dir[a], tb = (hi - origin[a]) / dir[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

bool eye_and_light_may_be_apart(const Scene& scene, const Light& light, const Bounds3& box) {
  const Vec3 eye = scene.camera.position;
  if (light.type == Light::Type::point) return segment_meets_box(eye, light.position - eye, 1, box);
  return segment_meets_box(eye, -light.direction, std::numeric_limits<double>::infinity(), box);
}

}  // namespace

std::vector<FarSheets> occluding_sheets(const Scene& scene, const Light& light) {
  std::vector<FarSheets> sheets;
  sheets.reserve(scene.objects.size());
  for (const SceneObject& object : scene.objects) {
    const Mesh& mesh = object.mesh;
    const bool solid = one_solid(mesh) && !eye_and_light_may_be_apart(scene, light, mesh.bounds());
    sheets.push_back(far_sheets(mesh, light, solid));
  }
  return sheets;
}

void leave_out_shadowed(const Scene& scene, const SubObjects& parts,
                        const std::vector<char>& shadowed, std::vector<FarSheets>& sheets) {
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const std::uint32_t first = scene.objects[o].first_face;
    for (std::uint32_t f = 0; f < sheets[o].side.size(); ++f) {
      if (shadowed[parts.of_face[first + f]]) sheets[o].side[f] = 0;
    }
  }
}

}  // namespace shadowkit::angular
