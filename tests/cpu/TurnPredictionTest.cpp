// DA-RTW's turn chosen by its predicted warp (algo/rtw/TurnPrediction.h): exact CPU tests on
// importance shapes whose answer is known without the prediction: an axis-aligned strip gains
// nothing from a turn, a strip at 45° gains at 45°, a round blob gains nothing; the score's
// quarter-turn symmetry; the search and the decision rule.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "algo/rtw/TurnPrediction.h"

namespace sl::rtw {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

glm::dvec2 rotate(glm::dvec2 p, double deg) {
  const double c = std::cos(deg * kDeg), s = std::sin(deg * kDeg);
  return {c * p.x - s * p.y, s * p.x + c * p.y};
}

/// A light frame in the unturned image plane (metres): turned by angleDeg, the tight box
/// [lo, lo + extent] in the turned coordinates q = R^T p, as the renderer's tight fit.
struct PlaneFrame {
  double angleDeg = 0.0;
  glm::dvec2 lo{0.0}, extent{1.0};
  glm::dvec2 uvOf(glm::dvec2 p) const { return (rotate(p, -angleDeg) - lo) / extent; }
  glm::dvec2 pointOf(glm::dvec2 uv) const { return rotate(lo + uv * extent, angleDeg); }
};

/// The tight frame at `angleDeg` around the polygon `focus` (the region the camera sees).
PlaneFrame tightFrame(const std::vector<glm::dvec2>& focus, double angleDeg) {
  glm::dvec2 lo(1e300), hi(-1e300);
  for (glm::dvec2 p : focus) {
    const glm::dvec2 q = rotate(p, -angleDeg);
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  return {angleDeg, lo, hi - lo};
}

CandidateFrame candidate(const PlaneFrame& snapshot, const PlaneFrame& to) {
  CandidateFrame c;
  c.angleDeg = to.angleDeg;
  c.turnDeg = to.angleDeg - snapshot.angleDeg;
  const glm::dvec2 o = to.uvOf(snapshot.pointOf({0.0, 0.0}));
  c.fromSnapshot.offset = o;
  c.fromSnapshot.linear = glm::dmat2(to.uvOf(snapshot.pointOf({1.0, 0.0})) - o,
                                     to.uvOf(snapshot.pointOf({0.0, 1.0})) - o);
  c.extentM = to.extent;
  return c;
}

/// A snapshot of M x M texels over `frame`: importance(p) at each texel centre, 4 pixels per
/// texel where it is > 0, one of them on a shadow edge whose normal (world plane, degrees) is
/// edgeNormalDeg(p) (no edge when it returns NaN).
ImportanceSnapshot snapshotOf(const PlaneFrame& frame, int m,
                              const std::function<double(glm::dvec2)>& importance,
                              const std::function<double(glm::dvec2)>& edgeNormalDeg = {}) {
  ImportanceSnapshot s;
  s.size = m;
  const size_t plane = size_t(m * m);
  s.importance.assign(plane, 0.0f);
  s.pixels.assign(plane, 0u);
  s.edgeBins.assign(kEdgeBins * plane, 0u);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const glm::dvec2 p = frame.pointOf({(i + 0.5) / m, (j + 0.5) / m});
      const double v = importance(p);
      if (!(v > 0.0)) continue;
      const size_t k = size_t(j * m + i);
      s.importance[k] = float(v);
      s.pixels[k] = 4;
      const double normal = edgeNormalDeg ? edgeNormalDeg(p) : std::nan("");
      if (std::isnan(normal)) continue;
      const EdgeBinParts parts = edgeBinParts(normal - frame.angleDeg);  // in the frame's axes
      s.edgeBins[size_t(parts.lo) * plane + k] += parts.loPart;
      s.edgeBins[size_t(parts.hi) * plane + k] += parts.hiPart;
    }
  return s;
}

PredictionSettings settings() {
  PredictionSettings p;
  p.warpResolution = 256;
  p.mapResolution = 512;
  p.densityPerImportance = 300.0;
  p.weight = PredictionWeight::EdgePixels;  // the default
  return p;
}

/// A strip of length 2 m and width 0.1 m along direction `deg`, importance falling off along
/// it (as 1/z does away from the camera): the focus region is the strip itself.
struct Strip {
  double deg;
  std::vector<glm::dvec2> focus() const {
    std::vector<glm::dvec2> f;
    for (glm::dvec2 c :
         {glm::dvec2(-1, -0.05), glm::dvec2(1, -0.05), glm::dvec2(1, 0.05), glm::dvec2(-1, 0.05)})
      f.push_back(rotate(c, deg));
    return f;
  }
  double importance(glm::dvec2 p) const {
    const glm::dvec2 q = rotate(p, -deg);
    if (std::abs(q.x) > 1.0 || std::abs(q.y) > 0.05) return 0.0;
    return 1.0 / (1.0 + 2.0 * (q.x + 1.0));
  }
  /// A fence on it: rails along the strip, and a post across it in one of every five
  /// segments of its length (most of a fence's shadow edge is its rails').
  double edgeNormal(glm::dvec2 p) const {
    const glm::dvec2 q = rotate(p, -deg);
    return deg + (int(std::floor((q.x + 1.0) * 20.0)) % 5 == 0 ? 0.0 : 90.0);
  }
  ImportanceSnapshot snapshot(const PlaneFrame& from, int m) const {
    return snapshotOf(
        from, m, [this](glm::dvec2 p) { return importance(p); },
        [this](glm::dvec2 p) { return edgeNormal(p); });
  }
};

TurnSearch searchFor(const std::vector<glm::dvec2>& focus, const ImportanceSnapshot& snap,
                     const PlaneFrame& from, const PredictionSettings& p) {
  return searchTurn(from.angleDeg, std::nullopt, [&](double deg) {
    return predictWarp(snap, candidate(from, tightFrame(focus, deg)), p);
  });
}

TEST(TurnPrediction, AxisAlignedStripPredictsNoGainFromTurning) {
  const Strip strip{0.0};
  const PlaneFrame from = tightFrame(strip.focus(), 0.0);
  const ImportanceSnapshot snap = strip.snapshot(from, 64);
  const TurnSearch s = searchFor(strip.focus(), snap, from, settings());
  ASSERT_GE(s.best, 0);
  const TurnDecision d = decideTurn(s, 0.0, 0.0);
  EXPECT_EQ(d.reason, TurnReason::CurrentIsBest) << "best at " << d.bestDeg << ", gain " << d.gain;
  EXPECT_DOUBLE_EQ(d.toDeg, 0.0);
  // Every turn is predicted worse, the diagonal worst of all.
  const WarpPrediction& cur = s.scored[size_t(s.current)];
  for (const WarpPrediction& p : s.scored) {
    ASSERT_TRUE(p.valid);
    if (p.angleDeg != 0.0) {
      EXPECT_GT(p.score, cur.score) << p.angleDeg;
    }
  }
  const WarpPrediction diag =
      predictWarp(snap, candidate(from, tightFrame(strip.focus(), 45.0)), settings());
  EXPECT_GT(diag.score, 1.2 * cur.score);
}

TEST(TurnPrediction, DiagonalStripPredictsItsGainAt45Degrees) {
  for (double deg : {45.0, -45.0, 30.0, -20.0}) {
    const Strip strip{deg};
    const PlaneFrame from = tightFrame(strip.focus(), 0.0);  // the unturned frame
    const ImportanceSnapshot snap = strip.snapshot(from, 128);
    const TurnSearch s = searchFor(strip.focus(), snap, from, settings());
    // The strip's own direction is the best turn, to the finest step of the search.
    EXPECT_NEAR(foldQuarterTurn(s.scored[size_t(s.best)].angleDeg - deg), 0.0, 3.75 + 1e-9) << deg;
    const TurnDecision d = decideTurn(s, kDefaultTurnMargin, 0.81);
    std::printf("strip at %g deg: best turn %g deg, predicted gain %.3f\n", deg, d.bestDeg, d.gain);
    if (std::abs(deg) == 45.0) {  // the most a separable warp can lose to a diagonal
      EXPECT_EQ(d.reason, TurnReason::Turned) << deg;
      EXPECT_GT(d.gain, kDefaultTurnMargin) << deg;
    }
  }
}

TEST(TurnPrediction, RoundBlobPredictsNoGain) {
  // A disc of importance falling off with the distance from a point off its centre: the
  // tight box and the separable warp are the same at every angle up to resampling.
  std::vector<glm::dvec2> focus;
  for (int k = 0; k < 64; ++k) focus.push_back(rotate({1.0, 0.0}, 360.0 * k / 64.0));
  const PlaneFrame from = tightFrame(focus, 0.0);
  const ImportanceSnapshot snap = snapshotOf(
      from, 128,
      [](glm::dvec2 p) {
        return glm::length(p) <= 1.0 ? 1.0 / (1.0 + glm::length(p - glm::dvec2(0.3, 0.2))) : 0.0;
      },
      [](glm::dvec2 p) { return std::atan2(p.y, p.x) / kDeg; });  // edges of every direction
  const TurnSearch s = searchFor(focus, snap, from, settings());
  const double cur = s.scored[size_t(s.current)].score;
  for (const WarpPrediction& p : s.scored) EXPECT_NEAR(p.score / cur, 1.0, 0.03) << p.angleDeg;
  EXPECT_NE(decideTurn(s, 0.05, 0.81).reason, TurnReason::Turned);
}

TEST(TurnPrediction, ScoresRepeatEveryQuarterTurnAndTheDensityConstantCancels) {
  const Strip strip{20.0};
  const PlaneFrame from = tightFrame(strip.focus(), 0.0);
  const ImportanceSnapshot snap = strip.snapshot(from, 64);
  PredictionSettings a = settings(), b = settings();
  b.densityPerImportance = 7.0 * a.densityPerImportance;
  for (double deg : {-40.0, -10.0, 0.0, 25.0}) {
    const WarpPrediction p = predictWarp(snap, candidate(from, tightFrame(strip.focus(), deg)), a);
    const WarpPrediction q =
        predictWarp(snap, candidate(from, tightFrame(strip.focus(), deg + 90.0)), a);
    EXPECT_NEAR(q.score / p.score, 1.0, 1e-6) << deg;  // the blur is in float
    const WarpPrediction r = predictWarp(snap, candidate(from, tightFrame(strip.focus(), deg)), b);
    EXPECT_NEAR(r.score / p.score, 7.0, 1e-9) << deg;  // ratios of scores do not depend on k
  }
}

TEST(TurnPrediction, UndersampledShareAndQuantilesFollowTheDensity) {
  const Strip strip{0.0};
  const PlaneFrame from = tightFrame(strip.focus(), 0.0);
  const ImportanceSnapshot snap =
      snapshotOf(from, 64, [&](glm::dvec2 p) { return strip.importance(p); });
  const CandidateFrame same = candidate(from, from);
  PredictionSettings p = settings();
  p.weight = PredictionWeight::Pixels;
  const std::vector<double> qs{0.5, 0.95};
  p.densityPerImportance = 1e-3;  // asks for almost nothing: nothing is undersampled
  EXPECT_EQ(predictWarp(snap, same, p).undersampled, 0.0);
  const std::vector<double> low = predictedAliasingQuantiles(snap, same, p, qs);
  p.densityPerImportance = 1e6;  // asks for far more than 512 texels: all undersampled
  EXPECT_EQ(predictWarp(snap, same, p).undersampled, 1.0);
  const std::vector<double> high = predictedAliasingQuantiles(snap, same, p, qs);
  ASSERT_EQ(low.size(), 2u);
  ASSERT_EQ(high.size(), 2u);
  EXPECT_LE(low[0], low[1]);
  EXPECT_NEAR(high[0] / low[0], 1e9, 1e9 * 1e-9);  // m is linear in k
}

TEST(TurnPrediction, ResampleIntoTheSameFrameFillsWhatWasThere) {
  // Snapshot at 64 texels, 1D maps at 256: each texel fills the 4 texels it covers.
  const PlaneFrame from{0.0, {0.0, 0.0}, {1.0, 1.0}};
  ImportanceSnapshot snap;
  snap.size = 64;
  snap.importance.assign(64 * 64, 0.0f);
  snap.importance[size_t(10 * 64 + 5)] = 2.0f;  // texel (5, 10)
  const Collapsed c = resampleCollapsed(snap, candidate(from, from), 256);
  for (int k = 0; k < 256; ++k) {
    EXPECT_EQ(c.x[size_t(k)], k >= 20 && k < 24 ? 2.0f : 0.0f) << k;
    EXPECT_EQ(c.y[size_t(k)], k >= 40 && k < 44 ? 2.0f : 0.0f) << k;
  }
}

TEST(TurnPrediction, EdgeWeightsIgnoreTexelsWithoutEdges) {
  const Strip strip{0.0};
  const PlaneFrame from = tightFrame(strip.focus(), 0.0);
  ImportanceSnapshot snap = snapshotOf(from, 64, [&](glm::dvec2 p) { return strip.importance(p); });
  PredictionSettings p = settings();
  p.weight = PredictionWeight::EdgePixels;
  EXPECT_FALSE(predictWarp(snap, candidate(from, from), p).valid);  // no edge: no prediction
  p.weight = PredictionWeight::Pixels;
  EXPECT_TRUE(predictWarp(snap, candidate(from, from), p).valid);
}

TEST(TurnPrediction, EdgesAlongADiagonalStripMakeTheTurnPayMore) {
  // The same 45° strip with its shadow edges along it (a wall's shadow): once turned, the
  // map's fine axis lies across every edge, so the edge-weighted prediction gains more than
  // the one that counts edges of every direction alike.
  const Strip strip{45.0};
  const PlaneFrame from = tightFrame(strip.focus(), 0.0);
  const ImportanceSnapshot snap = snapshotOf(
      from, 128, [&](glm::dvec2 p) { return strip.importance(p); },
      [](glm::dvec2) { return 135.0; });
  PredictionSettings p = settings();
  p.weight = PredictionWeight::EdgePixels;
  const TurnDecision edges = decideTurn(searchFor(strip.focus(), snap, from, p), 0.1, 0.81);
  p.weight = PredictionWeight::Pixels;
  const TurnDecision pixels = decideTurn(searchFor(strip.focus(), snap, from, p), 0.1, 0.81);
  EXPECT_EQ(edges.reason, TurnReason::Turned);
  EXPECT_NEAR(foldQuarterTurn(edges.toDeg - 45.0), 0.0, 3.75 + 1e-9);
  EXPECT_GT(edges.gain, pixels.gain + 0.2) << edges.gain << " " << pixels.gain;
  // Edges across the strip instead: the turn lays the map's COARSE axis across them.
  const ImportanceSnapshot across = snapshotOf(
      from, 128, [&](glm::dvec2 q) { return strip.importance(q); },
      [](glm::dvec2) { return 45.0; });
  p.weight = PredictionWeight::EdgePixels;
  const TurnDecision a = decideTurn(searchFor(strip.focus(), across, from, p), 0.1, 0.81);
  EXPECT_LT(a.gain, edges.gain);
}

TEST(TurnPrediction, EdgeBinPartsSplitBetweenTheTwoNearestBins) {
  const EdgeBinParts zero = edgeBinParts(0.0);
  EXPECT_EQ(zero.lo, 0);
  EXPECT_EQ(zero.loPart, kEdgeOne);
  EXPECT_EQ(zero.hiPart, 0u);
  const EdgeBinParts quarter = edgeBinParts(kEdgeBinDeg * 0.25);
  EXPECT_EQ(quarter.lo, 0);
  EXPECT_EQ(quarter.hi, 1);
  EXPECT_EQ(quarter.hiPart, kEdgeOne / 4);
  EXPECT_EQ(quarter.loPart + quarter.hiPart, kEdgeOne);
  const EdgeBinParts wrap = edgeBinParts(180.0 - kEdgeBinDeg * 0.5);  // between last and 0
  EXPECT_EQ(wrap.lo, kEdgeBins - 1);
  EXPECT_EQ(wrap.hi, 0);
  EXPECT_EQ(wrap.hiPart, kEdgeOne / 2);
  const EdgeBinParts negative = edgeBinParts(-kEdgeBinDeg * 0.5);  // the same direction
  EXPECT_EQ(negative.lo, wrap.lo);
  EXPECT_EQ(negative.hiPart, wrap.hiPart);
  EXPECT_EQ(edgeBinParts(std::nan("")).lo, 0);
}

TEST(TurnPrediction, EmptyOrDegenerateInputPredictsNothing) {
  const PlaneFrame from{0.0, {0.0, 0.0}, {1.0, 1.0}};
  ImportanceSnapshot empty;
  EXPECT_FALSE(predictWarp(empty, candidate(from, from), settings()).valid);
  ImportanceSnapshot zeros;
  zeros.size = 8;
  zeros.importance.assign(64, 0.0f);
  EXPECT_FALSE(predictWarp(zeros, candidate(from, from), settings()).valid);
  CandidateFrame flat = candidate(from, from);
  flat.extentM = {0.0, 1.0};
  zeros.importance[3] = 1.0f;
  EXPECT_FALSE(predictWarp(zeros, flat, settings()).valid);
  const TurnSearch s = searchTurn(0.0, std::nullopt, [](double) { return WarpPrediction{}; });
  EXPECT_EQ(decideTurn(s, 0.05, 0.81).reason, TurnReason::NoPrediction);
}

TEST(TurnPrediction, ReduceSnapshotKeepsBlockMaximaAndSumsCounts) {
  ImportanceSnapshot s;
  s.size = 5;  // 5 -> blocks of 3 -> 2 texels a side
  s.importance.assign(25, 0.0f);
  s.pixels.assign(25, 1u);
  s.edgeBins.assign(kEdgeBins * 25, 0u);
  s.importance[size_t(1 * 5 + 2)] = 3.0f;
  s.importance[size_t(0 * 5 + 0)] = 1.0f;
  s.importance[size_t(4 * 5 + 4)] = 2.0f;
  s.edgeBins[size_t(2 * 25 + 4 * 5 + 3)] = kEdgeOne;
  s.meanImportance.assign(25, 1.0f);
  s.meanImportance[0] = 4.0f;
  s.pixels[0] = 3u;  // block 0: 3 pixels of mean 4 and 8 of mean 1 -> 20 / 11
  const ImportanceSnapshot r = reduceSnapshot(s, 2);
  EXPECT_FLOAT_EQ(r.meanImportance[0], 20.0f / 11.0f);
  EXPECT_FLOAT_EQ(r.meanImportance[3], 1.0f);
  ASSERT_EQ(r.size, 2);
  EXPECT_EQ(r.importance[0], 3.0f);
  EXPECT_EQ(r.importance[3], 2.0f);
  EXPECT_EQ(r.pixels[0], 11u);
  EXPECT_EQ(r.pixels[1], 6u);
  EXPECT_EQ(r.pixels[3], 4u);
  EXPECT_EQ(r.edgeBins[size_t(2 * 4 + 3)], kEdgeOne);
  EXPECT_EQ(reduceSnapshot(s, 8).size, 5);
}

// The score's premise: beside a straight edge, the band where a point and the centre of its
// texel lie on opposite sides is on average a quarter of the texel's norm width across the
// edge, whatever the edge's angle and the texels' aspect. Sampled here: points uniform around
// edges at random offsets against a (wX, wY) grid (a fixed seed). The form is not exact: a
// 45° edge on square texels has 0.236 of a texel, not 0.25 (measured with 4 M samples); the
// tolerance is 7 %.
TEST(TurnPrediction, EdgeBandIsAQuarterOfTheTexelsNormWidth) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const glm::dvec2 w : {glm::dvec2(1.0, 1.0), glm::dvec2(1.0, 0.25)})
    for (double deg : {0.0, 10.0, 30.0, 45.0, 70.0, 90.0}) {
      const double c = std::cos(deg * kDeg), s = std::sin(deg * kDeg);
      const double half = 2.0 * std::max(w.x, w.y);
      long wrong = 0, samples = 0;
      for (int edge = 0; edge < 2000; ++edge) {
        const double offset = 10.0 * unit(rng);  // the edge: n . p = offset
        for (int i = 0; i < 200; ++i, ++samples) {
          const double t = 50.0 * unit(rng), d = half * (2.0 * unit(rng) - 1.0);
          const glm::dvec2 p(-s * t + c * (d + offset), c * t + s * (d + offset));
          const glm::dvec2 centre = (glm::floor(p / w) + 0.5) * w;
          const double sp = c * p.x + s * p.y - offset, sc = c * centre.x + s * centre.y - offset;
          wrong += (sp > 0.0) != (sc > 0.0);
        }
      }
      const double band = double(wrong) / double(samples) * 2.0 * half;
      EXPECT_NEAR(band / edgeBandWidth(deg, w.x, w.y), 1.0, 0.07) << deg << " " << w.y;
    }
}

