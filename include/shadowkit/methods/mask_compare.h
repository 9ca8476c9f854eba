#pragma once
/// \brief Pixel-by-pixel comparison of a method's mask with the reference mask.
#include <cstdint>
#include <vector>

#include "shadowkit/core/image.h"
#include "shadowkit/methods/shadow_method.h"

namespace shadowkit {

/// \brief Mismatch over the pixels where the reference sees a surface. Interior pixels are
/// those whose 3x3 neighbourhood (clipped to the image) in the reference is uniform in mask
/// value and object id: mismatches there are not explained by a boundary.
struct MaskComparison {
  std::size_t surface_pixels = 0;
  std::size_t mismatched = 0;
  std::size_t interior_pixels = 0;
  std::size_t interior_mismatched = 0;
  double raw_pct() const { return surface_pixels ? 100.0 * mismatched / surface_pixels : 0.0; }
  double interior_pct() const {
    return interior_pixels ? 100.0 * interior_mismatched / interior_pixels : 0.0;
  }
};

/// Compares \p mask with \p reference; \p object_ids gives the object per pixel (any value
/// for background) and has the masks' size.
MaskComparison compare_masks(const ShadowMask& reference, const ShadowMask& mask,
                             const std::vector<std::uint32_t>& object_ids);

/// A picture of the differences: agreeing lit pixels light grey, agreeing shadow dark grey,
/// shadow where the reference is lit red, lit where the reference is in shadow blue.
Image<Rgb8> difference_image(const ShadowMask& reference, const ShadowMask& mask);

/// \p mask as a grey image: each pixel's value in all three channels.
Image<Rgb8> grey_image(const ShadowMask& mask);

}  // namespace shadowkit
