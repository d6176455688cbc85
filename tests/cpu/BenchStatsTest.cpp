// Benchmark statistics (algo/metrics/BenchStats): percentiles by the closest-ranks rule,
// aliasing summaries, mask change and false flicker, the Pareto front against time and
// against memory, and the chart axes — exact answers on small hand-made inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
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

TEST(BenchStats, ParetoFrontAgainstTimeAndAgainstMemory) {
  // A hand-made sweep: uniform is fast but needs memory, RTW small but slow.
  struct Row {
    double ms, bytes, errorPct;
  };
  constexpr double kMiB = 1024.0 * 1024.0;
  const std::vector<Row> rows = {
      {20, 1 * kMiB, 2.0},    // 0 uniform 512
      {22, 4 * kMiB, 1.0},    // 1 uniform 1024
      {30, 16 * kMiB, 0.5},   // 2 uniform 2048
      {60, 0.5 * kMiB, 1.5},  // 3 rtw 256
      {70, 2 * kMiB, 0.8},    // 4 rtw 512
      {90, 8 * kMiB, 2.5},    // 5 rtw 1024
  };
  std::vector<CostPoint> byTime, byMemory;
  for (const Row& r : rows) {
    byTime.push_back({r.ms, r.errorPct});
    byMemory.push_back({r.bytes, r.errorPct});
  }
  // Time: uniform alone. Memory: 3 and 4 beat uniform 512 and 1024 with less memory;
  // 2048 stays (nothing is better); 5 is beaten by everything smaller.
  EXPECT_EQ(paretoFront(byTime), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(paretoFront(byMemory), (std::vector<std::size_t>{3, 4, 2}));
}

TEST(BenchStats, ChartXParsesMsAndBytesOnly) {
  EXPECT_EQ(parseChartX("ms"), ChartX::TimeMs);
  EXPECT_EQ(parseChartX("bytes"), ChartX::Bytes);
  EXPECT_FALSE(parseChartX("foo"));
  EXPECT_FALSE(parseChartX("MS"));
  EXPECT_FALSE(parseChartX(""));
  EXPECT_STREQ(chartHeadline(ChartX::TimeMs), "Speed against accuracy");
  EXPECT_STREQ(chartHeadline(ChartX::Bytes), "Memory against accuracy");
}

TEST(BenchStats, ByteUnitIsTheLargestWithAtLeastOne) {
  EXPECT_STREQ(byteUnitFor(1023).name, "bytes");
  EXPECT_EQ(byteUnitFor(1023).bytes, 1.0);
  EXPECT_STREQ(byteUnitFor(1024).name, "KiB");
  EXPECT_STREQ(byteUnitFor(1048575).name, "KiB");
  EXPECT_STREQ(byteUnitFor(1048576).name, "MiB");
  EXPECT_EQ(byteUnitFor(1048576).bytes, 1048576.0);
  EXPECT_STREQ(byteUnitFor(3.0 * 1073741824.0).name, "GiB");
  EXPECT_STREQ(byteUnitFor(5e12).name, "GiB");  // no TiB
  EXPECT_STREQ(byteUnitFor(kNaN).name, "bytes");
  EXPECT_STREQ(byteUnitFor(0).name, "bytes");
}

TEST(BenchStats, MemoryAxisInMiBTurnsLogBeyond8x) {
  constexpr double kMiB = 1024.0 * 1024.0;
  // 0.5 .. 16 MiB spans 32x: log, base 2, 1.6x margins, in MiB.
  const std::vector<double> wide = {0.5 * kMiB, 16 * kMiB, 2 * kMiB};
  const ChartAxis a = planCostAxis(ChartX::Bytes, wide);
  EXPECT_TRUE(a.log);
  EXPECT_EQ(a.logBase, 2.0);
  EXPECT_EQ(a.minorTicks, 0);
  EXPECT_EQ(a.unitScale, kMiB);
  EXPECT_DOUBLE_EQ(a.min, 0.5 / 1.6);
  EXPECT_DOUBLE_EQ(a.max, 16 * 1.6);
  EXPECT_EQ(a.title, "shadow memory (MiB), log scale");
  // 1 .. 4 MiB spans 4x: linear from 0 to niceAxisRange(4 * 1.08) = 4.5 (9 steps of 0.5).
  const std::vector<double> narrow = {1 * kMiB, 4 * kMiB};
  const ChartAxis b = planCostAxis(ChartX::Bytes, narrow);
  EXPECT_FALSE(b.log);
  EXPECT_EQ(b.min, 0.0);
  EXPECT_DOUBLE_EQ(b.max, 4.5);
  EXPECT_EQ(b.ticks, 10);
  EXPECT_EQ(b.title, "shadow memory (MiB)");
  // Exactly 8x stays linear; a zero (a technique with no map) keeps it linear.
  const std::vector<double> eight = {1 * kMiB, 8 * kMiB};
  EXPECT_FALSE(planCostAxis(ChartX::Bytes, eight).log);
  const std::vector<double> withZero = {0, 1 * kMiB, 64 * kMiB};
  EXPECT_FALSE(planCostAxis(ChartX::Bytes, withZero).log);
  // Small maps: KiB.
  const std::vector<double> small = {4096, 65536};
  EXPECT_EQ(planCostAxis(ChartX::Bytes, small).title, "shadow memory (KiB), log scale");
}

TEST(BenchStats, TimeAxisIsLinearFromZero) {
  const std::vector<double> ms = {2, 200, kNaN};  // 100x: still linear (time is additive)
  const ChartAxis a = planCostAxis(ChartX::TimeMs, ms);
  EXPECT_FALSE(a.log);
  EXPECT_EQ(a.unitScale, 1.0);
  EXPECT_EQ(a.min, 0.0);
  EXPECT_DOUBLE_EQ(a.max, 250.0);  // niceAxisRange(216): 5 steps of 50
  EXPECT_EQ(a.ticks, 6);
  EXPECT_EQ(a.title, "frame time, all passes (ms, median)");
}

TEST(BenchStats, ErrorAxisAutoLogAndRefusedLog) {
  const std::vector<double> wide = {0.1, 5.0};  // 50x > 20: log base 10
  const ChartAxis a = planChartAxis(wide, AxisScale::Auto, 20.0, 0.12, "error");
  EXPECT_TRUE(a.log);
  EXPECT_EQ(a.logBase, 10.0);
  EXPECT_EQ(a.minorTicks, 8);
  EXPECT_EQ(a.title, "error, log scale");
  EXPECT_FALSE(planChartAxis(wide, AxisScale::Linear, 20.0, 0.12, "error").log);
  const std::vector<double> withZero = {0.0, 5.0};
  EXPECT_FALSE(planChartAxis(withZero, AxisScale::Auto, 20.0, 0.12, "error").log);
  EXPECT_THROW(planChartAxis(withZero, AxisScale::Log, 20.0, 0.12, "error"), std::invalid_argument);
  // Nothing finite to show: a linear 0..1 axis.
  const ChartAxis none = planChartAxis({}, AxisScale::Log, 20.0, 0.12, "error");
  EXPECT_FALSE(none.log);
  EXPECT_EQ(none.max, 1.0);
}

}  // namespace
}  // namespace sl
