// Shadow-mask comparison against the reference: exact counts on small masks, the empty
// case, size checks, and the colours of the error image.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "metrics/ErrorMetrics.h"

namespace sl {
namespace {

constexpr std::uint8_t L = kMaskLit, S = kMaskShadowed, U = kMaskUncovered;

TEST(ErrorMetrics, ExactCounts) {
  //                                  agree  agree  fLit  fShad fLit  uncov uncov
  const std::vector<std::uint8_t> technique{L, S, L, S, L, U, U, L, S, S};
  const std::vector<std::uint8_t> reference{L, S, S, L, S, U, U, L, S, L};
  const ShadowErrorStats s = compareShadowMasks(technique, reference);
  EXPECT_EQ(s.covered, 8u);
  EXPECT_EQ(s.falseLit, 2u);
  EXPECT_EQ(s.falseShadow, 2u);
  EXPECT_EQ(s.coverageMismatch, 0u);
  EXPECT_DOUBLE_EQ(s.errorPct, 50.0);
  EXPECT_DOUBLE_EQ(s.falseLitPct, 25.0);
  EXPECT_DOUBLE_EQ(s.falseShadowPct, 25.0);
}

TEST(ErrorMetrics, PerfectMatchIsZero) {
  const std::vector<std::uint8_t> mask{L, S, U, L};
  const ShadowErrorStats s = compareShadowMasks(mask, mask);
  EXPECT_EQ(s.covered, 3u);
  EXPECT_EQ(s.falseLit + s.falseShadow, 0u);
  EXPECT_EQ(s.errorPct, 0.0);
}

TEST(ErrorMetrics, ZeroCoveredGivesZeroNotNaN) {
  const std::vector<std::uint8_t> none{U, U, U};
  for (const ShadowErrorStats& s : {compareShadowMasks(none, none), compareShadowMasks({}, {})}) {
    EXPECT_EQ(s.covered, 0u);
    EXPECT_EQ(s.errorPct, 0.0);
    EXPECT_EQ(s.falseLitPct, 0.0);
    EXPECT_EQ(s.falseShadowPct, 0.0);
    EXPECT_FALSE(std::isnan(s.errorPct));
  }
}

TEST(ErrorMetrics, CoverageMismatchIsCountedButNotAnError) {
  const std::vector<std::uint8_t> technique{U, L, S};
  const std::vector<std::uint8_t> reference{L, U, S};
  const ShadowErrorStats s = compareShadowMasks(technique, reference);
  EXPECT_EQ(s.covered, 1u);
  EXPECT_EQ(s.coverageMismatch, 2u);
  EXPECT_EQ(s.errorPct, 0.0);
}

TEST(ErrorMetrics, OtherNonZeroValuesReadAsLit) {
  const std::vector<std::uint8_t> technique{7, 7};
  const std::vector<std::uint8_t> reference{L, S};
  const ShadowErrorStats s = compareShadowMasks(technique, reference);
  EXPECT_EQ(s.falseLit, 1u);
  EXPECT_EQ(s.falseShadow, 0u);
}

TEST(ErrorMetrics, SizeMismatchThrows) {
  const std::vector<std::uint8_t> a{L, S}, b{L, S, U};
  EXPECT_THROW(compareShadowMasks(a, b), std::invalid_argument);
}

TEST(ErrorMetrics, ErrorImageColours) {
  ImageRGBA8 shaded = makeImage(4, 1, {200, 100, 50, 255});
  shaded.pixel(3, 0)[0] = 17;  // the uncovered pixel must be copied unchanged
  const std::vector<std::uint8_t> technique{L, L, S, U};
  const std::vector<std::uint8_t> reference{L, S, L, U};
  const ImageRGBA8 e = makeErrorImage(shaded, technique, reference);
  ASSERT_EQ(e.width, 4);
  ASSERT_EQ(e.height, 1);
  // Agreeing pixel: grey, darker than the luma of the input.
  const std::uint8_t* ok = e.pixel(0, 0);
  EXPECT_EQ(ok[0], ok[1]);
  EXPECT_EQ(ok[1], ok[2]);
  const float luma = 0.2126f * 200 + 0.7152f * 100 + 0.0722f * 50;
  EXPECT_NEAR(ok[0], 0.5f * luma, 1.0f);
  EXPECT_EQ(ok[3], 255);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(e.pixel(1, 0)[i], kFalseLitColor[i]) << i;
    EXPECT_EQ(e.pixel(2, 0)[i], kFalseShadowColor[i]) << i;
    EXPECT_EQ(e.pixel(3, 0)[i], shaded.pixel(3, 0)[i]) << i;
  }
}

TEST(ErrorMetrics, ErrorImageSizeMismatchThrows) {
  const ImageRGBA8 shaded = makeImage(2, 2);
  const std::vector<std::uint8_t> four(4, L), three(3, L);
  EXPECT_THROW(makeErrorImage(shaded, four, three), std::invalid_argument);
  EXPECT_THROW(makeErrorImage(ImageRGBA8{}, {}, {}), std::invalid_argument);
  EXPECT_NO_THROW(makeErrorImage(shaded, four, four));
}

}  // namespace
}  // namespace sl
