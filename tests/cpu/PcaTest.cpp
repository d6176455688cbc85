// Directionality-aware RTW (seed 000): the moment mip chain, the PCA of the importance
// map, and the image-plane rotation loop with its vibration threshold.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include <glm/glm.hpp>

#include "algo/Focus.h"
#include "algo/rtw/Importance.h"
#include "algo/rtw/Moments.h"
#include "algo/rtw/Rotation.h"

namespace sl::rtw {
namespace {

constexpr double kPi = std::numbers::pi;
double rad(double deg) {
  return deg * kPi / 180.0;
}

/// Fills an IM from a function of the centred texel-centre coordinates.
ImportanceMap rasterise(int w, int h, const std::function<float(glm::vec2)>& f) {
  ImportanceMap im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      im.at(x, y) = f(glm::vec2(centredCoordinate(x, w), centredCoordinate(y, h)));
  return im;
}

/// A thin line through `centre` at `deg`, |along| <= halfLength, with a 1.5-texel tent
/// profile across it (texel size of a w-texel axis is 2 / w in centred units).
std::function<float(glm::vec2)> line(double deg, glm::vec2 centre, float halfLength, int w) {
  glm::vec2 d(static_cast<float>(std::cos(rad(deg))), static_cast<float>(std::sin(rad(deg))));
  float halfWidth = 1.5f * 2.0f / static_cast<float>(w);
  return [=](glm::vec2 p) {
    glm::vec2 q = p - centre;
    float along = glm::dot(q, d), across = std::fabs(-d.y * q.x + d.x * q.y);
    if (std::fabs(along) > halfLength) return 0.0f;
    return std::max(0.0f, 1.0f - across / halfWidth);
  };
}

/// Angle difference modulo 180 degrees, in [0, 90].
double axisDiffDeg(double a, double b) {
  double d = std::fmod(std::fabs(a - b), 180.0);
  return std::min(d, 180.0 - d);
}

void expectNoNaN(const MomentStats& s) {
  for (float v : {s.sumI, s.meanX, s.meanY, s.alpha, s.beta, s.gamma, s.covXX, s.covXY, s.covYY,
                  s.lambda1, s.lambda2, s.anisotropy, s.ex, s.ey, s.angleDeg})
    EXPECT_FALSE(std::isnan(v));
}

// ---------------------------------------------------------------------------------------
// Moment textures and the chain of sums

TEST(RtwMoments, CentredCoordinatesAtTexelCentres) {
  EXPECT_EQ(centredCoordinate(0, 4), -0.75f);
  EXPECT_EQ(centredCoordinate(1, 4), -0.25f);
  EXPECT_EQ(centredCoordinate(2, 4), 0.25f);
  EXPECT_EQ(centredCoordinate(3, 4), 0.75f);
  EXPECT_EQ(centredCoordinate(0, 1), 0.0f);
  EXPECT_EQ(centredCoordinate(1, 3), 0.0f);
  EXPECT_FLOAT_EQ(centredCoordinate(2, 3), 2.0f / 3.0f);
  EXPECT_EQ(centredCoordinate(0, 7), -centredCoordinate(6, 7));  // symmetric, exactly
  for (int w : {1, 7, 13, 100, 512})
    for (int i = 0; i < w; ++i)
      EXPECT_NEAR(centredCoordinate(i, w), (i + 0.5) / w * 2.0 - 1.0, 1e-7) << w << " " << i;
}

TEST(RtwMoments, Level0Channels) {
  ImportanceMap im(2, 1);
  im.values = {1.0f, 3.0f};  // x = -0.5, 0.5; y = 0
  MomentLevel l = momentTextures(im);
  EXPECT_EQ(l.at(0, 0), (MomentTexel{1.0f, -0.5f, 0.0f, 0.25f, 0.0f, -0.0f}));
  EXPECT_EQ(l.at(1, 0), (MomentTexel{3.0f, 1.5f, 0.0f, 0.75f, 0.0f, 0.0f}));
}

TEST(RtwMoments, ReductionSumsUpToFourTexelsWithCeilSizes) {
  MomentLevel l{3, 3, {}};
  for (int i = 1; i <= 9; ++i) l.texels.push_back(MomentTexel{static_cast<float>(i)});
  MomentLevel r = reduceMomentLevel(l);
  ASSERT_EQ(r.width, 2);
  ASSERT_EQ(r.height, 2);
  // rows: [1 2 3] [4 5 6] [7 8 9] (row 0 first)
  EXPECT_EQ(r.at(0, 0)[kMomI], 12.0f);  // 1 + 2 + 4 + 5
  EXPECT_EQ(r.at(1, 0)[kMomI], 9.0f);   // 3 + 6
  EXPECT_EQ(r.at(0, 1)[kMomI], 15.0f);  // 7 + 8
  EXPECT_EQ(r.at(1, 1)[kMomI], 9.0f);   // 9
  MomentLevel top = reduceMomentLevel(r);
  EXPECT_EQ(top.width, 1);
  EXPECT_EQ(top.at(0, 0)[kMomI], 45.0f);
  MomentLevel same = reduceMomentLevel(top);
  EXPECT_EQ(same.at(0, 0)[kMomI], 45.0f);
}

TEST(RtwMoments, ChainSizes) {
  ImportanceMap im(13, 7);
  std::vector<MomentLevel> c = buildMomentChain(im);
  std::vector<std::pair<int, int>> sizes;
  for (const MomentLevel& l : c) sizes.emplace_back(l.width, l.height);
  EXPECT_EQ(sizes, (std::vector<std::pair<int, int>>{{13, 7}, {7, 4}, {4, 2}, {2, 1}, {1, 1}}));
  EXPECT_EQ(buildMomentChain(ImportanceMap(1, 1)).size(), 1u);
  std::vector<MomentLevel> empty = buildMomentChain(ImportanceMap());
  ASSERT_EQ(empty.size(), 1u);
  EXPECT_EQ(empty[0].texels[0], MomentTexel{});
}

TEST(RtwMoments, ChainTopEqualsDirectSumsForNonPowerOfTwoSizes) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> d(0.0f, 1.0f);
  for (auto [w, h] : std::vector<std::pair<int, int>>{
           {1, 1}, {7, 13}, {13, 7}, {100, 37}, {1, 9}, {9, 1}, {64, 64}, {513, 3}, {100, 100}}) {
    ImportanceMap im(w, h);
    for (float& v : im.values) v = d(rng) < 0.3f ? 0.0f : d(rng) * 10.0f;
    MomentTexel top = buildMomentChain(im).back().texels[0], ref = momentSumsDirect(im);
    // |x|, |y| <= 1, so every channel's sum is bounded by Σ I.
    float tol = 1e-5f * std::max(ref[kMomI], 1.0f);
    for (int k = 0; k < kMomCount; ++k)
      EXPECT_NEAR(top[k], ref[k], tol) << w << "x" << h << " channel " << k;
  }
}

// ---------------------------------------------------------------------------------------
// Stats and PCA

TEST(RtwPca, HandCheckedStats) {
  ImportanceMap im(2, 1);
  im.values = {1.0f, 3.0f};
  MomentStats s = momentsOf(im);
  EXPECT_EQ(s.sumI, 4.0f);
  EXPECT_FLOAT_EQ(s.meanX, 0.25f);
  EXPECT_EQ(s.meanY, 0.0f);
  EXPECT_FLOAT_EQ(s.alpha, 0.25f);
  EXPECT_FLOAT_EQ(s.covXX, 0.1875f);
  EXPECT_EQ(s.covYY, 0.0f);
  EXPECT_FLOAT_EQ(s.lambda1, 0.1875f);
  EXPECT_EQ(s.lambda2, 0.0f);
  EXPECT_TRUE(s.valid);
  EXPECT_EQ(s.ex, 1.0f);
  EXPECT_EQ(s.ey, 0.0f);
  EXPECT_EQ(s.angleDeg, 0.0f);

  ImportanceMap diag(2, 2);
  diag.at(0, 0) = diag.at(1, 1) = 1.0f;  // (±0.5, ±0.5)
  s = momentsOf(diag);
  EXPECT_FLOAT_EQ(s.gamma, 0.25f);  // Σ xyI / Σ I, not the poster's Σ yI / Σ I (= 0 here)
  EXPECT_FLOAT_EQ(s.covXY, 0.25f);
  EXPECT_FLOAT_EQ(s.ex, std::sqrt(0.5f));
  EXPECT_FLOAT_EQ(s.ey, std::sqrt(0.5f));
  EXPECT_FLOAT_EQ(s.angleDeg, 45.0f);

  ImportanceMap anti(2, 2);
  anti.at(1, 0) = anti.at(0, 1) = 1.0f;
  s = momentsOf(anti);
  EXPECT_FLOAT_EQ(s.angleDeg, -45.0f);
  EXPECT_GT(s.ex, 0.0f);

  ImportanceMap vertical(1, 2);
  vertical.values = {1.0f, 1.0f};
  s = momentsOf(vertical);
  EXPECT_TRUE(s.valid);
  EXPECT_EQ(s.ex, 0.0f);  // exactly along y: e = (0, +1), a +90° rotation
  EXPECT_EQ(s.ey, 1.0f);
  EXPECT_EQ(s.angleDeg, 90.0f);

  // Measured in metres on a 2:1 frustum the diagonal is at atan(1/2).
  s = momentsOf(diag, glm::vec2(2.0f, 1.0f));
  EXPECT_NEAR(s.angleDeg, std::atan(0.5) * 180.0 / kPi, 1e-4);
}

TEST(RtwPca, ThinLineGivesItsAngleWithin0p5Degrees) {
  for (auto [w, h] : std::vector<std::pair<int, int>>{{100, 100}, {128, 128}, {96, 96}}) {
    for (int deg = 0; deg <= 180; deg += 5) {
      for (glm::vec2 c : {glm::vec2(0.0f), glm::vec2(0.13f, -0.07f)}) {
        MomentStats s = momentsOf(rasterise(w, h, line(deg, c, 0.75f, w)));
        ASSERT_TRUE(s.valid) << deg;
        EXPECT_LT(axisDiffDeg(s.angleDeg, deg), 0.5) << w << " " << deg << " got " << s.angleDeg;
        EXPECT_TRUE(s.ex > 0.0f || (s.ex == 0.0f && s.ey == 1.0f)) << deg;
        EXPECT_GE(s.angleDeg, -90.0f);  // (-90, 90] up to float rounding
        EXPECT_LE(s.angleDeg, 90.0f);
        EXPECT_NEAR(s.ex * s.ex + s.ey * s.ey, 1.0f, 1e-6f);
        EXPECT_NEAR(s.meanX, c.x, 0.02f);
        EXPECT_NEAR(s.meanY, c.y, 0.02f);
      }
    }
  }
}

TEST(RtwPca, DiscAndUniformAreIsotropic) {
  for (int n : {64, 100, 127}) {
    MomentStats disc =
        momentsOf(rasterise(n, n, [](glm::vec2 p) { return glm::length(p) < 0.5f ? 1.0f : 0.0f; }));
    EXPECT_FALSE(disc.valid) << n << " anisotropy " << disc.anisotropy;
    EXPECT_GT(disc.sumI, 0.0f);
    EXPECT_EQ(disc.ex, 1.0f);
    EXPECT_EQ(disc.ey, 0.0f);
    expectNoNaN(disc);
    ImportanceMap all(n, n);
    std::fill(all.values.begin(), all.values.end(), 2.0f);
    EXPECT_FALSE(momentsOf(all).valid) << n;
  }
  // A single texel has no spread at all: λ1 = λ2 = 0, invalid.
  ImportanceMap dot(9, 9);
  dot.at(4, 4) = 1.0f;
  MomentStats s = momentsOf(dot);
  EXPECT_FALSE(s.valid);
  EXPECT_EQ(s.lambda1, 0.0f);
}

TEST(RtwPca, AllZeroHasNoAxisAndNoNaN) {
  for (auto [w, h] : std::vector<std::pair<int, int>>{{1, 1}, {7, 13}, {64, 64}, {0, 0}}) {
    MomentStats s = momentsOf(ImportanceMap(w, h));
    EXPECT_FALSE(s.valid);
    EXPECT_EQ(s.sumI, 0.0f);
    EXPECT_EQ(s.ex, 1.0f);
    EXPECT_EQ(s.ey, 0.0f);
    expectNoNaN(s);
    RotationState r;
    RotationUpdate u = updateRotation(r, s);
    EXPECT_FALSE(u.valid);
    EXPECT_FALSE(u.rotated);
    EXPECT_EQ(r.R, glm::mat2(1.0f));
    EXPECT_EQ(r.changes, 0);
  }
  float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(momentsFromTop(MomentTexel{nan, 0, 0, 0, 0, 0}).valid);
  EXPECT_FALSE(momentsFromTop(MomentTexel{-1, 0, 0, 0, 0, 0}).valid);
}

// ---------------------------------------------------------------------------------------
// Rotation

TEST(RtwRotation, RelativeRotationIsThePostersMatrix) {
  float c = std::cos(0.3f), s = std::sin(0.3f);
  glm::mat2 r = relativeRotation(c, s);
  // Rows [[c, -s], [s, c]]: glm indexes [column][row].
  EXPECT_EQ(r[0][0], c);
  EXPECT_EQ(r[1][0], -s);
  EXPECT_EQ(r[0][1], s);
  EXPECT_EQ(r[1][1], c);
  glm::vec2 x = r * glm::vec2(1, 0);  // turns x counter-clockwise onto e
  EXPECT_FLOAT_EQ(x.x, c);
  EXPECT_FLOAT_EQ(x.y, s);
}

TEST(RtwRotation, OneStepPutsThePrincipalAxisOnX) {
  MomentStats st;
  st.valid = true;
  st.ex = static_cast<float>(std::cos(rad(30)));
  st.ey = static_cast<float>(std::sin(rad(30)));
  RotationState r;
  RotationUpdate u = updateRotation(r, st);
  EXPECT_TRUE(u.valid);
  EXPECT_TRUE(u.rotated);
  EXPECT_FALSE(u.held);
  EXPECT_NEAR(u.stepDeg, 30.0f, 1e-4f);
  EXPECT_NEAR(r.angleDeg(), 30.0, 1e-4);
  EXPECT_EQ(r.changes, 1);
  EXPECT_EQ(r.frames, 1);
  // The light view takes base-plane points to the SM plane: e lands on +x.
  glm::vec2 q = lightViewRotation(r) * glm::vec2(st.ex, st.ey);
  EXPECT_NEAR(q.x, 1.0f, 1e-6f);
  EXPECT_NEAR(q.y, 0.0f, 1e-6f);
  // Same through Focus.h's 4x4 (FocusSettings::rotation = lightViewRotation).
  glm::vec4 q4 = imagePlaneRotation(lightViewRotation(r)) * glm::vec4(st.ex, st.ey, 0.5f, 1);
  EXPECT_NEAR(q4.x, 1.0f, 1e-6f);
  EXPECT_NEAR(q4.y, 0.0f, 1e-6f);
  EXPECT_EQ(q4.z, 0.5f);
  // Steps compose; reset() returns to R_0 = I.
  updateRotation(r, st);
  EXPECT_NEAR(r.angleDeg(), 60.0, 1e-4);
  EXPECT_NEAR(r.accumulatedDeg, 60.0, 1e-4);
  r.reset();
  EXPECT_EQ(r.R, glm::mat2(1.0f));
  EXPECT_EQ(r.changes, 0);
  EXPECT_EQ(r.frames, 0);
  EXPECT_EQ(r.accumulatedDeg, 0.0);
}

TEST(RtwRotation, VibrationThreshold) {
  MomentStats st;
  st.valid = true;
  st.ex = std::cos(0.01f);  // 0.573°: e_x = 0.99995 > 0.9999
  st.ey = std::sin(0.01f);
  RotationState r;
  RotationUpdate u = updateRotation(r, st);
  EXPECT_TRUE(u.held);
  EXPECT_FALSE(u.rotated);
  EXPECT_EQ(r.R, glm::mat2(1.0f));
  u = updateRotation(r, st, 1.0f);  // threshold 1: never held
  EXPECT_TRUE(u.rotated);
  EXPECT_NEAR(r.angleDeg(), 0.01 * 180.0 / kPi, 1e-4);
  r.reset();
  u = updateRotation(r, st, 0.5f);  // clamped to 0.9: held
  EXPECT_TRUE(u.held);
  u = updateRotation(r, st, std::numeric_limits<float>::quiet_NaN());  // default: held
  EXPECT_TRUE(u.held);
  st.ex = std::cos(0.02f);  // 1.15°: e_x = 0.9998 < 0.9999
  st.ey = -std::sin(0.02f);
  u = updateRotation(r, st);
  EXPECT_TRUE(u.rotated);
  EXPECT_NEAR(u.stepDeg, -0.02 * 180.0 / kPi, 1e-4);
  st.valid = false;  // invalid stats never rotate
  u = updateRotation(r, st, 1.0f);
  EXPECT_FALSE(u.valid);
  EXPECT_FALSE(u.rotated);
  EXPECT_EQ(r.changes, 1);
}

TEST(RtwRotation, StaysOrthonormalOverManySteps) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> a(-1.5f, 1.5f);
  RotationState r;
  MomentStats st;
  st.valid = true;
  double expect = 0;
  for (int i = 0; i < 2000; ++i) {
    float t = a(rng);
    st.ex = std::cos(t);
    st.ey = std::sin(t);
    updateRotation(r, st, 1.0f);
    expect += t;
  }
  EXPECT_NEAR(glm::determinant(r.R), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::length(r.R[0]), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(r.R[0], r.R[1]), 0.0f, 1e-6f);
  EXPECT_LT(axisDiffDeg(r.angleDeg(), expect * 180.0 / kPi), 0.05);
}

