// Rectilinear Texture Warping CPU reference (seed 002, Rosen 2012): importance terms,
// scatter, collapse, blur, floor, prefix sums, warp maps and the seed's memory figure.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "algo/rtw/Importance.h"
#include "algo/rtw/Warp.h"

namespace sl::rtw {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// ---------------------------------------------------------------------------------------
// Importance terms

TEST(RtwImportance, EyeDepthTermIsNearOverDepth) {
  EXPECT_FLOAT_EQ(eyeDepthTerm(5.0f, 0.1f), 0.02f);
  EXPECT_FLOAT_EQ(eyeDepthTerm(0.2f, 0.1f), 0.5f);
  EXPECT_EQ(eyeDepthTerm(0.1f, 0.1f), 1.0f);   // at the near plane
  EXPECT_EQ(eyeDepthTerm(0.05f, 0.1f), 1.0f);  // in front of it
  EXPECT_EQ(eyeDepthTerm(kNaN, 0.1f), 1.0f);
  EXPECT_EQ(eyeDepthTerm(kInf, 0.1f), 0.0f);
  EXPECT_EQ(eyeDepthTerm(5.0f, 0.0f), 1.0f);  // invalid near plane: neutral
  EXPECT_EQ(eyeDepthTerm(5.0f, kNaN), 1.0f);
  // Importance grows as the eye depth shrinks.
  EXPECT_GT(eyeDepthTerm(1.0f, 0.1f), eyeDepthTerm(2.0f, 0.1f));
}

TEST(RtwImportance, OrientationTermIsCosEyeOverCosLight) {
  EXPECT_FLOAT_EQ(orientationTerm(1.0f, 1.0f, 0.1f), 1.0f);
  EXPECT_FLOAT_EQ(orientationTerm(0.5f, 0.5f, 0.1f), 1.0f);   // θ_i = θ_l: no aliasing
  EXPECT_FLOAT_EQ(orientationTerm(-0.5f, 0.5f, 0.1f), 1.0f);  // lit from behind: |n·L|
  EXPECT_FLOAT_EQ(orientationTerm(0.25f, 1.0f, 0.1f), 4.0f);
  EXPECT_FLOAT_EQ(orientationTerm(0.0f, 1.0f, 0.1f), 10.0f);   // grazing light: 1/minCosL
  EXPECT_FLOAT_EQ(orientationTerm(0.0f, 1.0f, 0.0f), 100.0f);  // minCosL clamped to 0.01
  EXPECT_EQ(orientationTerm(1.0f, -0.3f, 0.1f), 0.0f);         // faces away from the eye
  EXPECT_FLOAT_EQ(orientationTerm(kNaN, 1.0f, 0.1f), 10.0f);
  EXPECT_EQ(orientationTerm(1.0f, kNaN, 0.1f), 0.0f);
  EXPECT_FLOAT_EQ(orientationTerm(1.0f, 1.5f, 0.1f), 1.0f);  // nDotV clamped to 1
}

TEST(RtwImportance, ShadowEdgeTermClamps) {
  EXPECT_EQ(shadowEdgeTerm(0.5f), 0.5f);
  EXPECT_EQ(shadowEdgeTerm(2.0f), 1.0f);
  EXPECT_EQ(shadowEdgeTerm(-1.0f), 0.0f);
  EXPECT_EQ(shadowEdgeTerm(kNaN), 0.0f);
}

TEST(RtwImportance, CombineMultipliesEnabledTerms) {
  ImportanceSettings s;  // defaults: eye only, weight 1, near 0.1
  EXPECT_FLOAT_EQ(combineImportance(s, 2.0f, 0.2f, 0.8f, 1.0f), 0.05f);

  ImportanceSettings off;
  off.eyeOn = false;
  EXPECT_EQ(combineImportance(off, 2.0f, 0.2f, 0.8f, 1.0f), 1.0f);

  ImportanceSettings all;
  all.orientationOn = true;
  all.edgeOn = true;  // edgeWeight 4: an edge texel gets 5x
  // e = 0.05, o = 0.8 / 0.2 = 4, s = 1 + 4 * 1 = 5
  EXPECT_FLOAT_EQ(combineImportance(all, 2.0f, 0.2f, 0.8f, 1.0f), 0.05f * 4.0f * 5.0f);
  EXPECT_FLOAT_EQ(combineImportance(all, 2.0f, 0.2f, 0.8f, 0.0f), 0.05f * 4.0f);

  ImportanceSettings half;
  half.eyeWeight = 0.5f;  // halfway between neutral (1) and the full term (0.05)
  EXPECT_FLOAT_EQ(combineImportance(half, 2.0f, 0.0f, 0.0f, 0.0f), 0.525f);

  ImportanceSettings wild;
  wild.eyeWeight = 7.0f;  // clamped to 1
  wild.orientationOn = true;
  wild.orientationWeight = -3.0f;  // clamped to 0: neutral
  wild.edgeOn = true;
  wild.edgeWeight = kNaN;  // -> 0: neutral
  EXPECT_FLOAT_EQ(combineImportance(wild, 2.0f, 0.2f, 0.8f, 1.0f), 0.05f);
  EXPECT_GE(combineImportance(all, 2.0f, 0.2f, -1.0f, 1.0f), 0.0f);  // never negative
}

// ---------------------------------------------------------------------------------------
// Scatter and collapse

TEST(RtwScatter, TexelOfLightUvFloorsAndRejectsOutside) {
  glm::ivec2 t(-1);
  ASSERT_TRUE(texelOfLightUv(4, 2, {0.0f, 0.0f}, t));
  EXPECT_EQ(t, glm::ivec2(0, 0));
  ASSERT_TRUE(texelOfLightUv(4, 2, {0.2499f, 0.5f}, t));
  EXPECT_EQ(t, glm::ivec2(0, 1));
  ASSERT_TRUE(texelOfLightUv(4, 2, {0.25f, 0.4999f}, t));
  EXPECT_EQ(t, glm::ivec2(1, 0));
  ASSERT_TRUE(texelOfLightUv(4, 2, {0.9999f, 0.9999f}, t));
  EXPECT_EQ(t, glm::ivec2(3, 1));
  EXPECT_FALSE(texelOfLightUv(4, 2, {1.0f, 0.5f}, t));  // u = 1 is outside
  EXPECT_FALSE(texelOfLightUv(4, 2, {-0.001f, 0.5f}, t));
  EXPECT_FALSE(texelOfLightUv(4, 2, {0.5f, 1.2f}, t));
  EXPECT_FALSE(texelOfLightUv(4, 2, {kNaN, 0.5f}, t));
  EXPECT_FALSE(texelOfLightUv(4, 2, {0.5f, kInf}, t));
}

TEST(RtwScatter, ScatterMaxKeepsTheMaximumAndDropsInvalidValues) {
  ImportanceMap im(4, 2);
  scatterMax(im, {0.6f, 0.7f}, 2.0f);  // texel (2, 1)
  scatterMax(im, {0.6f, 0.7f}, 1.0f);
  scatterMax(im, {0.7f, 0.9f}, 3.0f);  // same texel
  EXPECT_EQ(im.at(2, 1), 3.0f);
  scatterMax(im, {0.1f, 0.1f}, -1.0f);
  scatterMax(im, {0.1f, 0.1f}, -0.0f);
  scatterMax(im, {0.1f, 0.1f}, kNaN);
  scatterMax(im, {0.1f, 0.1f}, kInf);
  scatterMax(im, {1.5f, 0.1f}, 9.0f);
  EXPECT_EQ(im.at(0, 0), 0.0f);
  float sum = 0.0f;
  for (float v : im.values) sum += v;
  EXPECT_EQ(sum, 3.0f);
}

// The GPU scatters with imageAtomicMax on floatBitsToUint: valid for finite floats >= +0.
TEST(RtwScatter, UintBitsOfNonNegativeFloatsAreOrderedLikeTheFloats) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> mag(-40.0f, 40.0f);
  std::vector<float> v = {0.0f, std::numeric_limits<float>::denorm_min(),
                          std::numeric_limits<float>::min(), 1.0f,
                          std::numeric_limits<float>::max()};
  for (int i = 0; i < 2000; ++i) v.push_back(std::exp2(mag(rng)));
  for (size_t i = 0; i + 1 < v.size(); ++i) {
    float a = v[i], b = v[i + 1];
    EXPECT_EQ(a < b, std::bit_cast<std::uint32_t>(a) < std::bit_cast<std::uint32_t>(b));
  }
  // -0.0 is why the scatter must drop values that are not > 0.
  EXPECT_GT(std::bit_cast<std::uint32_t>(-0.0f), std::bit_cast<std::uint32_t>(1.0f));
}

