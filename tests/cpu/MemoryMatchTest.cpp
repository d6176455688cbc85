// The split view's equal-memory match (algo/MemoryMatch): the largest knob value whose bytes
// stay within the budget, the smallest accepted value when none does, refusals below a
// minimum skipped, and few measured frames.
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "algo/MemoryMatch.h"

namespace sl {
namespace {

/// A square map of `value`² texels at 4 bytes each, refused below `minimum`.
BytesAtValue squareMap(long long minimum, int* calls = nullptr) {
  return [=](long long value, std::string& problem) -> std::optional<std::uint64_t> {
    if (calls) ++*calls;
    if (value < minimum) {
      problem = "below the minimum " + std::to_string(minimum);
      return std::nullopt;
    }
    return std::uint64_t(value) * std::uint64_t(value) * 4u;
  };
}

TEST(MemoryMatch, LargestValueWithinTheBudget) {
  // uniform 2048² (16 MiB) against a knob 64..16384 step 64: exactly 2048 fits.
  MemoryMatchResult m = matchMemory(64, 16384, 64, 2048ull * 2048 * 4, squareMap(0));
  ASSERT_TRUE(m.ok()) << m.problem;
  EXPECT_EQ(m.value, 2048);
  EXPECT_EQ(m.bytes, 2048ull * 2048 * 4);
  EXPECT_FALSE(m.belowMinimum);
  // One byte less: the grid value below.
  m = matchMemory(64, 16384, 64, 2048ull * 2048 * 4 - 1, squareMap(0));
  EXPECT_EQ(m.value, 1984);
  EXPECT_LE(m.bytes, 2048ull * 2048 * 4 - 1);
}

TEST(MemoryMatch, EveryBudgetOverTheGridGivesTheExactAnswer) {
  for (std::uint64_t budget = 0; budget < 300ull * 300 * 4; budget += 9973) {
    const MemoryMatchResult m = matchMemory(10, 290, 7, budget, squareMap(0));
    ASSERT_TRUE(m.ok());
    // The brute-force answer: the largest grid value within the budget, else the smallest.
    long long want = 10;
    bool below = true;
    for (long long v = 10; v <= 290; v += 7)
      if (std::uint64_t(v * v * 4) <= budget) want = v, below = false;
    EXPECT_EQ(m.value, want) << "budget " << budget;
    EXPECT_EQ(m.belowMinimum, below) << "budget " << budget;
    EXPECT_EQ(m.bytes, std::uint64_t(m.value * m.value * 4));
  }
}

TEST(MemoryMatch, RefusedValuesBelowAMinimumAreSkipped) {
  // Like rmsm's pool, which refuses fewer pages than its coarsest level needs.
  MemoryMatchResult m = matchMemory(1, 4096, 1, 1000ull * 1000 * 4, squareMap(37));
  ASSERT_TRUE(m.ok()) << m.problem;
  EXPECT_EQ(m.value, 1000);
  // A budget under the minimum's bytes: the minimum, flagged.
  m = matchMemory(1, 4096, 1, 100, squareMap(37));
  ASSERT_TRUE(m.ok());
  EXPECT_EQ(m.value, 37);
  EXPECT_TRUE(m.belowMinimum);
  EXPECT_EQ(m.bytes, 37ull * 37 * 4);
}

TEST(MemoryMatch, NoAcceptedValueIsAProblemNamingTheRefusal) {
  const MemoryMatchResult m = matchMemory(1, 100, 1, 1u << 30, squareMap(1000));
  EXPECT_FALSE(m.ok());
  EXPECT_EQ(m.problem, "below the minimum 1000");
}

TEST(MemoryMatch, MeasuresLogarithmicallyManyFrames) {
  int calls = 0;
  const MemoryMatchResult m =
      matchMemory(1, 1 << 20, 1, 123456ull * 123456 * 4, squareMap(500, &calls));
  ASSERT_TRUE(m.ok());
  EXPECT_EQ(m.value, 123456);
  EXPECT_EQ(calls, m.evaluations);
  // Two doubling-then-bisecting searches over 2^20 values, and the final measurement.
  EXPECT_LE(m.evaluations, 4 * 20 + 1);
}

}  // namespace
}  // namespace sl