/// Seed 000's loop: every frame the IM is the (fixed) base-plane importance seen through
/// the current light view, q = V p with V = lightViewRotation(state) (what the renderer
/// passes to FocusSettings::rotation), i.e. IM_k(q) = f(V^-1 q); PCA; update.
struct LoopResult {
  std::vector<RotationUpdate> updates;
  RotationState state;
};

LoopResult runLoop(const std::function<float(glm::vec2)>& basePlane, int frames, int res = 128) {
  LoopResult out;
  for (int k = 0; k < frames; ++k) {
    // Through Focus.h's 4x4, as the renderer builds the light view.
    glm::mat4 toBase = glm::inverse(imagePlaneRotation(lightViewRotation(out.state)));
    ImportanceMap im = rasterise(res, res, [&](glm::vec2 q) {
      return basePlane(glm::vec2(toBase * glm::vec4(q, 0.0f, 1.0f)));
    });
    out.updates.push_back(updateRotation(out.state, momentsOf(im)));
  }
  return out;
}

TEST(RtwRotation, LoopConvergesThenHolds) {
  for (double deg : {0.0, 10.0, 30.0, 45.0, 60.0, 89.0, 90.0, 120.0, 135.0, 170.0, -20.0}) {
    LoopResult r = runLoop(line(deg, glm::vec2(0.05f, -0.1f), 0.6f, 128), 8);
    // The first frame turns by the line's angle (mod 180, into (-90, 90]) unless it is
    // already (almost) on x; from the third frame on the rotation holds.
    if (axisDiffDeg(deg, 0.0) > 1.0) {
      EXPECT_TRUE(r.updates[0].rotated) << deg;
      EXPECT_LT(axisDiffDeg(r.updates[0].stepDeg, deg), 0.5) << deg;
    } else {
      EXPECT_TRUE(r.updates[0].held) << deg;
    }
    for (size_t k = 2; k < r.updates.size(); ++k) {
      EXPECT_TRUE(r.updates[k].held) << deg << " frame " << k;
      EXPECT_FALSE(r.updates[k].rotated) << deg << " frame " << k;
    }
    EXPECT_GT(r.updates.back().e_x, 0.9999f) << deg;
    EXPECT_LE(r.state.changes, 2) << deg;
    EXPECT_LT(axisDiffDeg(r.state.angleDeg(), deg), 0.5) << deg << " got " << r.state.angleDeg();
  }
}

