#include "shadowkit/methods/mask_compare.h"

#include <algorithm>

#include "shadowkit/core/error.h"

namespace shadowkit {
namespace {

bool uniform_neighbourhood(const ShadowMask& ref, const std::vector<std::uint32_t>& ids, int x,
                           int y) {
  const std::size_t centre = std::size_t(y) * ref.width + x;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= ref.width || ny >= ref.height) continue;
      const std::size_t i = std::size_t(ny) * ref.width + nx;
      if (ref.pixels[i] != ref.pixels[centre] || ids[i] != ids[centre]) return false;
    }
  }
  return true;
}

}  // namespace

MaskComparison compare_masks(const ShadowMask& reference, const ShadowMask& mask,
                             const std::vector<std::uint32_t>& object_ids) {
  SHADOWKIT_CHECK(reference.width == mask.width && reference.height == mask.height);
  SHADOWKIT_CHECK(object_ids.size() == reference.size());
  MaskComparison c;
  for (int y = 0; y < reference.height; ++y) {
    for (int x = 0; x < reference.width; ++x) {
      const std::size_t i = std::size_t(y) * reference.width + x;
      if (reference.pixels[i] == kMaskBackground) continue;
      const bool differs = mask.pixels[i] != reference.pixels[i];
      ++c.surface_pixels;
      c.mismatched += differs;
      if (uniform_neighbourhood(reference, object_ids, x, y)) {
        ++c.interior_pixels;
        c.interior_mismatched += differs;
      }
    }
  }
  return c;
}

Image<Rgb8> difference_image(const ShadowMask& reference, const ShadowMask& mask) {
  Image<Rgb8> out(reference.width, reference.height);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::uint8_t r = reference.pixels[i], m = mask.pixels[i];
    if (r == kMaskBackground && m == kMaskBackground) continue;
    if (r == m) {
      out.pixels[i] = r == kMaskLit ? Rgb8{200, 200, 200} : Rgb8{90, 90, 90};
    } else {
      out.pixels[i] = m == kMaskShadow ? Rgb8{230, 40, 40} : Rgb8{40, 90, 240};
    }
  }
  return out;
}

Image<Rgb8> grey_image(const ShadowMask& mask) {
  Image<Rgb8> image(mask.width, mask.height);
  for (std::size_t i = 0; i < mask.size(); ++i) {
    image.pixels[i] = {mask.pixels[i], mask.pixels[i], mask.pixels[i]};
  }
  return image;
}

}  // namespace shadowkit