TEST(RtwCollapse, ColumnsAndRowsMax) {
  ImportanceMap im(3, 2);
  im.values = {1, 5, 0,   // row 0 (v = 0, bottom)
               4, 2, 3};  // row 1
  EXPECT_EQ(collapseColumnsMax(im), (std::vector<float>{4, 5, 3}));
  EXPECT_EQ(collapseRowsMax(im), (std::vector<float>{5, 4}));
  EXPECT_TRUE(collapseColumnsMax(ImportanceMap()).empty());
  EXPECT_TRUE(collapseRowsMax(ImportanceMap(0, 5)).empty());
}

TEST(RtwCollapse, NonPowerOfTwoSizes) {
  ImportanceMap im(13, 7);
  for (int y = 0; y < 7; ++y)
    for (int x = 0; x < 13; ++x) im.at(x, y) = static_cast<float>((x * 3 + y * 5) % 11);
  std::vector<float> cx = collapseColumnsMax(im), cy = collapseRowsMax(im);
  ASSERT_EQ(cx.size(), 13u);
  ASSERT_EQ(cy.size(), 7u);
  for (int x = 0; x < 13; ++x) {
    float m = 0;
    for (int y = 0; y < 7; ++y) m = std::max(m, im.at(x, y));
    EXPECT_EQ(cx[x], m);
  }
  for (int y = 0; y < 7; ++y) EXPECT_EQ(cy[y], 10.0f);  // every row of 13 hits 10 (mod 11)
}

