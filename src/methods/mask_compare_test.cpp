#include "shadowkit/methods/mask_compare.h"

#include <gtest/gtest.h>

namespace shadowkit {
namespace {

TEST(MaskCompare, InteriorExcludesPixelsNearShadowAndObjectBoundaries) {
  // 6x4 reference: left three columns lit, right three shadowed; one object.
  ShadowMask ref(6, 4, kMaskLit);
  for (int y = 0; y < 4; ++y)
    for (int x = 3; x < 6; ++x) ref.at(x, y) = kMaskShadow;
  std::vector<std::uint32_t> ids(ref.size(), 0);
  ShadowMask mask = ref;
  mask.at(0, 0) = kMaskShadow;  // interior (corner, uniform clipped neighbourhood)
  mask.at(2, 1) = kMaskShadow;  // next to the shadow boundary: not interior
  const MaskComparison c = compare_masks(ref, mask, ids);
  EXPECT_EQ(c.surface_pixels, 24u);
  EXPECT_EQ(c.mismatched, 2u);
  EXPECT_EQ(c.interior_pixels, 16u);  // columns 0, 1, 4, 5
  EXPECT_EQ(c.interior_mismatched, 1u);
  EXPECT_DOUBLE_EQ(c.raw_pct(), 100.0 * 2 / 24);
  EXPECT_DOUBLE_EQ(c.interior_pct(), 100.0 / 16);

  ids[0] = 7;  // an object boundary at the corner removes (0,0), (1,0), (0,1), (1,1)
  EXPECT_EQ(compare_masks(ref, mask, ids).interior_pixels, 12u);
}

TEST(MaskCompare, BackgroundIsNotCounted) {
  ShadowMask ref(3, 3, kMaskBackground);
  ref.at(1, 1) = kMaskLit;
  const MaskComparison c = compare_masks(ref, ref, std::vector<std::uint32_t>(9, 0));
  EXPECT_EQ(c.surface_pixels, 1u);
  EXPECT_EQ(c.interior_pixels, 0u);
  EXPECT_EQ(c.raw_pct(), 0.0);
}

TEST(MaskCompare, DifferenceImageColoursEachDisagreement) {
  ShadowMask ref(2, 1, kMaskLit), mask(2, 1, kMaskLit);
  mask.at(1, 0) = kMaskShadow;
  const Image<Rgb8> diff = difference_image(ref, mask);
  EXPECT_EQ(diff.at(0, 0), (Rgb8{200, 200, 200}));
  EXPECT_EQ(diff.at(1, 0), (Rgb8{230, 40, 40}));
}

}  // namespace
}  // namespace shadowkit
