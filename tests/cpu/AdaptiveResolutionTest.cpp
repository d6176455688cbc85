// The view's adaptive internal resolution (algo/AdaptiveResolution): exact drops and climbs.
#include <gtest/gtest.h>

#include "algo/AdaptiveResolution.h"

namespace {

TEST(AdaptiveResolution, FastFramesStayAtFullSize) {
  sl::AdaptiveResolution a;
  EXPECT_FALSE(a.onFrame(100.0, 250.0));
  EXPECT_FALSE(a.onFrame(250.0, 250.0));  // exactly the budget: not slower
  EXPECT_EQ(a.divisor(), 1);
  EXPECT_EQ(a.dropFrameMs(), 0.0);
}

TEST(AdaptiveResolution, ASlowFrameDropsToHalfSizeAndNeverBelow) {
  // The floor is half the view's size, however slow the frame (a lecturer's picture stays
  // readable: the old floor of an eighth turned a 1280-px view into 160 px).
  for (double ms : {260.0, 610.0, 2000.0, 18000.0, 1e7}) {
    sl::AdaptiveResolution a;
    EXPECT_TRUE(a.onFrame(ms, 250.0)) << ms;
    EXPECT_EQ(a.divisor(), 2) << ms;
    EXPECT_EQ(a.dropFrameMs(), ms);
    EXPECT_FALSE(a.onFrame(ms, 250.0)) << ms;  // still slow: stays at the floor
    EXPECT_EQ(a.divisor(), 2) << ms;
  }
  EXPECT_EQ(sl::AdaptiveResolution::kMaxDivisor, 2);
}

TEST(AdaptiveResolution, TheFirstFrameThatWouldFitAtFullSizeReturnsToIt) {
  sl::AdaptiveResolution a;
  ASSERT_TRUE(a.onFrame(18000.0, 250.0));
  ASSERT_EQ(a.divisor(), 2);
  // 4 x 51 ms = 204 ms > 0.8 x 250 = 200 ms: stays.
  EXPECT_FALSE(a.onFrame(51.0, 250.0));
  EXPECT_EQ(a.divisor(), 2);
  EXPECT_TRUE(a.onFrame(49.0, 250.0));  // 196 ms < 200 ms: full size at once
  EXPECT_EQ(a.divisor(), 1);
  EXPECT_FALSE(a.onFrame(1.0, 250.0));  // full size is the top
  EXPECT_EQ(a.divisor(), 1);
  // Frames between the budget's share and the budget neither drop nor climb (hysteresis).
  sl::AdaptiveResolution b;
  ASSERT_TRUE(b.onFrame(300.0, 250.0));
  for (double ms : {55.0, 60.0, 62.4}) EXPECT_FALSE(b.onFrame(ms, 250.0)) << ms;
  EXPECT_EQ(b.divisor(), 2);
}

TEST(AdaptiveResolution, ResetAndBadInput) {
  sl::AdaptiveResolution a;
  ASSERT_TRUE(a.onFrame(1000.0, 250.0));
  EXPECT_FALSE(a.onFrame(-1.0, 250.0));
  EXPECT_FALSE(a.onFrame(1e9, 0.0));
  a.reset();
  EXPECT_EQ(a.divisor(), 1);
  EXPECT_EQ(a.dropFrameMs(), 0.0);
  EXPECT_EQ(sl::AdaptiveResolution::scaled(1279, 2), 639);
  EXPECT_EQ(sl::AdaptiveResolution::scaled(5, 8), 1);  // at least one pixel
  EXPECT_EQ(sl::AdaptiveResolution::scaled(100, 0), 100);
}

}  // namespace