// ---------------------------------------------------------------------------------------
// Blur

TEST(RtwBlur, GaussianWeightsAreNormalised) {
  std::vector<float> w = gaussianWeights(1, 1.0f);
  ASSERT_EQ(w.size(), 3u);
  double e = std::exp(-0.5), sum = 1.0 + 2.0 * e;
  EXPECT_NEAR(w[0], e / sum, 1e-7);    // 0.274068...
  EXPECT_NEAR(w[1], 1.0 / sum, 1e-7);  // 0.451862...
  EXPECT_EQ(w[0], w[2]);
  for (int r : {0, 1, 2, 5, 13, kMaxBlurRadius, kMaxBlurRadius + 10}) {
    std::vector<float> ww = gaussianWeights(r, 2.5f);
    EXPECT_EQ(ww.size(), static_cast<size_t>(2 * std::min(r, kMaxBlurRadius) + 1));
    double s = 0;
    for (float x : ww) s += x;
    EXPECT_NEAR(s, 1.0, 1e-6) << r;
  }
  EXPECT_EQ(gaussianWeights(3, 0.0f), std::vector<float>{1.0f});
  EXPECT_EQ(gaussianWeights(3, -1.0f), std::vector<float>{1.0f});
  EXPECT_EQ(gaussianWeights(3, kNaN), std::vector<float>{1.0f});
  EXPECT_EQ(gaussianWeights(-2, 1.0f), std::vector<float>{1.0f});
}

