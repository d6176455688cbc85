// Warping and partitioning analysis (Lloyd, Tuft, Yoon, Manocha, EGSR 2006): the closed forms
// for the overhead light (eqs. 7-14), the equivalence of PSM, LiSPSM and TSM for
// n' <= n'_LiSPSM, the log split's optimality, face partitioning, split schemes, stable cascades.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "algo/partition/Splits.h"
#include "algo/partition/Stabilize.h"
#include "algo/partition/StorageFactor.h"
#include "algo/warp/PerspectiveWarp.h"

namespace sl::partition {
namespace {

using warp::ViewFrustum;
using warp::WarpFit;
using warp::WarpKind;
using warp::WarpSettings;

constexpr double kPi = std::numbers::pi;
const glm::dvec3 kOverhead(0.0, 1.0, 0.0);

/// The paper's Fig. 6 frustum (n = 1, f = 100), looking along -z, square image, 60 degrees.
ViewFrustum paperView(double n = 1.0, double f = 100.0, double fovDeg = 60.0) {
  ViewFrustum v;
  v.nearM = n;
  v.farM = f;
  v.fovYRad = fovDeg * kPi / 180.0;
  return v;
}

std::vector<glm::dvec3> cornersOf(const ViewFrustum& v) {
  const auto c = v.corners();
  return {c.begin(), c.end()};
}

WarpFit fitEta(const ViewFrustum& v, double eta, const glm::dvec3& light = kOverhead) {
  WarpSettings ws;
  ws.kind = WarpKind::Eta;
  ws.eta = eta;
  WarpFit fit;
  auto e = warp::fitWarp(v, cornersOf(v), light, ws, fit);
  EXPECT_FALSE(e) << *e;
  return fit;
}

StorageResult evaluate(const ViewFrustum& v, const glm::dvec3& light, SchemeSettings s) {
  StorageResult r;
  auto e = evaluateScheme(v, light, s, r);
  EXPECT_FALSE(e) << *e;
  return r;
}

SchemeSettings scheme(Scheme s, int k = 1) {
  SchemeSettings st;
  st.scheme = s;
  st.partitions = k;
  return st;
}

/// Towards a light at `elevationDeg` above the horizon, behind (+z) a viewer looking along -z.
glm::dvec3 lightBehind(double elevationDeg) {
  const double e = elevationDeg * kPi / 180.0;
  return {0.0, std::sin(e), std::cos(e)};
}

void expectRel(double got, double want, double rel, const char* what) {
  EXPECT_NEAR(got, want, rel * std::abs(want)) << what;
}

// ---------------------------------------------------------------------------------------
// Eq. 11: eta -> n'

TEST(WarpEta, EndpointsAreUniformLispsmAndPsm) {
  const double n = 1.0, f = 100.0;
  EXPECT_TRUE(std::isinf(warp::nPrimeFromEta(-1.0, n, f)));
  EXPECT_DOUBLE_EQ(warp::nPrimeFromEta(0.0, n, f), 11.0);  // n + sqrt(f n) = 1 + 10
  EXPECT_DOUBLE_EQ(warp::nPrimeFromEta(1.0, n, f), 1.0);   // n (PSM)
  EXPECT_DOUBLE_EQ(warp::nPrimeFromEta(-0.5, n, f), 1.0 * (10.0 + 1.0 + 0.5 * 99.0) / 0.5);
  EXPECT_DOUBLE_EQ(warp::nPrimeFromEta(0.5, n, f), 11.0 / 6.0);
  double last = std::numeric_limits<double>::infinity();
  for (double eta = -0.99; eta <= 1.0; eta += 0.01) {
    const double np = warp::nPrimeFromEta(eta, n, f);
    EXPECT_LT(np, last) << eta;  // strictly decreasing from infinity to n
    EXPECT_NEAR(warp::etaFromNPrime(np, n, f), eta, 1e-12) << eta;
    last = np;
  }
}

TEST(WarpEta, InverseEndpointsAndRoundTripFromNPrime) {
  // Eq. 11 inverted (etaFromNPrime, what tsm publishes for its focus' n'): n' = infinity ->
  // -1 (uniform), n + sqrt(f n) -> 0 (LiSPSM), n -> 1 (PSM), exactly (0 within rounding of
  // the square root); n' -> eta -> n' round
  // trips on both branches (n' above and below n'_LiSPSM) over several f / n.
  for (const auto& [n, f] : {std::pair{1.0, 100.0}, {0.1, 1000.0}, {2.0, 3.0}}) {
    SCOPED_TRACE(f / n);
    const double lispsm = n + std::sqrt(f * n);
    EXPECT_EQ(warp::etaFromNPrime(std::numeric_limits<double>::infinity(), n, f), -1.0);
    EXPECT_NEAR(warp::etaFromNPrime(lispsm, n, f), 0.0, 1e-15);  // sqrt(f n) / n vs sqrt(f / n)
    EXPECT_EQ(warp::etaFromNPrime(n, n, f), 1.0);
    EXPECT_DOUBLE_EQ(warp::nPrimeFromEta(0.0, n, f), lispsm);
    EXPECT_DOUBLE_EQ(warp::nPrimeFromEta(1.0, n, f), n);
    for (double q = 1.0; q < 1e6; q *= 1.37) {  // n' from n to a million n
      const double np = q * n, eta = warp::etaFromNPrime(np, n, f);
      EXPECT_GE(eta, -1.0);
      EXPECT_LE(eta, 1.0);
      EXPECT_NEAR(warp::nPrimeFromEta(eta, n, f), np, 1e-9 * np) << "n' " << np;
      EXPECT_EQ(eta > 0.0, np < lispsm) << "branch at n' " << np;
    }
    // Far beyond: eta tends to -1 from above; below n (a TSM focus at the eye) eq. 11 has no
    // eta: it clamps to 1 (PSM).
    EXPECT_GT(warp::etaFromNPrime(1e12 * n, n, f), -1.0);
    EXPECT_LT(warp::etaFromNPrime(1e12 * n, n, f), -1.0 + 1e-6);
    EXPECT_EQ(warp::etaFromNPrime(0.5 * n, n, f), 1.0);
  }
}

TEST(WarpEta, TsmIsOneWarpWithItsEta) {
  // Lloyd et al. §4.3: a TSM is one perspective warp along light-space z, i.e. eq. 11 with
  // some eta. For random lights and focus fractions, the warp fitted with WarpKind::Eta at
  // the TSM fit's eta has the TSM's n' and the same M_x, M_z, S (1e-9 relative) - what the
  // Storage factor panel assumes when it analyses tsm by the eta it publishes, and why
  // `shadowlab-cli storage --scheme tsm` prints the same S as one warp at that eta.
  const ViewFrustum v = paperView(0.5, 60.0);
  std::mt19937 rng(2006);
  std::uniform_real_distribution<double> u(-1.0, 1.0), focus(0.05, 0.7);
  int compared = 0, beyondPsm = 0;
  for (int i = 0; i < 300; ++i) {
    const glm::dvec3 l(u(rng), std::abs(u(rng)) + 0.05, u(rng));
    SchemeSettings tsm = scheme(Scheme::Tsm);
    tsm.tsmFocusFraction = focus(rng);
    const StorageResult t = evaluate(v, l, tsm);
    const WarpFit& tf = t.parts[0].fit;
    if (!tf.warped()) continue;
    if (tf.eta >= 1.0) {  // n' below eq. 11's n: no eta reaches it (clamped, published as 1)
      ++beyondPsm;
      continue;
    }
    ++compared;
    SchemeSettings eta = scheme(Scheme::Eta);
    eta.eta = tf.eta;
    const StorageResult e = evaluate(v, l, eta);
    const WarpFit& ef = e.parts[0].fit;
    ASSERT_TRUE(ef.warped()) << i;
    EXPECT_NEAR(ef.nPrime, tf.nPrime, 1e-9 * tf.nPrime) << i;
    EXPECT_NEAR(e.s, t.s, 1e-9 * t.s) << i;
    EXPECT_NEAR(e.mx, t.mx, 1e-9 * t.mx) << i;
    EXPECT_NEAR(e.mz, t.mz, 1e-9 * t.mz) << i;
  }
  std::printf("TSM = one warp at its eta: %d lights compared, %d with n' < n (eta 1)\n", compared,
              beyondPsm);
  EXPECT_GT(compared, 150);
}

// ---------------------------------------------------------------------------------------
// Overhead light: the vertex method reproduces the closed forms

TEST(StorageOverhead, VertexMaximaAreEqs9To12) {
  for (double fov : {30.0, 60.0, 90.0})
    for (double f : {20.0, 100.0, 1000.0}) {
      const ViewFrustum v = paperView(1.0, f, fov);
      const double t = v.tanHalfY();
      for (double eta = -1.0; eta <= 1.0001; eta += 0.125) {
        const WarpFit fit = fitEta(v, eta);
        const double np = warp::nPrimeFromEta(eta, 1.0, f);
        if (eta > -1.0) expectRel(fit.nPrime, np, 1e-12, "n'");
        const Storage s = storageOfBody(v, fit, cornersOf(v));
        expectRel(s.mx, overhead::maxMx(np, 1.0, f), 1e-10, "M_x = eq. 9");
        expectRel(s.mz, overhead::maxMz(np, 1.0, f, t), 1e-10, "M_z = eq. 10");
        expectRel(s.s, overhead::storage(np, 1.0, f, t), 1e-10, "S = eq. 12");
      }
    }
}

TEST(StorageOverhead, ErrorInsideTheFrustumIsEqs7And8) {
  const ViewFrustum v = paperView(1.0, 20.0);  // the paper's Fig. 5 frustum
  std::mt19937 rng(2006);
  std::uniform_real_distribution<double> u(-1.0, 1.0), d(1.0, 20.0);
  for (double eta : {-0.7, -0.2, 0.0, 0.4, 1.0}) {
    const WarpFit fit = fitEta(v, eta);
    for (int i = 0; i < 200; ++i) {
      const double z = d(rng);
      const glm::dvec3 p(u(rng) * z * v.tanHalfX(), u(rng) * z * v.tanHalfY(), -z);
      const glm::dvec2 m = aliasingAt(v, fit, p);
      expectRel(m.x, overhead::mx(z, fit.nPrime, 1.0, 20.0), 1e-10, "m_x = eq. 7");
      expectRel(m.y, overhead::mz(z, fit.nPrime, 1.0, 20.0, v.tanHalfY()), 1e-10, "m_z = eq. 8");
    }
  }
}

TEST(StorageOverhead, MaxZErrorIsAtFarBelowLispsmAtNearAboveAndAtBothAtLispsm) {
  // §4.1: M_z lies at z = f for n' < n'_LiSPSM, at z = n above it, at both for n'_LiSPSM.
  const double n = 1.0, f = 100.0, t = std::tan(kPi / 6.0), nl = overhead::nPrimeLispsm(n, f);
  EXPECT_GT(overhead::mz(f, 0.5 * nl, n, f, t), overhead::mz(n, 0.5 * nl, n, f, t));
  EXPECT_LT(overhead::mz(f, 2.0 * nl, n, f, t), overhead::mz(n, 2.0 * nl, n, f, t));
  expectRel(overhead::mz(f, nl, n, f, t), overhead::mz(n, nl, n, f, t), 1e-12, "both ends");
}

TEST(StorageOverhead, StorageIsMinimalAndEqualForNPrimeUpToLispsm) {
  // §4.3: for n' <= n'_LiSPSM, S = (f/n - 1) / (2 tan theta) whatever n' (PSM = LiSPSM);
  // above it S grows monotonically to the uniform map's (f/n - 1) f / (2 n tan theta).
  const ViewFrustum v = paperView();
  const double t = v.tanHalfY(), minimal = (100.0 - 1.0) / (2.0 * t);
  for (double eta = 0.0; eta <= 1.0; eta += 0.05)
    expectRel(storageOfBody(v, fitEta(v, eta), cornersOf(v)).s, minimal, 1e-10, "eta >= 0");
  double last = minimal;
  for (double eta = -0.05; eta > -1.0; eta -= 0.05) {
    const double s = storageOfBody(v, fitEta(v, eta), cornersOf(v)).s;
    EXPECT_GT(s, last * (1.0 + 1e-9)) << eta;
    last = s;
  }
  const double uniform = evaluate(v, kOverhead, scheme(Scheme::Uniform)).s;
  expectRel(uniform, minimal * 100.0, 1e-10, "uniform = (f/n - 1) f / (2 n tan theta)");
  EXPECT_GT(uniform, last);
  const double psm = evaluate(v, kOverhead, scheme(Scheme::Psm)).s;
  const double lispsm = evaluate(v, kOverhead, scheme(Scheme::Lispsm)).s;
  expectRel(psm, minimal, 1e-10, "PSM");
  expectRel(lispsm, minimal, 1e-10, "LiSPSM");
  // With n = 1, f = 100, fov 60: S = 99 / (2 tan 30) = 85.7, uniform 8574 (100 times more).
  EXPECT_NEAR(minimal, 85.7365, 1e-4);
}

TEST(StorageOverhead, TsmEqualsTheOthersWhenItsNPrimeIsInTheMinimalRange) {
  // "some TSMs" (§4.3): a focus point near the viewer gives n' <= n'_LiSPSM; the middle of
  // the frustum gives n' = 0.2 L delta / (0.8 L - delta) = 33 > 11 and a larger S (eq. 12).
  const ViewFrustum v = paperView();
  const double t = v.tanHalfY();
  SchemeSettings near = scheme(Scheme::Tsm);
  near.tsmFocusFraction = 0.1;  // delta = 9.9: n' = 0.2*99*9.9/(79.2-9.9) = 2.83
  const StorageResult rn = evaluate(v, kOverhead, near);
  expectRel(rn.parts[0].fit.nPrime, 0.2 * 99.0 * 9.9 / (0.8 * 99.0 - 9.9), 1e-10, "TSM n'");
  EXPECT_LT(rn.parts[0].fit.nPrime, 11.0);
  expectRel(rn.s, 99.0 / (2.0 * t), 1e-10, "TSM S minimal");
  const StorageResult rm = evaluate(v, kOverhead, scheme(Scheme::Tsm));
  const double np = 0.2 * 99.0 * 49.5 / (0.8 * 99.0 - 49.5);
  expectRel(rm.parts[0].fit.nPrime, np, 1e-10, "TSM n' (focus in the middle)");
  expectRel(rm.s, overhead::storage(np, 1.0, 100.0, t), 1e-10, "TSM S = eq. 12");
  EXPECT_GT(rm.s, rn.s * 1.1);
  // The focus point maps to the 80 % line (t = 0.8).
  EXPECT_NEAR(rm.parts[0].fit.mapUv(glm::dvec3(0, 0, -50.5)).y, 0.8, 1e-12);
}

TEST(StorageOverhead, BudgetResolutionIsEqs13And14) {
  const ViewFrustum v = paperView();
  const Storage st = evaluate(v, kOverhead, scheme(Scheme::Lispsm)).parts[0].storage;
  const double image = 1000.0;  // res_i
  // The budget of a critical-resolution map: res = (M_x, M_z) res_i, error 1 in x and z.
  glm::dvec2 r = budgetResolution(st, st.s * image * image);
  expectRel(r.x, st.mx * image, 1e-12, "res_s critical");
  expectRel(r.y, st.mz * image, 1e-12, "res_t critical");
  // A quarter of it: the error doubles, equally in x and z.
  r = budgetResolution(st, 0.25 * st.s * image * image);
  expectRel(st.mx * image / r.x, 2.0, 1e-12, "M_x at a quarter budget");
  expectRel(st.mz * image / r.y, 2.0, 1e-12, "M_z at a quarter budget");
  expectRel(r.x * r.y, 0.25 * st.s * image * image, 1e-12, "res_s res_t = S0");
}

// ---------------------------------------------------------------------------------------
// z-partitioning (§5.2)

TEST(ZPartitioning, LogSplitGivesEqualErrorPerPartAndBeatsRandomSplits) {
  const ViewFrustum v = paperView(1.0, 1000.0);
  const double t = v.tanHalfY();
  std::mt19937 rng(42);
  for (bool warped : {true, false})
    for (int k = 2; k <= 6; ++k) {
      SchemeSettings s = scheme(Scheme::Cascades, k);
      s.partitionWarp = warped;
      const StorageResult log = evaluate(v, kOverhead, s);
      ASSERT_EQ(log.parts.size(), std::size_t(k));
      const double r = std::pow(1000.0, 1.0 / k);  // each part's far / near
      const double each = warped ? (r - 1.0) / (2.0 * t) : r * (r - 1.0) / (2.0 * t);
      for (const PartStorage& p : log.parts) expectRel(p.storage.s, each, 1e-9, "equal parts");
      expectRel(log.s, k * each, 1e-9, "sum");
      // Against random splits of the same k (uniform in log depth, then sorted).
      std::uniform_real_distribution<double> u(0.0, 1.0);
      for (int trial = 0; trial < 300; ++trial) {
        std::vector<double> q{0.0, 1.0};
        for (int i = 1; i < k; ++i) q.push_back(u(rng));
        std::sort(q.begin(), q.end());
        SchemeSettings rs = s;
        rs.customSplits.clear();
        for (double x : q) rs.customSplits.push_back(std::pow(1000.0, x));
        rs.customSplits.front() = 1.0;
        rs.customSplits.back() = 1000.0;
        EXPECT_GT(evaluate(v, kOverhead, rs).s, log.s) << "k " << k << " trial " << trial;
      }
      for (SplitScheme other : {SplitScheme::Uniform, SplitScheme::Practical}) {
        SchemeSettings os = s;
        os.split = other;
        EXPECT_GT(evaluate(v, kOverhead, os).s, log.s) << splitSchemeName(other) << " k " << k;
      }
    }
}

TEST(ZPartitioning, WarpedPartsBeatOrthographicParts) {
  // §5.2 / §7: z-partitioning combined with warping has the least error for a given k.
  const ViewFrustum v = paperView(1.0, 1000.0);
  for (int k = 1; k <= 8; ++k) {
    SchemeSettings s = scheme(Scheme::Cascades, k);
    const double warped = evaluate(v, kOverhead, s).s;
    s.partitionWarp = false;
    EXPECT_LT(warped, evaluate(v, kOverhead, s).s) << k;
  }
}

// ---------------------------------------------------------------------------------------
// Light behind / in front of the viewer (§4.4, Fig. 7) and face partitioning (§5.1)

TEST(FacePartitioning, LightBehindOrInFrontRevertsToUniformAndFacesLowerStorage) {
  const ViewFrustum v = paperView();
  for (double sign : {1.0, -1.0})  // behind, in front
    for (double elev : {0.0, 10.0, 25.0}) {
      glm::dvec3 l = lightBehind(elev);
      l.z *= sign;
      const StorageResult lis = evaluate(v, l, scheme(Scheme::Lispsm));
      const StorageResult uni = evaluate(v, l, scheme(Scheme::Uniform));
      ASSERT_TRUE(lis.parts[0].fit.fallback) << elev;
      EXPECT_FALSE(lis.parts[0].fit.fallbackReason.empty());
      EXPECT_EQ(lis.parts[0].fit.lightBehindViewer, sign > 0);
      EXPECT_DOUBLE_EQ(lis.s, uni.s) << "LiSPSM reverts to uniform, elevation " << elev;
      const StorageResult face = evaluate(v, l, scheme(Scheme::Face));
      EXPECT_GE(face.parts.size(), 4u);
      EXPECT_LT(face.s, 0.5 * lis.s) << "face partitioning, elevation " << elev << " sign " << sign;
    }
}

TEST(FacePartitioning, OverheadLightUsesTheBottomFaceWithTheViewAxis) {
  const ViewFrustum v = paperView();
  const auto parts = facePartitions(v, v.nearM, v.farM, kOverhead);
  ASSERT_EQ(parts.size(), 1u);  // v . y = 0: back faces, only the bottom one is seen
  EXPECT_EQ(parts[0].face, 4);
  EXPECT_EQ(parts[0].body.size(), 8u);
  ASSERT_TRUE(parts[0].bisector);
  EXPECT_NEAR(glm::length(*parts[0].bisector - v.forward), 0.0, 1e-12);
}

TEST(FacePartitioning, PartitionsCoverTheFrustumOnce) {
  // Every point of the frustum lies in exactly one partition: its projection along the
  // light lands in exactly one partition's projection (the front or back faces tile the
  // frustum's silhouette).
  const ViewFrustum v = paperView(1.0, 10.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0), d(1.0, 10.0);
  for (const glm::dvec3& l :
       {lightBehind(20.0), glm::dvec3(0.3, 0.8, -0.5), glm::dvec3(0.9, 0.2, 0.1)}) {
    const auto parts = facePartitions(v, 1.0, 10.0, l);
    ASSERT_FALSE(parts.empty());
    for (int i = 0; i < 300; ++i) {
      const double z = d(rng);
      const glm::dvec3 p(u(rng) * z * v.tanHalfX(), u(rng) * z * v.tanHalfY(), -z);
      int inside = 0;
      for (const FacePartition& fp : parts) {
        // In the partition: p's projection along the light lands in the projection of the
        // partition's vertices (a 2D convex hull).
        const glm::dvec3 y = glm::normalize(l);
        const glm::dvec3 xAxis = glm::normalize(
            glm::cross(y, std::abs(y.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1)));
        const glm::dvec3 zAxis = glm::cross(xAxis, y);
        std::vector<glm::dvec2> q;
        for (const glm::dvec3& b : fp.body) q.push_back({glm::dot(b, xAxis), glm::dot(b, zAxis)});
        const glm::dvec2 pp(glm::dot(p, xAxis), glm::dot(p, zAxis));
        // 2D hull containment: pp is inside when no hull edge separates it (all points on
        // one side of every line through two hull points that has all points on one side).
        bool in = true;
        for (std::size_t a = 0; a < q.size() && in; ++a)
          for (std::size_t b = 0; b < q.size() && in; ++b) {
            if (a == b) continue;
            const glm::dvec2 e = q[b] - q[a];
            bool allLeft = true;
            for (const glm::dvec2& r : q) {
              const double c = e.x * (r.y - q[a].y) - e.y * (r.x - q[a].x);
              allLeft = allLeft && c >= -1e-9;
            }
            if (allLeft && e.x * (pp.y - q[a].y) - e.y * (pp.x - q[a].x) < -1e-9) in = false;
          }
        inside += in;
      }
      EXPECT_EQ(inside, 1) << "point " << i;
    }
  }
}

// ---------------------------------------------------------------------------------------
// The fitted matrices

TEST(WarpFitMatrices, CoverTheBodyAndAgreeWithTheAnalysis) {
  const ViewFrustum v = paperView(0.5, 60.0);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int warped = 0;
  for (int i = 0; i < 200; ++i) {
    glm::dvec3 l(u(rng), std::abs(u(rng)) + 0.05, u(rng));
    for (WarpKind kind : {WarpKind::Uniform, WarpKind::Lispsm, WarpKind::Psm, WarpKind::Tsm}) {
      WarpSettings ws;
      ws.kind = kind;
      WarpFit fit;
      ASSERT_FALSE(warp::fitWarp(v, cornersOf(v), l, ws, fit));
      warped += fit.warped();
      const glm::dmat4 m = glm::dmat4(fit.lightProj) * glm::dmat4(fit.lightView);
      for (const glm::dvec3& p : cornersOf(v)) {
        const glm::dvec4 c = m * glm::dvec4(p, 1.0);
        ASSERT_GT(c.w, 0.0);
        const glm::dvec3 ndc = glm::dvec3(c) / c.w;
        for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(ndc[k]), 1.0 + 1e-4) << i;
        const glm::dvec2 uv = fit.mapUv(p);
        EXPECT_NEAR(0.5 * ndc.x + 0.5, uv.x, 1e-4);
        EXPECT_NEAR(0.5 * ndc.y + 0.5, uv.y, 1e-4);
        // Beam widths: the inverse derivatives of (s, t) along light-space x and z.
        const double h = 1e-4;
        const glm::dvec2 ds =
            (fit.mapUv(p + h * fit.space.x) - fit.mapUv(p - h * fit.space.x)) / (2 * h);
        const glm::dvec2 dt =
            (fit.mapUv(p + h * fit.space.z) - fit.mapUv(p - h * fit.space.z)) / (2 * h);
        const glm::dvec2 w = fit.beamWidths(p);
        EXPECT_NEAR(1.0 / ds.x, w.x, 1e-5 * w.x);
        EXPECT_NEAR(1.0 / dt.y, w.y, 1e-5 * w.y);
      }
    }
  }
  EXPECT_GT(warped, 300);  // most random lights are warped
}

TEST(WarpFit, PsmSingularityIsClampedAndReported) {
  ViewFrustum v = paperView(1e-6, 100.0);  // n -> 0: PSM's n' = n -> 0
  WarpSettings ws;
  ws.kind = WarpKind::Psm;
  WarpFit fit;
  ASSERT_FALSE(warp::fitWarp(v, cornersOf(v), kOverhead, ws, fit));
  EXPECT_TRUE(fit.nearClamped);
  EXPECT_NEAR(fit.nPrime, 1e-3 * fit.depthM, 1e-12);
  EXPECT_FALSE(fit.note.empty());
}

TEST(WarpFit, BadInputIsNamed) {
  const ViewFrustum v = paperView();
  WarpFit fit;
  WarpSettings ws;
  ws.kind = WarpKind::Eta;
  ws.eta = 1.5;
  EXPECT_EQ(*warp::fitWarp(v, cornersOf(v), kOverhead, ws, fit), "warp: eta must be in [-1, 1]");
  EXPECT_TRUE(warp::fitWarp(v, {}, kOverhead, WarpSettings{}, fit));
  EXPECT_TRUE(warp::fitWarp(v, cornersOf(v), glm::dvec3(0.0), WarpSettings{}, fit));
  ViewFrustum bad = v;
  bad.farM = 0.5;
  EXPECT_TRUE(warp::fitWarp(bad, cornersOf(v), kOverhead, WarpSettings{}, fit));
}

// ---------------------------------------------------------------------------------------
// Split schemes and stable cascades

TEST(Splits, UniformLogPractical) {
  const auto u = splitDistances(SplitScheme::Uniform, 1.0, 9.0, 4);
  EXPECT_EQ(u, (std::vector<double>{1.0, 3.0, 5.0, 7.0, 9.0}));
  const auto l = splitDistances(SplitScheme::Log, 1.0, 10000.0, 4);
  ASSERT_EQ(l.size(), 5u);
  for (int i = 0; i <= 4; ++i) EXPECT_NEAR(l[std::size_t(i)], std::pow(10.0, i), 1e-9);
  const auto p = splitDistances(SplitScheme::Practical, 1.0, 10000.0, 4, 0.25);
  for (int i = 0; i <= 4; ++i)
    EXPECT_NEAR(p[std::size_t(i)], 0.25 * std::pow(10.0, i) + 0.75 * (1.0 + 9999.0 * i / 4.0),
                1e-9);
  EXPECT_EQ(splitDistances(SplitScheme::Practical, 1.0, 50.0, 3, 1.0),
            splitDistances(SplitScheme::Log, 1.0, 50.0, 3));
  EXPECT_THROW(splitDistances(SplitScheme::Log, 0.0, 10.0, 2), std::invalid_argument);
  EXPECT_THROW(splitDistances(SplitScheme::Log, 1.0, 10.0, 0), std::invalid_argument);
  EXPECT_THROW(splitDistances(SplitScheme::Practical, 1.0, 10.0, 2, 1.5), std::invalid_argument);
}

TEST(StableCascades, TranslationMovesTheFrustumByWholeTexelsAndRotationKeepsItsSize) {
  ViewFrustum v = paperView(0.1, 50.0, 50.0);
  const glm::dvec3 light = glm::normalize(glm::dvec3(0.4, 0.8, 0.3));
  StableOrtho base;
  ASSERT_FALSE(stabilizeCascade(v, 2.0, 8.0, light, 1024, 0.5, 10.0, base));
  EXPECT_NEAR(std::fmod(base.extentM, 0.5), 0.0, 1e-12);
  EXPECT_GE(base.extentM, 2.0 * base.sphereRadiusM);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-20.0, 20.0), a(-kPi, kPi);
  for (int i = 0; i < 100; ++i) {
    ViewFrustum moved = v;
    moved.eye += glm::dvec3(u(rng), 0.1 * u(rng), u(rng));
    StableOrtho s;
    ASSERT_FALSE(stabilizeCascade(moved, 2.0, 8.0, light, 1024, 0.5, 10.0, s));
    EXPECT_DOUBLE_EQ(s.extentM, base.extentM);
    for (int k = 0; k < 2; ++k) {
      const double texels = (s.minXY[k] - base.minXY[k]) / base.texelM;
      EXPECT_NEAR(texels, std::round(texels), 1e-6) << i;
    }
    // A turned camera: same extent (bounding sphere), and the slice stays inside.
    ViewFrustum turned = moved;
    const double yaw = a(rng), pitch = 0.4 * a(rng);
    turned.forward = glm::dvec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                                -std::cos(pitch) * std::cos(yaw));
    turned.up = glm::normalize(glm::dvec3(0, 1, 0) - turned.forward.y * turned.forward);
    ASSERT_FALSE(stabilizeCascade(turned, 2.0, 8.0, light, 1024, 0.5, 10.0, s));
    EXPECT_DOUBLE_EQ(s.extentM, base.extentM);
    const glm::dmat4 m = glm::dmat4(s.proj) * glm::dmat4(s.view);
    for (const glm::dvec3& p : turned.corners(2.0, 8.0)) {
      const glm::dvec4 c = m * glm::dvec4(p, 1.0);
      for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(c[k] / c.w), 1.0 + 1e-5);
    }
  }
  StableOrtho s;
  EXPECT_EQ(*stabilizeCascade(v, 8.0, 2.0, light, 1024, 0.5, 0.0, s),
            "cascade: need 0 < slice near < slice far (finite)");
}

}  // namespace
}  // namespace sl::partition
