// The lit area of every face for a sequence of directional lights (the sun study): one
// scene BSP tree (§3), one SVBSP tree per light (§4), areas summed as fragments come.
#include <span>

#include "scene_bsp.h"
#include "shadow_generator.h"
#include "shadowkit/methods/svbsp.h"

namespace shadowkit::svbsp {

SunlitAreas::SunlitAreas(const Scene& scene)
    : scene_(scene), bsp_(std::make_unique<const SceneBsp>(SceneBsp::build(scene))) {}

SunlitAreas::~SunlitAreas() = default;

std::vector<double> SunlitAreas::lit_areas(Vec3 toward_light) const {
  const Light light = Light::directional(-toward_light);
  std::vector<double> lit(scene_.face_count(), 0.0);
  ShadowGenerator generator(scene_, light);
  // Fragments are summed node by node and dropped: only the tree must grow (§4), not the
  // list of every fragment the fragments command keeps.
  std::vector<Fragment> fragments;
  bsp_->front_to_back(light, [&](std::span<const ConvexPolygon> coplanar) {
    fragments.clear();
    generator.process(coplanar, fragments);
    for (const Fragment& f : fragments) {
      if (f.lit) lit[f.polygon.face] += area(f.polygon);
    }
  });
  // The working frame is the world scaled by frame.scale (a power of two: exact).
  const double scale2 = scene_.frame.scale * scene_.frame.scale;
  for (double& a : lit) a *= scale2;
  return lit;
}

}  // namespace shadowkit::svbsp