TEST(RtwBlur, ImpulseAndClampToEdge) {
  std::vector<float> w = gaussianWeights(1, 1.0f);
  std::vector<float> impulse = {0, 0, 1, 0, 0};
  std::vector<float> out = gaussianBlur1D(impulse, 1, 1.0f);
  EXPECT_EQ(out, (std::vector<float>{0, w[0], w[1], w[2], 0}));
  // Clamp-to-edge: texel -1 reads texel 0.
  std::vector<float> edge = {1, 0, 0};
  out = gaussianBlur1D(edge, 1, 1.0f);
  EXPECT_FLOAT_EQ(out[0], w[0] + w[1]);
  EXPECT_FLOAT_EQ(out[1], w[0]);
  EXPECT_EQ(out[2], 0.0f);
  // Radius larger than the map: every tap clamps, a constant stays constant.
  std::vector<float> c(7, 2.0f);
  for (float v : gaussianBlur1D(c, 20, 5.0f)) EXPECT_NEAR(v, 2.0f, 2e-6f);
  EXPECT_EQ(gaussianBlur1D(impulse, 0, 1.0f), impulse);  // radius 0: identity
  EXPECT_TRUE(gaussianBlur1D(std::vector<float>{}, 3, 1.0f).empty());
  std::vector<float> one = {3.0f};
  EXPECT_NEAR(gaussianBlur1D(one, 3, 1.0f)[0], 3.0f, 1e-6f);
}

TEST(RtwBlur, MatchesTheWrittenDefinitionOnOddSizes) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> d(0.0f, 10.0f);
  for (int n : {7, 13, 100}) {
    std::vector<float> in(n);
    for (float& x : in) x = d(rng);
    int r = 3;
    std::vector<float> w = gaussianWeights(r, 1.7f), out = gaussianBlur1D(in, r, 1.7f);
    for (int i = 0; i < n; ++i) {
      float acc = 0.0f;
      for (int k = -r; k <= r; ++k) acc += w[k + r] * in[std::clamp(i + k, 0, n - 1)];
      EXPECT_EQ(out[i], acc) << n << " " << i;
    }
  }
}

// ---------------------------------------------------------------------------------------
// Floor

TEST(RtwFloor, RaisesToAFractionOfTheMax) {
  std::vector<float> v = {0, 2, 4, 1, 0.5f};
  applyImportanceFloor(v, 0.25f);
  EXPECT_EQ(v, (std::vector<float>{1, 2, 4, 1, 1}));
  std::vector<float> u = {0, 2, 4};
  applyImportanceFloor(u, 0.0f);
  EXPECT_EQ(u, (std::vector<float>{0, 2, 4}));
  applyImportanceFloor(u, kNaN);
  EXPECT_EQ(u, (std::vector<float>{0, 2, 4}));
  applyImportanceFloor(u, 3.0f);  // clamped to 1: everything becomes the max
  EXPECT_EQ(u, (std::vector<float>{4, 4, 4}));
}

TEST(RtwFloor, AllZeroBecomesUniform) {
  for (int n : {1, 7, 13, 100}) {
    std::vector<float> v(n, 0.0f);
    applyImportanceFloor(v, 0.05f);
    for (float x : v) EXPECT_EQ(x, 1.0f);
  }
  std::vector<float> empty;
  applyImportanceFloor(empty, 0.05f);  // no crash
}

// ---------------------------------------------------------------------------------------
// Prefix sums

TEST(RtwScan, ExactOnIntegersForOddSizes) {
  for (int n : {1, 2, 3, 7, 8, 13, 100, 512, 513}) {
    std::vector<float> in(n);
    for (int i = 0; i < n; ++i) in[i] = static_cast<float>(i % 5 + 1);
    std::vector<float> seq = inclusiveScan(in), ble = blellochScan(in);
    ASSERT_EQ(seq.size(), static_cast<size_t>(n));
    ASSERT_EQ(ble.size(), static_cast<size_t>(n));
    float expect = 0;
    for (int i = 0; i < n; ++i) {
      expect += in[i];
      EXPECT_EQ(seq[i], expect) << n << " " << i;
      EXPECT_EQ(ble[i], expect) << n << " " << i;
    }
  }
  std::vector<float> seven = {1, 2, 3, 4, 5, 6, 7};
  EXPECT_EQ(blellochScan(seven), (std::vector<float>{1, 3, 6, 10, 15, 21, 28}));
  EXPECT_TRUE(blellochScan(std::vector<float>{}).empty());
  EXPECT_TRUE(inclusiveScan(std::vector<float>{}).empty());
}

