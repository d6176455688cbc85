// A claim's verdict (algo/claims/ClaimVerdict): the paired bootstrap interval on hand-made
// series (a constant ratio has a zero-width interval, a noisy one straddles 1, the same seed
// gives the same interval) and the verdicts an interval gives: two-sided "within", "partly"
// only for an effect in the paper's direction, inconclusive when a bound is inside.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "algo/claims/ClaimVerdict.h"

namespace sl::claims {
namespace {

Interval point(double v) {
  return {v, v, v, 0};
}

TEST(PairedBootstrap, AConstantRatioHasAZeroWidthInterval) {
  // Every frame of a is half of b's: every resample gives 0.5.
  const std::vector<double> a = {1,  2,  3,  4,  5,  6,  7,  8,  9,  10,
                                 11, 12, 13, 14, 15, 16, 17, 18, 19, 20};
  std::vector<double> b;
  for (double v : a) b.push_back(2 * v);
  const Interval r = pairedBootstrap(a, b, Combine::Ratio);
  EXPECT_DOUBLE_EQ(r.value, 0.5);
  EXPECT_DOUBLE_EQ(r.low, 0.5);
  EXPECT_DOUBLE_EQ(r.high, 0.5);
  EXPECT_EQ(r.pairs, 20);
}

TEST(PairedBootstrap, PairingRemovesTheFramesOwnSpread) {
  // The frames differ a hundredfold (the view changes along the path), a is b plus or minus
  // 1 %: paired, the ratio's interval is within 1 % of 1; the frames' spread is not in it.
  std::vector<double> a, b;
  for (int i = 0; i < 20; ++i) {
    b.push_back(1.0 + 5.0 * i);
    a.push_back(b.back() * (i % 2 ? 1.01 : 0.99));
  }
  const Interval r = pairedBootstrap(a, b, Combine::Ratio);
  EXPECT_GT(r.low, 0.985);
  EXPECT_LT(r.high, 1.015);
  EXPECT_LE(r.low, r.value);
  EXPECT_GE(r.high, r.value);
  EXPECT_LT(r.low, 1.0);  // a straddles b: some frames better, some worse
  EXPECT_GT(r.high, 1.0);
}

TEST(PairedBootstrap, IsDeterministicAndDependsOnTheSeed) {
  const std::vector<double> a = {3, 1, 4, 1, 5, 9, 2, 6, 5, 3, 5, 8, 9, 7, 9, 3, 2, 3, 8, 4};
  const std::vector<double> b = {2, 7, 1, 8, 2, 8, 1, 8, 2, 8, 4, 5, 9, 0, 4, 5, 2, 3, 5, 3};
  const Interval r1 = pairedBootstrap(a, b, Combine::Ratio);
  const Interval r2 = pairedBootstrap(a, b, Combine::Ratio);
  EXPECT_EQ(r1.low, r2.low);
  EXPECT_EQ(r1.high, r2.high);
  const Interval other = pairedBootstrap(a, b, Combine::Ratio, kBootstrapResamples, 7);
  EXPECT_NE(r1.low, other.low);
  EXPECT_DOUBLE_EQ(r1.value, 97.0 / 87.0);  // Σa / Σb
  EXPECT_LT(r1.low, 1.0);                   // noisy: the interval holds 1
  EXPECT_GT(r1.high, 1.0);
}

TEST(PairedBootstrap, DifferenceAndSingleSeries) {
  const std::vector<double> a = {2, 2, 2, 2}, b = {1, 1, 1, 1};
  const Interval d = pairedBootstrap(a, b, Combine::Difference);
  EXPECT_DOUBLE_EQ(d.value, 1.0);
  EXPECT_DOUBLE_EQ(d.low, 1.0);
  EXPECT_DOUBLE_EQ(d.high, 1.0);
  const std::vector<double> share = {0.1, 0.3};
  const Interval m = pairedBootstrap(share, {}, Combine::A);
  EXPECT_DOUBLE_EQ(m.value, 0.2);
  EXPECT_GE(m.low, 0.1);
  EXPECT_LE(m.high, 0.3);
  EXPECT_THROW(pairedBootstrap(a, share, Combine::Ratio), std::invalid_argument);
}

TEST(Judge, OneSidedThresholds) {
  const Predicate lessError{"<=", 1.0, 0.0};
  EXPECT_EQ(judge(lessError, std::nullopt, {0.8, 0.7, 0.9, 20}), Verdict::Reproduced);
  EXPECT_EQ(judge(lessError, std::nullopt, {1.2, 1.1, 1.3, 20}), Verdict::NotReproduced);
  EXPECT_EQ(judge(lessError, std::nullopt, {0.98, 0.9, 1.05, 20}), Verdict::Inconclusive);
  EXPECT_EQ(judge(lessError, std::nullopt, point(1.0)), Verdict::Reproduced);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(judge(lessError, std::nullopt, {nan, nan, nan, 0}), Verdict::NotTestable);
}

TEST(Judge, WithinAFactorIsTwoSided) {
  // "within 2x" of 1: 0.296 is as far outside as 3.4 is.
  const Predicate within2x{"within-factor", 1.0, 2.0};
  EXPECT_EQ(judge(within2x, std::nullopt, point(0.296)), Verdict::NotReproduced);
  EXPECT_EQ(judge(within2x, std::nullopt, point(3.4)), Verdict::NotReproduced);
  EXPECT_EQ(judge(within2x, std::nullopt, point(0.6)), Verdict::Reproduced);
  EXPECT_EQ(judge(within2x, std::nullopt, point(1.9)), Verdict::Reproduced);
  EXPECT_EQ(judge(within2x, std::nullopt, {0.5, 0.4, 0.6, 20}), Verdict::Inconclusive);
  // An interval wider than the accepted set on both sides holds both bounds.
  EXPECT_EQ(judge(within2x, std::nullopt, {1.0, 0.1, 10.0, 20}), Verdict::Inconclusive);
  EXPECT_EQ(within2x.text(), "within 2x of 1");
}

TEST(Judge, PartlyIsASmallerEffectInThePapersDirection) {
  // The paper: at least 10x faster; partly: faster, by 3x or more.
  const Predicate tenfold{">=", 10.0, 0.0}, threefold{">=", 3.0, 0.0};
  EXPECT_EQ(judge(tenfold, threefold, {5.0, 4.0, 6.0, 3}), Verdict::Partly);
  EXPECT_EQ(judge(tenfold, threefold, {2.0, 1.5, 2.5, 3}), Verdict::NotReproduced);
  EXPECT_EQ(judge(tenfold, threefold, {3.0, 2.5, 3.5, 3}), Verdict::Inconclusive);
  EXPECT_EQ(judge(tenfold, threefold, {12.0, 11.0, 13.0, 3}), Verdict::Reproduced);
}

TEST(Predicate, SidesAndDirections) {
  EXPECT_EQ((Predicate{"<", 1.0, 0.0}).side(1.0), 1);
  EXPECT_EQ((Predicate{"<=", 1.0, 0.0}).side(1.0), 0);
  EXPECT_EQ((Predicate{">", 1.0, 0.0}).side(1.0), -1);
  EXPECT_EQ((Predicate{"within", 100.0, 0.01}).side(98.0), -1);
  EXPECT_EQ((Predicate{"within", 100.0, 0.01}).side(100.5), 0);
  EXPECT_EQ((Predicate{"<", 1.0, 0.0}).direction(), -1);
  EXPECT_EQ((Predicate{">=", 1.0, 0.0}).direction(), 1);
  EXPECT_EQ((Predicate{"within-factor", 1.0, 2.0}).direction(), 0);
  EXPECT_FALSE((Predicate{"<=", 1.0, 0.0}).holds(std::numeric_limits<double>::quiet_NaN()));
}

}  // namespace
}  // namespace sl::claims