TEST(RtwRotation, LoopConvergesForAnOffCentreAnisotropicBlob) {
  // Gaussian blob, σ 0.35 along 125°, 0.08 across, centred at (0.1, 0.05).
  double deg = 125.0;
  glm::vec2 d(static_cast<float>(std::cos(rad(deg))), static_cast<float>(std::sin(rad(deg))));
  auto blob = [=](glm::vec2 p) {
    glm::vec2 q = p - glm::vec2(0.1f, 0.05f);
    float a = glm::dot(q, d), b = -d.y * q.x + d.x * q.y;
    return std::exp(-(a * a) / (2 * 0.35f * 0.35f) - (b * b) / (2 * 0.08f * 0.08f));
  };
  LoopResult r = runLoop(blob, 6, 100);
  EXPECT_TRUE(r.updates[0].rotated);
  for (size_t k = 2; k < r.updates.size(); ++k) EXPECT_TRUE(r.updates[k].held) << k;
  EXPECT_LT(axisDiffDeg(r.state.angleDeg(), deg), 0.5) << r.state.angleDeg();
}

// ---------------------------------------------------------------------------------------
// The poster's source: the moments of the importance map itself, every texel.

// A hand-made 64^2 IM of five texels on a diagonal (weights 1..5): x̄, ȳ and Σ computed by
// hand from the five centred texel coordinates equal the chain's over the full IM (1e-6),
// and its axis is the diagonal's. Reduced to 16^2 block maxima (the block-max source) the
// same texels land in blocks whose centres are up to 1.5 texels away: the mean moves, so
// the source changes what the PCA sees.
TEST(RtwPca, FullImMomentsEqualHandComputedMoments) {
  const int n = 64;
  ImportanceMap im(n, n);
  const int tx[5] = {8, 20, 32, 44, 56}, ty[5] = {10, 21, 33, 45, 54};
  for (int k = 0; k < 5; ++k) im.at(tx[k], ty[k]) = float(k + 1);
  double s = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  for (int k = 0; k < 5; ++k) {
    const double w = k + 1, x = (2.0 * tx[k] + 1 - n) / n, y = (2.0 * ty[k] + 1 - n) / n;
    s += w, sx += w * x, sy += w * y, sxx += w * x * x, syy += w * y * y, sxy += w * x * y;
  }
  const double mx = sx / s, my = sy / s;
  const double cxx = sxx / s - mx * mx, cyy = syy / s - my * my, cxy = sxy / s - mx * my;
  const MomentStats st = momentsOf(im);
  ASSERT_TRUE(st.valid);
  EXPECT_NEAR(st.sumI, 15.0, 1e-6);
  EXPECT_NEAR(st.meanX, mx, 1e-6);
  EXPECT_NEAR(st.meanY, my, 1e-6);
  EXPECT_NEAR(st.covXX, cxx, 1e-6);
  EXPECT_NEAR(st.covYY, cyy, 1e-6);
  EXPECT_NEAR(st.covXY, cxy, 1e-6);
  const double axisDeg = 0.5 * std::atan2(2 * cxy, cxx - cyy) * 180.0 / kPi;
  EXPECT_NEAR(st.angleDeg, axisDeg, 1e-3);
  // The block-max source: 16^2 blocks of 4x4 texels, each its maximum.
  ImportanceMap blocks(16, 16);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      blocks.at(x / 4, y / 4) = std::max(blocks.at(x / 4, y / 4), im.at(x, y));
  const MomentStats sb = momentsOf(blocks);
  EXPECT_GT(std::fabs(sb.meanY - st.meanY), 1e-3);
}