// The tree order is observable in float: 2^24 + 1 + 1 rounds twice sequentially, once
// ((2^24 + 0) + (1 + 1)) in the up-sweep. The GPU must reproduce the tree, not the loop.
TEST(RtwScan, BlellochFollowsTheTreeOrder) {
  std::vector<float> in = {16777216.0f, 0.0f, 1.0f, 1.0f};
  EXPECT_EQ(inclusiveScan(in)[3], 16777216.0f);
  EXPECT_EQ(blellochScan(in)[3], 16777218.0f);
  // Padding with zeros does not change the values (n = 3 padded to 4).
  std::vector<float> three = {16777216.0f, 0.0f, 1.0f};
  EXPECT_EQ(blellochScan(three), (std::vector<float>{16777216.0f, 16777216.0f, 16777216.0f}));
}

TEST(RtwScan, BlellochMatchesSequentialWithin1e5Relative) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<float> d(0.0f, 1.0f);
  for (int n : {1, 5, 7, 13, 100, 255, 256, 257, 1000, 1024, 2049}) {
    std::vector<float> in(n);
    for (float& x : in) x = d(rng) * d(rng) * 100.0f;
    std::vector<float> seq = inclusiveScan(in), ble = blellochScan(in);
    double exact = 0;
    for (int i = 0; i < n; ++i) {
      exact += in[i];
      double tol = 1e-5 * exact + 1e-30;
      EXPECT_NEAR(ble[i], seq[i], tol) << n << " " << i;
      EXPECT_NEAR(ble[i], exact, tol) << n << " " << i;
    }
  }
}

// ---------------------------------------------------------------------------------------
// Warp maps

TEST(RtwWarp, HandCheckedEdges) {
  std::vector<float> uniform = {1, 1, 1, 1};
  EXPECT_EQ(warpFromImportance(uniform), (std::vector<float>{0, 0, 0, 0, 0}));

  std::vector<float> two = {3, 1};  // edges: 0, 3/4 - 1/2, 0
  EXPECT_EQ(warpFromImportance(two), (std::vector<float>{0, 0.25f, 0}));

  // 1..7, T = 28: warp[e] = S_e / 28 - e / 7 = -3, -5, -6, -6, -5, -3 (/28).
  std::vector<float> ramp = {1, 2, 3, 4, 5, 6, 7};
  std::vector<float> w = warpFromImportance(ramp);
  std::vector<float> expect = {0, -3, -5, -6, -6, -5, -3, 0};
  ASSERT_EQ(w.size(), 8u);
  for (size_t e = 0; e < w.size(); ++e) EXPECT_NEAR(w[e], expect[e] / 28.0f, 1e-7f) << e;
  EXPECT_EQ(w.front(), 0.0f);
  EXPECT_EQ(w.back(), 0.0f);

  EXPECT_EQ(warpFromImportance(std::vector<float>{}), std::vector<float>{0.0f});
  EXPECT_EQ(warpFromImportance(std::vector<float>{5.0f}), (std::vector<float>{0, 0}));
}

