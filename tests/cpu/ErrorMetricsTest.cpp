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

TEST(ErrorMetrics, SplitByDistanceHalvesTheCoveredPixels) {
  // Six covered pixels at 1..6 m from the eye (one uncovered): the lower median is 3 m, so
  // 1, 2, 3 m are near and 4, 5, 6 m far. Wrong: the pixel at 2 m (false lit) and those at
  // 5 and 6 m (false shadowed).
  const glm::vec3 eye(1.0f, 2.0f, 3.0f);
  std::vector<glm::vec4> positions;
  for (float d : {4.0f, 1.0f, 6.0f, 0.0f, 2.0f, 5.0f, 3.0f})
    positions.push_back(glm::vec4(eye + glm::vec3(0.0f, 0.0f, -d), d > 0.0f ? 1.0f : 0.0f));
  //                                  4 m  1 m  6 m  none 2 m  5 m  3 m
  const std::vector<std::uint8_t> technique{L, S, S, U, L, S, L};
  const std::vector<std::uint8_t> reference{L, S, L, U, S, L, L};
  const DistanceSplitError s = splitErrorByDistance(technique, reference, positions, eye);
  EXPECT_DOUBLE_EQ(s.medianDistanceM, 3.0);
  EXPECT_EQ(s.nearCovered, 3u);
  EXPECT_EQ(s.farCovered, 3u);
  EXPECT_EQ(s.nearWrong, 1u);
  EXPECT_EQ(s.farWrong, 2u);
  EXPECT_DOUBLE_EQ(s.nearErrorPct, 100.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.farErrorPct, 200.0 / 3.0);
  // The whole frame's error is the two halves' together.
  const ShadowErrorStats all = compareShadowMasks(technique, reference);
  EXPECT_EQ(all.falseLit + all.falseShadow, s.nearWrong + s.farWrong);
  EXPECT_EQ(all.covered, s.nearCovered + s.farCovered);
}

TEST(ErrorMetrics, SplitByDistanceOfNothingIsZeroAndSizesMustMatch) {
  const std::vector<std::uint8_t> none{U, U};
  const std::vector<glm::vec4> positions(2, glm::vec4(0.0f));
  const DistanceSplitError s = splitErrorByDistance(none, none, positions, glm::vec3(0.0f));
  EXPECT_EQ(s.nearCovered + s.farCovered, 0u);
  EXPECT_EQ(s.nearErrorPct, 0.0);
  EXPECT_EQ(s.farErrorPct, 0.0);
  const std::vector<glm::vec4> one(1, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  EXPECT_THROW(splitErrorByDistance(none, none, one, glm::vec3(0.0f)), std::invalid_argument);
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

TEST(ErrorMetrics, ErrorImageDilatedForPrint) {
  // 7x5, all lit and covered but one uncovered pixel; one false-lit pixel at (1, 1), one
  // false-shadow pixel at (4, 2). Dilated by 1: each a 3x3 square; every other pixel as in
  // the undilated image (the uncovered one as shaded).
  const int w = 7, h = 5;
  const ImageRGBA8 shaded = makeImage(w, h, {200, 100, 50, 255});
  std::vector<std::uint8_t> technique(w * h, L), reference(w * h, L);
  technique[1 * w + 1] = L, reference[1 * w + 1] = S;  // false lit
  technique[2 * w + 4] = S;                            // false shadow
  technique[0 * w + 5] = U;                            // uncovered: stays as shaded
  const ImageRGBA8 thin = makeErrorImage(shaded, technique, reference, 0);
  const ImageRGBA8 same = makeErrorImage(shaded, technique, reference);
  EXPECT_EQ(thin.pixels, same.pixels);
  const ImageRGBA8 e = makeErrorImage(shaded, technique, reference, 1);
  auto is = [&](int x, int y, const Rgba8& c) {
    return std::equal(c.begin(), c.end(), e.pixel(x, y));
  };
  int lit = 0, shadow = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool inLit = x <= 2 && y <= 2;
      const bool inShadow = x >= 3 && x <= 5 && y >= 1 && y <= 3;
      lit += is(x, y, kFalseLitColor);
      shadow += is(x, y, kFalseShadowColor);
      if (inLit)
        EXPECT_TRUE(is(x, y, kFalseLitColor)) << x << ", " << y;
      else if (inShadow)
        EXPECT_TRUE(is(x, y, kFalseShadowColor)) << x << ", " << y;
      else
        EXPECT_TRUE(std::equal(thin.pixel(x, y), thin.pixel(x, y) + 4, e.pixel(x, y)))
            << x << ", " << y;
    }
  EXPECT_EQ(lit, 9);
  EXPECT_EQ(shadow, 9);
  EXPECT_EQ(e.pixel(5, 0)[0], shaded.pixel(5, 0)[0]);  // uncovered: unchanged
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