TEST(TurnPrediction, FoldQuarterTurn) {
  EXPECT_DOUBLE_EQ(foldQuarterTurn(0.0), 0.0);
  EXPECT_DOUBLE_EQ(foldQuarterTurn(45.0), 45.0);
  EXPECT_DOUBLE_EQ(foldQuarterTurn(-45.0), 45.0);
  EXPECT_DOUBLE_EQ(foldQuarterTurn(60.0), -30.0);
  EXPECT_DOUBLE_EQ(foldQuarterTurn(-100.0), -10.0);
  EXPECT_DOUBLE_EQ(foldQuarterTurn(90.0), 0.0);
  EXPECT_DOUBLE_EQ(foldQuarterTurn(std::nan("")), 0.0);
}

TEST(TurnPrediction, SearchScoresEachAngleOnceAndRefinesAroundTheBest) {
  // A smooth synthetic score with its minimum at 22°.
  std::vector<double> asked;
  const TurnSearch s = searchTurn(-10.0, 40.0, [&](double deg) {
    asked.push_back(deg);
    WarpPrediction p;
    p.valid = true;
    p.score = 1.0 + std::pow(foldQuarterTurn(deg - 22.0) / 45.0, 2.0);
    return p;
  });
  EXPECT_EQ(asked.size(), s.scored.size());
  EXPECT_LE(s.scored.size(), 12u);
  for (size_t i = 0; i < asked.size(); ++i)
    for (size_t j = i + 1; j < asked.size(); ++j) EXPECT_NE(asked[i], asked[j]);
  EXPECT_DOUBLE_EQ(s.scored[size_t(s.current)].angleDeg, -10.0);
  EXPECT_NEAR(s.scored[size_t(s.best)].angleDeg, 22.5, 1e-9);  // 15 -> 22.5 (7.5) -> 22.5
  const TurnDecision d = decideTurn(s, 0.05, 0.81);
  EXPECT_EQ(d.reason, TurnReason::Turned);
  EXPECT_DOUBLE_EQ(d.toDeg, 22.5);
  // With no turn in sight (refined only above a gain of 0.9), the coarse grid alone.
  asked.clear();
  const TurnSearch coarse = searchTurn(
      -10.0, 40.0,
      [&](double deg) {
        asked.push_back(deg);
        WarpPrediction p;
        p.valid = true;
        p.score = 1.0 + std::pow(foldQuarterTurn(deg - 22.0) / 45.0, 2.0);
        return p;
      },
      0.9);
  EXPECT_EQ(asked.size(), 8u);  // the current angle, PCA's axis, six every 15°
  EXPECT_DOUBLE_EQ(coarse.scored[size_t(coarse.best)].angleDeg, 15.0);
}