TEST(RtwWarp, WarpCoordinateInterpolatesBetweenEdges) {
  std::vector<float> w = warpFromImportance(std::vector<float>{3, 1});
  // u' is the CDF: texel 0 (3/4 of the importance) gets [0, 0.75).
  EXPECT_FLOAT_EQ(warpCoordinate(w, 0.25f), 0.375f);
  EXPECT_FLOAT_EQ(warpCoordinate(w, 0.5f), 0.75f);
  EXPECT_FLOAT_EQ(warpCoordinate(w, 0.75f), 0.875f);
  // Identity outside (0, 1), and continuous at the ends.
  EXPECT_EQ(warpCoordinate(w, 0.0f), 0.0f);
  EXPECT_EQ(warpCoordinate(w, 1.0f), 1.0f);
  EXPECT_EQ(warpCoordinate(w, -0.5f), -0.5f);
  EXPECT_EQ(warpCoordinate(w, 1.5f), 1.5f);
  EXPECT_NEAR(warpCoordinate(w, 1e-6f), 1.5e-6f, 1e-9f);
  EXPECT_NEAR(warpCoordinate(w, 1.0f - 1e-6f), 1.0f - 0.5e-6f, 1e-7f);
  EXPECT_TRUE(std::isnan(warpCoordinate(w, kNaN)));
  // The inverse.
  EXPECT_FLOAT_EQ(unwarpCoordinate(w, 0.375f), 0.25f);
  EXPECT_FLOAT_EQ(unwarpCoordinate(w, 0.75f), 0.5f);
  EXPECT_FLOAT_EQ(unwarpCoordinate(w, 0.875f), 0.75f);
  EXPECT_EQ(unwarpCoordinate(w, -0.25f), -0.25f);
  // A flat part (zero importance in texels 1 and 2) maps back to its first edge.
  std::vector<float> gap = warpFromImportance(std::vector<float>{1, 0, 0, 1});
  EXPECT_FLOAT_EQ(warpCoordinate(gap, 0.25f), 0.5f);
  EXPECT_FLOAT_EQ(warpCoordinate(gap, 0.5f), 0.5f);
  EXPECT_FLOAT_EQ(warpCoordinate(gap, 0.75f), 0.5f);
  EXPECT_FLOAT_EQ(unwarpCoordinate(gap, 0.5f), 0.25f);
  EXPECT_FLOAT_EQ(unwarpCoordinate(gap, 0.625f), 0.8125f);
}

TEST(RtwWarp, AllZeroImportanceIsTheIdentity) {
  for (int n : {1, 7, 13, 100, 512}) {
    std::vector<float> zero(n, 0.0f);
    std::vector<float> raw = warpFromImportance(zero);
    WarpSettings s;
    std::vector<float> built = buildWarpMap(zero, s);
    ASSERT_EQ(raw.size(), static_cast<size_t>(n + 1));
    ASSERT_EQ(built.size(), static_cast<size_t>(n + 1));
    for (int e = 0; e <= n; ++e) {
      EXPECT_EQ(raw[e], 0.0f);
      EXPECT_NEAR(built[e], 0.0f, 1e-7f);
    }
    for (float u : {0.1f, 0.33f, 0.5f, 0.9f}) EXPECT_NEAR(warpCoordinate(built, u), u, 1e-7f);
  }
  ImportanceMap im(13, 7);
  WarpMaps maps = buildWarpMaps(im, WarpSettings{});
  glm::vec2 uv = warpUv(maps, {0.3f, 0.8f});
  EXPECT_NEAR(uv.x, 0.3f, 1e-7f);
  EXPECT_NEAR(uv.y, 0.8f, 1e-7f);
}

// Float rounding may break monotonicity by an ulp or two; the property is checked to 1e-6.
constexpr float kMonotoneTol = 1e-6f;

void expectWarpProperties(const std::vector<float>& imp, const std::vector<float>& w,
                          const char* what) {
  size_t n = imp.size();
  ASSERT_EQ(w.size(), n + 1) << what;
  EXPECT_EQ(w.front(), 0.0f) << what << " n=" << n;
  EXPECT_EQ(w.back(), 0.0f) << what << " n=" << n;
  double total = 0;
  for (float x : imp) total += x;
  // Edge coordinates are the CDF: non-decreasing, texel k's warped width = I_k / T.
  double s = 0;
  for (size_t e = 0; e + 1 <= n; ++e) {
    float ce = static_cast<float>(e) / static_cast<float>(n) + w[e];
    float cn = static_cast<float>(e + 1) / static_cast<float>(n) + w[e + 1];
    EXPECT_GE(cn, ce - kMonotoneTol) << what << " n=" << n << " e=" << e;
    s += imp[e];
    if (total > 0) {
      EXPECT_NEAR(cn, s / total, 2e-6) << what << " n=" << n << " e=" << e;
    }
  }
  // Dense samples of u' = u + warp(u): non-decreasing, inside [0, 1].
  float prev = 0.0f;
  for (int j = 0; j <= 4096; ++j) {
    float u = static_cast<float>(j) / 4096.0f;
    float up = warpCoordinate(w, u);
    EXPECT_GE(up, prev - kMonotoneTol) << what << " n=" << n << " u=" << u;
    EXPECT_GE(up, -kMonotoneTol);
    EXPECT_LE(up, 1.0f + kMonotoneTol);
    prev = up;
    // The inverse undoes it (u' -> some u with the same u').
    float back = unwarpCoordinate(w, up);
    EXPECT_NEAR(warpCoordinate(w, back), up, 2e-6f) << what << " n=" << n << " u=" << u;
  }
}

