#include "shadowkit/core/huge_pages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

namespace shadowkit {
namespace {

TEST(HugePages, ALargeArrayStartsOnAHugePageAndHoldsItsValues) {
  const std::size_t n = kHugePageBytes / sizeof(float) * 3 + 17;
  HugePageArray<float> a = make_huge_page_array<float>(n);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(a.get()) % kHugePageBytes, 0u);
  std::iota(a.get(), a.get() + n, 0.0f);
  EXPECT_EQ(a[0], 0.0f);
  EXPECT_EQ(a[n - 1], float(n - 1));
}

TEST(HugePages, SmallAndEmptyArraysAreOrdinaryAllocations) {
  HugePageArray<std::uint32_t> small = make_huge_page_array<std::uint32_t>(5);
  ASSERT_NE(small.get(), nullptr);
  small[4] = 7;
  EXPECT_EQ(small[4], 7u);
  EXPECT_NE(make_huge_page_array<double>(0).get(), nullptr);
}

}  // namespace
}  // namespace shadowkit