TEST(TurnPrediction, DecisionHoldsWithinTheMarginAndTheVibrationAngle) {
  TurnSearch s;
  WarpPrediction cur, best;
  cur.valid = best.valid = true;
  cur.angleDeg = 10.0;
  cur.score = 1.0;
  best.angleDeg = 10.5;
  best.score = 0.8;
  s.scored = {cur, best};
  s.current = 0;
  s.best = 1;
  EXPECT_EQ(decideTurn(s, 0.25, 0.0).reason, TurnReason::WithinMargin);
  s.scored[0].outside = 0.3;  // most of the last frame's importance left this frame
  EXPECT_EQ(decideTurn(s, 0.1, 0.0).reason, TurnReason::ViewMoved);
  s.scored[0].outside = 0.0;
  EXPECT_EQ(decideTurn(s, 0.1, 0.81).reason, TurnReason::WithinVibration);
  const TurnDecision d = decideTurn(s, 0.1, 0.3);
  EXPECT_EQ(d.reason, TurnReason::Turned);
  EXPECT_DOUBLE_EQ(d.toDeg, 10.5);
  EXPECT_NEAR(d.gain, 0.2, 1e-12);
}

TEST(TurnPrediction, UvAffineBetweenLightFrames) {
  // Two orthographic frames of the same light: the second turned by 30° and shifted.
  auto frame = [](double deg, glm::dvec2 lo, glm::dvec2 ext) {
    const double c = std::cos(deg * kDeg), s = std::sin(deg * kDeg);
    glm::mat4 view(1.0f);  // world (x, y) -> turned (R^T p)
    view[0][0] = float(c), view[1][0] = float(s);
    view[0][1] = float(-s), view[1][1] = float(c);
    const glm::mat4 proj =
        glm::ortho(float(lo.x), float(lo.x + ext.x), float(lo.y), float(lo.y + ext.y), -1.0f, 1.0f);
    return proj * view;
  };
  const PlaneFrame a{0.0, {-1.0, -2.0}, {2.0, 4.0}}, b{30.0, {-1.5, -1.0}, {3.0, 2.5}};
  const UvAffine m =
      uvAffineBetween(frame(a.angleDeg, a.lo, a.extent), frame(b.angleDeg, b.lo, b.extent));
  for (glm::dvec2 uv : {glm::dvec2(0.2, 0.7), glm::dvec2(0.9, 0.1)}) {
    const glm::dvec2 expected = b.uvOf(a.pointOf(uv));
    const glm::dvec2 got = m.apply(uv);
    EXPECT_NEAR(got.x, expected.x, 1e-6);
    EXPECT_NEAR(got.y, expected.y, 1e-6);
  }
}

TEST(TurnPrediction, RotationOfAngleMatchesRotationState) {
  const glm::mat2 r = rotationOfAngle(30.0);
  EXPECT_NEAR(r[0][0], std::cos(30.0 * kDeg), 1e-7);
  EXPECT_NEAR(r[0][1], std::sin(30.0 * kDeg), 1e-7);  // R = [[c, -s], [s, c]] (rows)
  EXPECT_NEAR(r[1][0], -std::sin(30.0 * kDeg), 1e-7);
}

}  // namespace
}  // namespace sl::rtw