TEST(RtwWarp, MonotonicAndZeroAtBothEndsForRandomImportance) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<float> d(0.0f, 1.0f);
  for (int n : {1, 2, 3, 5, 7, 13, 31, 64, 100, 128, 257, 512, 1000}) {
    for (int trial = 0; trial < 4; ++trial) {
      std::vector<float> imp(n);
      for (float& x : imp) {
        float r = d(rng);
        x = r < 0.4f ? 0.0f : std::exp2(40.0f * d(rng) - 20.0f);  // zeros and a huge range
      }
      expectWarpProperties(imp, warpFromImportance(imp), "raw");
      WarpSettings s;
      std::vector<float> v = gaussianBlur1D(imp, s.blurRadius, s.blurSigma);
      applyImportanceFloor(v, s.importanceFloor);
      expectWarpProperties(v, buildWarpMap(imp, s), "built");
    }
  }
}

TEST(RtwWarp, FloorGuaranteesEveryTexelASliceAndImportantTexelsMore) {
  std::vector<float> imp(100, 0.0f);
  imp[10] = 1.0f;
  WarpSettings s;
  s.blurRadius = 0;
  s.importanceFloor = 0.05f;
  std::vector<float> w = buildWarpMap(imp, s);
  // After the floor: one texel 1, 99 texels 0.05; T = 5.95.
  auto width = [&](int k) {
    return (static_cast<float>(k + 1) / 100.0f + w[k + 1]) -
           (static_cast<float>(k) / 100.0f + w[k]);
  };
  EXPECT_NEAR(width(10), 1.0f / 5.95f, 1e-6f);
  EXPECT_NEAR(width(50), 0.05f / 5.95f, 1e-6f);
  EXPECT_GT(width(10), 0.01f * 10.0f);  // > 10x its unwarped width
}

TEST(RtwWarp, BuildWarpMapsUsesColumnsForXAndRowsForY) {
  ImportanceMap im(13, 7);
  im.at(2, 5) = 1.0f;  // a single bright texel near the left and the top
  WarpSettings s;
  WarpMaps m = buildWarpMaps(im, s);
  ASSERT_EQ(m.x.size(), 14u);
  ASSERT_EQ(m.y.size(), 8u);
  // Texel 2 of x and texel 5 of y get more than their share of the warped axis.
  EXPECT_GT((3.0f / 13 + m.x[3]) - (2.0f / 13 + m.x[2]), 1.0f / 13);
  EXPECT_GT((6.0f / 7 + m.y[6]) - (5.0f / 7 + m.y[5]), 1.0f / 7);
  glm::vec2 uv(0.4f, 0.6f), back = unwarpUv(m, warpUv(m, uv));
  EXPECT_NEAR(back.x, uv.x, 1e-5f);
  EXPECT_NEAR(back.y, uv.y, 1e-5f);
}

// ---------------------------------------------------------------------------------------
// Memory (seed 002)

TEST(RtwMemory, SeedFigures) {
  EXPECT_EQ(rtwTexels(512, 512, 3), 525824);  // 512² SM + 512² IM + three 1D maps of 512
  EXPECT_EQ(rtwTexels(1024, 0, 0), 1048576);  // the uniform 1024² it is compared with
  EXPECT_EQ(rtwTexels(16384, 16384, 3), std::int64_t{2} * 16384 * 16384 + 3 * 16384);
  EXPECT_EQ(rtwTexels(-1, -1, -1), 0);
}

}  // namespace
}  // namespace sl::rtw
