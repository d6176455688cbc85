// Benchmark statistics (algo/metrics/BenchStats): percentiles by the closest-ranks rule,
// aliasing summaries, mask change and false flicker, and the Pareto front — exact answers
// on small hand-made inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "algo/metrics/BenchStats.h"

namespace sl {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(BenchStats, PercentileInterpolatesBetweenClosestRanks) {
  const std::vector<double> v = {15, 20, 35, 40, 50};  // given unsorted below
  const std::vector<double> shuffled = {40, 15, 50, 20, 35};
  EXPECT_DOUBLE_EQ(percentile(shuffled, 0), 15);
  EXPECT_DOUBLE_EQ(percentile(shuffled, 100), 50);
  EXPECT_DOUBLE_EQ(percentile(shuffled, 50), 35);
  EXPECT_DOUBLE_EQ(percentile(shuffled, 25), 20);  // h = 1
  EXPECT_DOUBLE_EQ(percentile(shuffled, 40), 29);  // h = 1.6: 20 + 0.6 * 15
  EXPECT_DOUBLE_EQ(percentile(shuffled, 95), 48);  // h = 3.8: 40 + 0.8 * 10
  EXPECT_DOUBLE_EQ(percentile(v, 95), 48);
  EXPECT_DOUBLE_EQ(percentile(shuffled, -5), 15);   // clamped
  EXPECT_DOUBLE_EQ(percentile(shuffled, 250), 50);  // clamped
}

TEST(BenchStats, MedianOfEvenAndOddCounts) {
  EXPECT_DOUBLE_EQ(median(std::vector<double>{3, 1, 2}), 2);
  EXPECT_DOUBLE_EQ(median(std::vector<double>{4, 1, 3, 2}), 2.5);
  EXPECT_DOUBLE_EQ(median(std::vector<double>{7}), 7);
  EXPECT_DOUBLE_EQ(median(std::vector<double>{}), 0);
  EXPECT_DOUBLE_EQ(median(std::vector<double>{5, 5, 5, 5}), 5);
}

TEST(BenchStats, PercentileIgnoresNonFiniteValues) {
  EXPECT_DOUBLE_EQ(median(std::vector<double>{kNaN, 1, kInf, 3, -kInf}), 2);
  EXPECT_DOUBLE_EQ(percentile(std::vector<double>{kNaN}, 50), 0);
  EXPECT_DOUBLE_EQ(percentile(std::vector<float>{1.0f, 2.0f, 3.0f}, 50), 2);
}

TEST(BenchStats, AliasingStatsOverCoveredPixelsOnly) {
  // Pixels: three covered with m = 1, 2, 4; one uncovered (mask 255) with m = 100;
  // one covered with m = 0 (no coordinate); one covered with m = inf.
  const std::vector<float> m = {1.0f, 2.0f, 100.0f,
                                4.0f, 0.0f, std::numeric_limits<float>::infinity()};
  const std::vector<std::uint8_t> mask = {1, 0, 255, 1, 1, 0};
  AliasingStats s = computeAliasingStats(m, mask);
  EXPECT_EQ(s.pixels, 3u);
  EXPECT_EQ(s.nonFinite, 1u);
  EXPECT_DOUBLE_EQ(s.mean, 7.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
  EXPECT_DOUBLE_EQ(s.p95, 2.0 + 0.9 * 2.0);  // h = 1.9
  EXPECT_THROW(computeAliasingStats(m, std::vector<std::uint8_t>(2, 1)), std::invalid_argument);
  AliasingStats none = computeAliasingStats({}, {});
  EXPECT_EQ(none.pixels, 0u);
  EXPECT_EQ(none.mean, 0.0);
}

TEST(BenchStats, MaskChangeCountsPixelsCoveredInBothFrames) {
  const std::vector<std::uint8_t> a = {1, 1, 0, 0, 255, 1, 7};
  const std::vector<std::uint8_t> b = {1, 0, 0, 1, 1, 255, 1};  // 7 reads as lit
  MaskChange c = compareConsecutiveMasks(a, b);
  EXPECT_EQ(c.compared, 5u);
  EXPECT_EQ(c.changed, 2u);
  EXPECT_DOUBLE_EQ(c.pct, 40.0);
  EXPECT_EQ(compareConsecutiveMasks(a, a).changed, 0u);
  EXPECT_EQ(compareConsecutiveMasks({}, {}).pct, 0.0);
  EXPECT_THROW(compareConsecutiveMasks(a, std::vector<std::uint8_t>(3, 1)), std::invalid_argument);
}

TEST(BenchStats, FlickerIsATechniqueFlipTheReferenceDoesNotMake) {
  //                          px: 0  1  2  3  4    5
  const std::vector<std::uint8_t> m0 = {1, 1, 0, 1, 1, 1};
  const std::vector<std::uint8_t> m1 = {1, 0, 1, 0, 0, 255};
  const std::vector<std::uint8_t> r0 = {1, 1, 0, 0, 1, 1};
  const std::vector<std::uint8_t> r1 = {1, 1, 1, 1, 0, 1};
  // px0 steady; px1 technique flips, reference steady: flicker; px2 both flip: true flip;
  // px3 technique flips, reference flips: true; px4 both flip; px5 not covered.
  FlickerStats f = computeFlicker(m0, m1, r0, r1);
  EXPECT_EQ(f.compared, 5u);
  EXPECT_EQ(f.flicker, 1u);
  EXPECT_EQ(f.trueFlips, 3u);
  EXPECT_DOUBLE_EQ(f.pct, 20.0);
  // A static frame (identical masks) has no flicker whatever the error.
  EXPECT_EQ(computeFlicker(m0, m0, r1, r1).flicker, 0u);
  EXPECT_THROW(computeFlicker(m0, m1, r0, std::vector<std::uint8_t>(2, 1)), std::invalid_argument);
}

TEST(BenchStats, ParetoFrontOnSmallInputs) {
  //                               0         1         2         3        4         5
  const std::vector<CostPoint> p = {{1, 10}, {2, 5}, {3, 6}, {4, 1}, {2, 5}, {0.5, 20}};
  // 2 is dominated by 1 (faster and better); 4 duplicates 1 (both stay).
  EXPECT_EQ(paretoFront(p), (std::vector<std::size_t>{5, 0, 1, 4, 3}));
}

TEST(BenchStats, ParetoFrontTiesAndNonFinite) {
  // Same cost, worse error: dominated. Same error, slower: dominated.
  const std::vector<CostPoint> p = {{1, 2}, {1, 3}, {2, 2}, {kNaN, 0}, {0, kInf}};
  EXPECT_EQ(paretoFront(p), (std::vector<std::size_t>{0}));
  EXPECT_TRUE(paretoFront({}).empty());
  const std::vector<CostPoint> one = {{3, 3}};
  EXPECT_EQ(paretoFront(one), (std::vector<std::size_t>{0}));
}

TEST(BenchStats, ParetoFrontOfAChainIsEveryPoint) {
  std::vector<CostPoint> p;
  for (int i = 0; i < 6; ++i) p.push_back({double(i), double(10 - i)});
  EXPECT_EQ(paretoFront(p), (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));
}

}  // namespace
}  // namespace sl
