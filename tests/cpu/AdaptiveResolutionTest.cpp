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

TEST(AdaptiveResolution, ASlowFrameDropsByWhatItNeeds) {
  sl::AdaptiveResolution a;
  EXPECT_TRUE(a.onFrame(610.0, 250.0));  // sqrt(2.44) = 1.56: half size
  EXPECT_EQ(a.divisor(), 2);
  EXPECT_EQ(a.dropFrameMs(), 610.0);
  sl::AdaptiveResolution b;
  EXPECT_TRUE(b.onFrame(2000.0, 250.0));  // sqrt(8) = 2.83: a quarter
  EXPECT_EQ(b.divisor(), 4);
  sl::AdaptiveResolution c;
  EXPECT_TRUE(c.onFrame(18000.0, 250.0));  // sqrt(72) = 8.5: capped at an eighth
  EXPECT_EQ(c.divisor(), 8);
  EXPECT_FALSE(c.onFrame(9000.0, 250.0));  // already at the cap
  EXPECT_EQ(c.divisor(), 8);
  EXPECT_EQ(c.dropFrameMs(), 18000.0);  // the frame that made the last drop
}

TEST(AdaptiveResolution, DropsFurtherFromAReducedSize) {
  sl::AdaptiveResolution a;
  ASSERT_TRUE(a.onFrame(400.0, 250.0));
  ASSERT_EQ(a.divisor(), 2);
  EXPECT_TRUE(a.onFrame(300.0, 250.0));  // still slow at half size: 2 x 1.1 -> 4
  EXPECT_EQ(a.divisor(), 4);
}

TEST(AdaptiveResolution, ClimbsBackOneStepWhenTheNextSizeUpWouldFit) {
  sl::AdaptiveResolution a;
  ASSERT_TRUE(a.onFrame(18000.0, 250.0));
  ASSERT_EQ(a.divisor(), 8);
  // 4 x 40 ms = 160 ms > 0.6 x 250 = 150 ms: stays.
  EXPECT_FALSE(a.onFrame(40.0, 250.0));
  EXPECT_EQ(a.divisor(), 8);
  EXPECT_TRUE(a.onFrame(37.0, 250.0));  // 148 ms < 150 ms: one step up
  EXPECT_EQ(a.divisor(), 4);
  EXPECT_TRUE(a.onFrame(10.0, 250.0));
  EXPECT_EQ(a.divisor(), 2);
  EXPECT_TRUE(a.onFrame(10.0, 250.0));
  EXPECT_EQ(a.divisor(), 1);
  EXPECT_FALSE(a.onFrame(1.0, 250.0));  // full size is the top
  EXPECT_EQ(a.divisor(), 1);
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
  EXPECT_EQ(sl::AdaptiveResolution::scaled(5, 8), 1);
  EXPECT_EQ(sl::AdaptiveResolution::scaled(100, 0), 100);
}

}  // namespace
