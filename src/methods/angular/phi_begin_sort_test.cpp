#include "phi_begin_sort.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

namespace shadowkit::angular {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Pairs with the given begins, each numbered by its place (in `hidden`) to check stability.
std::vector<AngularPair> pairs_with_begins(const std::vector<double>& begins) {
  std::vector<AngularPair> pairs;
  for (std::size_t i = 0; i < begins.size(); ++i) {
    pairs.push_back({begins[i], begins[i] + 1, 0, std::uint32_t(i)});
  }
  return pairs;
}

// The order std::stable_sort gives, as the pairs' numbers.
std::vector<std::uint32_t> stable_order(std::vector<AngularPair> pairs) {
  std::stable_sort(pairs.begin(), pairs.end(), [](const AngularPair& a, const AngularPair& b) {
    return a.phi_begin < b.phi_begin;
  });
  std::vector<std::uint32_t> order;
  for (const AngularPair& p : pairs) order.push_back(p.hidden);
  return order;
}

std::vector<std::uint32_t> sorted_order(PhiBeginSort& sort, const std::vector<AngularPair>& pairs) {
  std::vector<std::uint32_t> order;
  for (const AngularPair& p : sort(pairs)) order.push_back(p.hidden);
  return order;
}

TEST(PhiBeginSort, MatchesAStableSortWithTiesAndInfiniteBegins) {
  PhiBeginSort sort;
  for (const std::vector<double>& begins : std::vector<std::vector<double>>{
           {},
           {3},
           {2, 1},
           {5, 5, 5, 5},                       // one finite value: a single bucket
           {1, -kInf, 0.5, kInf, -kInf, 0.5},  // walks from the light's axis
           {kInf, -kInf},                      // no finite begin at all
           {1e-300, 0, 2e-300, 1e-300},        // a subnormal range: an infinite scale
           {-1e308, 1e308, 0, 1},              // a range that overflows: scale 0
           {1e12, 1e12 + 0.5, 1e12 - 0.25},    // huge and close
       }) {
    const std::vector<AngularPair> pairs = pairs_with_begins(begins);
    EXPECT_EQ(sorted_order(sort, pairs), stable_order(pairs)) << begins.size() << " begins";
  }
}

TEST(PhiBeginSort, SortsManyNearlySortedAndClusteredEntriesWithOneSorter) {
  // As the table's entries come: runs of loops in order of their least phi, with begins
  // displaced from it, clustered, and repeated (hidden edges inserted in duplicate).
  std::mt19937_64 random(7);
  std::normal_distribution<double> jitter(0, 0.3);
  std::uniform_int_distribution<int> size(1, 300);
  PhiBeginSort sort;
  for (int entry = 0; entry < 200; ++entry) {
    std::vector<double> begins;
    const int n = size(random);
    for (int i = 0; i < n; ++i) {
      const double cluster = (i % 7) * 10.0;
      begins.push_back(i % 5 == 0 && i > 0 ? begins.back() : cluster + i * 0.01 + jitter(random));
    }
    const std::vector<AngularPair> pairs = pairs_with_begins(begins);
    ASSERT_EQ(sorted_order(sort, pairs), stable_order(pairs)) << "entry " << entry;
  }
}

TEST(PhiBeginSort, KeepsEveryFieldOfAPair) {
  PhiBeginSort sort;
  const std::vector<AngularPair> pairs{{2, 4, 9, 11}, {1, 3, 8, 10}};
  const auto sorted = sort(pairs);
  ASSERT_EQ(sorted.size(), 2u);
  EXPECT_EQ(sorted[0].phi_begin, 1);
  EXPECT_EQ(sorted[0].phi_end, 3);
  EXPECT_EQ(sorted[0].reach, 8);
  EXPECT_EQ(sorted[0].hidden, 10u);
  EXPECT_EQ(sorted[1].hidden, 11u);
}

}  // namespace
}  // namespace shadowkit::angular
