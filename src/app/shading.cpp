#include "shadowkit/app/shading.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "shadowkit/core/palette.h"

namespace shadowkit {

Image<Rgb8> shade_image(const Scene& scene, const VisibleSurfaceBuffer& surfaces,
                        const std::vector<const ShadowMask*>& masks) {
  Image<Rgb8> image(surfaces.width, surfaces.height, kBackground);
  const Vec3 eye = scene.camera.position;
  const double diffuse_share = (1.0 - kAmbient) / double(std::max<std::size_t>(1, masks.size()));
  tbb::parallel_for(0, surfaces.height, [&](int y) {
    for (int x = 0; x < surfaces.width; ++x) {
      const std::size_t i = surfaces.index(x, y);
      if (!surfaces.covered(i)) continue;
      const Plane& plane = scene.face_plane(surfaces.face[i]);
      const Vec3 p = surfaces.point(i);
      // Two-sided: the normal of the side the camera sees.
      const Vec3 n = plane.distance(eye) >= 0 ? plane.normal : -plane.normal;
      double light = kAmbient;
      for (std::size_t l = 0; l < masks.size(); ++l) {
        if (masks[l]->pixels[i] != kMaskLit) continue;
        light += diffuse_share * std::max(0.0, dot(n, scene.lights[l].direction_to(p)));
      }
      image.pixels[i] = to_rgb8(object_colour(surfaces.object(i)) * light);
    }
  });
  return image;
}

}  // namespace shadowkit