// The half-mass width of a 1D map: the shortest run of texels holding half its sum.
TEST(RtwImportance, HalfMassWidth) {
  EXPECT_EQ(halfMassWidth({}), 0.0f);
  EXPECT_EQ(halfMassWidth({0, 0, 0, 0}), 0.0f);
  EXPECT_FLOAT_EQ(halfMassWidth({1, 1, 1, 1}), 0.5f);
  EXPECT_FLOAT_EQ(halfMassWidth({0, 0, 10, 0, 0, 0, 0, 0, 0, 0}), 0.1f);
  EXPECT_FLOAT_EQ(halfMassWidth({1, 0, 0, 0, 0, 0, 0, 4, 4, 1}), 0.2f);  // 8 of 10
  EXPECT_FLOAT_EQ(halfMassWidth({3, 0, 0, 0, 0, 0, 0, 0, 0, 3}), 0.1f);  // either end alone
}

// light.fit = rotation-invariant: the rotated frustum has the same side at every angle
// (its area does not depend on the rotation), covers every focus point, and is never
// smaller than the tight fit; the tight fit's area changes with the angle.
TEST(RtwFocus, RotationInvariantExtentDoesNotChangeWithTheAngle) {
  Camera cam;
  cam.position = {0, 2, 6};
  cam.target = {3, 0, -4};
  cam.farM = 30;
  const Aabb box{{-20, 0, -20}, {20, 1, 20}};
  const glm::vec3 L = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
  std::vector<float> tightArea, side;
  for (double deg : {0.0, 17.0, 45.0, -60.0, 90.0}) {
    const float c = float(std::cos(rad(deg))), sn = float(std::sin(rad(deg)));
    FocusSettings fs;
    fs.rotation = glm::mat2(c, sn, -sn, c);
    LightFit tight, inv;
    ASSERT_FALSE(fitDirectionalLight(cam, 16.0f / 9.0f, box, L, fs, tight));
    fs.extent = FocusExtent::RotationInvariant;
    ASSERT_FALSE(fitDirectionalLight(cam, 16.0f / 9.0f, box, L, fs, inv));
    EXPECT_FLOAT_EQ(inv.extentM.x, inv.extentM.y);
    EXPECT_GE(inv.extentM.x * inv.extentM.y, tight.extentM.x * tight.extentM.y);
    side.push_back(inv.extentM.x);
    tightArea.push_back(tight.extentM.x * tight.extentM.y);
    for (const glm::vec3& p : inv.focusPoints) {
      glm::vec4 q = inv.viewProj * glm::vec4(p, 1.0f);
      EXPECT_LE(std::fabs(q.x), 1.0f + 1e-4f);
      EXPECT_LE(std::fabs(q.y), 1.0f + 1e-4f);
    }
  }
  for (float s : side) EXPECT_NEAR(s, side.front(), 1e-4f * side.front());
  const auto [lo, hi] = std::minmax_element(tightArea.begin(), tightArea.end());
  EXPECT_GT(*hi / *lo, 1.05f);
}

// pca.min_anisotropy: an axis of an importance rounder than the gate leaves R as it is
// (tooRound, not a vibration hold); at or above it the poster's update runs.
TEST(RtwRotation, MinAnisotropyGate) {
  MomentStats st;
  st.valid = true;
  st.ex = std::cos(float(rad(30.0)));
  st.ey = std::sin(float(rad(30.0)));
  st.anisotropy = 0.5f;
  RotationState state;
  RotationUpdate u = updateRotation(state, st, 0.9999f, 0.6f);
  EXPECT_TRUE(u.valid);
  EXPECT_TRUE(u.tooRound);
  EXPECT_FALSE(u.held);
  EXPECT_FALSE(u.rotated);
  EXPECT_EQ(state.angleDeg(), 0.0);
  u = updateRotation(state, st, 0.9999f, 0.5f);
  EXPECT_TRUE(u.rotated);
  EXPECT_NEAR(state.angleDeg(), 30.0, 1e-4);
  u = updateRotation(state, st, 0.9999f, std::nanf(""));  // NaN: 0, the poster
  EXPECT_TRUE(u.rotated);
}

// pca.min_spread: a thin, anisotropic importance whose half mass sits in a small share of
// the map leaves R as it is (tooConcentrated, checked after the anisotropy gate and before
// the hold); a spread one turns; 0 (or a NaN spread with the gate off) is the poster.
TEST(RtwRotation, MinSpreadGate) {
  MomentStats st;
  st.valid = true;
  st.ex = std::cos(float(rad(40.0)));
  st.ey = std::sin(float(rad(40.0)));
  st.anisotropy = 0.98f;
  RotationState state;
  RotationUpdate u = updateRotation(state, st, 0.9999f, 0.9f, 0.006f, 0.05f);
  EXPECT_TRUE(u.valid);
  EXPECT_TRUE(u.tooConcentrated);
  EXPECT_FALSE(u.tooRound);
  EXPECT_FALSE(u.held);
  EXPECT_FALSE(u.rotated);
  EXPECT_EQ(state.angleDeg(), 0.0);
  // Too round wins over too concentrated: the first gate that stops it is named.
  u = updateRotation(state, st, 0.9999f, 0.99f, 0.006f, 0.05f);
  EXPECT_TRUE(u.tooRound);
  EXPECT_FALSE(u.tooConcentrated);
  // Spread at the gate: turns.
  u = updateRotation(state, st, 0.9999f, 0.9f, 0.05f, 0.05f);
  EXPECT_TRUE(u.rotated);
  EXPECT_NEAR(state.angleDeg(), 40.0, 1e-4);
  // Gate off: any spread, even an unmeasured one, turns.
  state.reset();
  u = updateRotation(state, st, 0.9999f, 0.0f, std::nanf(""), 0.0f);
  EXPECT_TRUE(u.rotated);
  // A NaN spread with the gate on is not a measurement that allows a turn.
  state.reset();
  u = updateRotation(state, st, 0.9999f, 0.0f, std::nanf(""), 0.05f);
  EXPECT_TRUE(u.tooConcentrated);
  EXPECT_EQ(state.angleDeg(), 0.0);
}

}  // namespace
}  // namespace sl::rtw
