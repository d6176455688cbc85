// algo/omni/LatLongMapping: the poles, the seam at ±180°, round trips of directions and
// texels, the halves' continuous uv, the sampling density (the top row's texels are
// cot(pi / 2H) times smaller than the equator's, growing with the resolution, where the
// cube's and the paraboloid's ratios are fixed; at equal memory the lat-long map's sparsest
// direction is the densest of the three), and the bounds of triangles' images (seam, poles,
// edges bulging towards a pole).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "algo/omni/LatLongMapping.h"
#include "algo/omni/OmniMapping.h"

namespace sl::omni {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<glm::dvec3> sphereDirections(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  std::vector<glm::dvec3> dirs;
  for (int i = 0; i < n; ++i) {
    glm::dvec3 d(g(rng), g(rng), g(rng));
    if (glm::length(d) > 1e-6) dirs.push_back(glm::normalize(d));
  }
  return dirs;
}

TEST(LatLong, FrameIsRightHandedAboutThePole) {
  for (const glm::dvec3& pole : {glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1),
                                 glm::normalize(glm::dvec3(1, -2, 0.5))}) {
    const LatLongFrame f = latLongFrame(pole);
    EXPECT_NEAR(glm::length(glm::cross(f.x, f.y) - f.pole), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(f.x, f.pole), 0.0, 1e-12);
  }
  // The default pole y: longitude 0 along +x as for the paraboloid's frame about y.
  const LatLongFrame f = latLongFrame({0, 1, 0});
  EXPECT_NEAR(glm::length(f.x - glm::dvec3(1, 0, 0)), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(f.y - glm::dvec3(0, 0, -1)), 0.0, 1e-12);
}

TEST(LatLong, PolesAreTheTopAndBottomRows) {
  const LatLongFrame f = latLongFrame({0, 1, 0});
  const int h = 64;
  EXPECT_DOUBLE_EQ(latLong(f, {0, 1, 0}).latitudeRad, 0.5 * kPi);
  EXPECT_DOUBLE_EQ(latLong(f, {0, -3, 0}).latitudeRad, -0.5 * kPi);
  EXPECT_DOUBLE_EQ(latLongUv(f, {0, 1, 0}).y, 1.0);
  EXPECT_DOUBLE_EQ(latLongUv(f, {0, -1, 0}).y, 0.0);
  EXPECT_EQ(latLongTexel(f, {0, 1, 0}, h).y, h - 1);
  EXPECT_EQ(latLongTexel(f, {0, -1, 0}, h).y, 0);
  // Every column of the top row reaches the pole: its texel centres all lie half a row
  // (pi / 2H) from it.
  for (int x = 0; x < 2 * h; x += 7) {
    const glm::dvec3 d = latLongTexelCentreDirection(f, {x, h - 1}, h);
    EXPECT_NEAR(std::acos(glm::dot(d, f.pole)), 0.5 * kPi / h, 1e-12);
  }
  EXPECT_TRUE(std::isinf(latLongTexelsPerSteradian(f, {0, 1, 0}, h)));
  // A PCF tap one row over the north pole is the texel half way round, same row.
  EXPECT_EQ(latLongWrapTexel({3, h}, h), glm::ivec2(3 + h, h - 1));
  EXPECT_EQ(latLongWrapTexel({h + 5, -2}, h), glm::ivec2(5, 1));
}

TEST(LatLong, SeamIsAtPlusMinus180Degrees) {
  const LatLongFrame f = latLongFrame({0, 1, 0});
  const int h = 32, w = 2 * h;
  // -x is longitude +180° (u = 1, which wraps to column 0); just either side of it the
  // first and the last column.
  EXPECT_DOUBLE_EQ(latLong(f, -f.x).longitudeRad, kPi);
  EXPECT_DOUBLE_EQ(latLongUv(f, -f.x).x, 1.0);
  EXPECT_EQ(latLongTexel(f, -f.x, h).x, 0);
  const glm::dvec3 justBelow = -f.x + 1e-6 * f.y, justAbove = -f.x - 1e-6 * f.y;
  EXPECT_NEAR(latLongUv(f, justBelow).x, 1.0, 1e-6);
  EXPECT_NEAR(latLongUv(f, justAbove).x, 0.0, 1e-6);
  EXPECT_EQ(latLongTexel(f, justBelow, h).x, w - 1);
  EXPECT_EQ(latLongTexel(f, justAbove, h).x, 0);
  EXPECT_EQ(latLongWrapTexel({w, 5}, h), glm::ivec2(0, 5));
  EXPECT_EQ(latLongWrapTexel({-1, 5}, h), glm::ivec2(w - 1, 5));
  // Half 0's uv continues across the seam: longitude 180° - eps is u = -eps / pi there.
  EXPECT_EQ(latLongHalfUv(f, justBelow).half, 1);
  EXPECT_EQ(latLongHalfUv(f, justAbove).half, 0);
  EXPECT_NEAR(latLongUvInHalf(f, 0, justBelow).x, -1e-6 / kPi, 1e-9);
  EXPECT_NEAR(latLongUvInHalf(f, 1, justAbove).x, 1.0 + 1e-6 / kPi, 1e-9);
}

TEST(LatLong, DirectionsAndTexelsRoundTrip) {
  for (const glm::dvec3& pole : {glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(1, 2, -3))}) {
    const LatLongFrame f = latLongFrame(pole);
    for (const glm::dvec3& d : sphereDirections(2000, 7)) {
      EXPECT_NEAR(glm::length(latLongUvDirection(f, latLongUv(f, d)) - d), 0.0, 1e-12);
      const LatLongHalfCoord hc = latLongHalfUv(f, d);
      const glm::dvec2 uv = latLongUv(f, d);
      EXPECT_NEAR(hc.uv.x, 2.0 * uv.x - hc.half, 1e-12);
      EXPECT_NEAR(hc.uv.y, uv.y, 1e-12);
      EXPECT_NEAR(glm::length(latLongUvInHalf(f, hc.half, d) - hc.uv), 0.0, 1e-12);
    }
    const int h = 48;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < 2 * h; ++x)
        ASSERT_EQ(latLongTexel(f, latLongTexelCentreDirection(f, {x, y}, h), h), glm::ivec2(x, y));
  }
}

TEST(LatLong, TexelSolidAnglesSumToTheSphereAndMatchTheDensity) {
  const LatLongFrame f = latLongFrame({0, 1, 0});
  for (int h : {16, 256, 1024}) {
    double total = 0.0;
    for (int y = 0; y < h; ++y) total += 2.0 * h * latLongTexelSolidAngle(y, h);
    EXPECT_NEAR(total, 4.0 * kPi, 1e-10);
    // Away from the poles the density at a texel's centre is 1 / its solid angle, to
    // second order in the texel's size.
    for (int y : {h / 2, h / 4, h / 16}) {
      const double density =
          latLongTexelsPerSteradian(f, latLongTexelCentreDirection(f, {0, y}, h), h);
      EXPECT_NEAR(density * latLongTexelSolidAngle(y, h), 1.0, 2.0 / (double(h) * h) * 20.0);
    }
  }
}

TEST(LatLong, PolesOversampleByAFactorThatGrowsWithResolution) {
  // Top row against the row above the equator: cot(pi / 2H), about 2H / pi; the cube's
  // corner / centre ratio stays 3√3 and the paraboloid's rim / centre 4 at any resolution.
  for (int h : {64, 512, 2048}) {
    const double ratio = latLongTexelSolidAngle(h / 2, h) / latLongTexelSolidAngle(h - 1, h);
    EXPECT_NEAR(ratio, 1.0 / std::tan(kPi / (2.0 * h)), 1e-9 * ratio);
    EXPECT_GT(ratio, 0.63 * h);
  }
  const glm::dvec3 corner = glm::normalize(glm::dvec3(1, 1, 1));
  EXPECT_NEAR(cubeTexelsPerSteradian(corner, 512) / cubeTexelsPerSteradian({1, 0, 0}, 512),
              3.0 * std::sqrt(3.0), 1e-9);
}

TEST(LatLong, AtEqualMemoryItsSparsestDirectionIsTheDensestOfTheThree) {
  // N texels in all: cube 6 r^2 (sparsest at a face's centre, (r/2)^2 = N / 24), dual
  // paraboloid 2 r^2 (at a disc's centre, r^2 / 16 = N / 32; the corners outside the disc
  // are wasted), lat-long 2 H^2 (on the equator, H^2 / pi^2 = N / (2 pi^2) = N / 19.7).
  const double n = 6.0 * 1024.0 * 1024.0;
  const int cubeRes = 1024;
  const double h = std::sqrt(n / 2.0);  // lat-long height and paraboloid resolution
  const LatLongFrame f = latLongFrame({0, 1, 0});
  const ParaboloidFrame pf = paraboloidFrame({0, 1, 0});
  double sphMin = 1e300, cubeMin = 1e300, dpMin = 1e300;
  for (const glm::dvec3& d : sphereDirections(20000, 3)) {
    const double hh = h;
    sphMin = std::min(sphMin, hh * hh / (kPi * kPi * std::cos(latLong(f, d).latitudeRad)));
    cubeMin = std::min(cubeMin, cubeTexelsPerSteradian(d, cubeRes));
    const double c = std::abs(glm::dot(d, pf.axis));
    dpMin = std::min(dpMin, hh * hh / 4.0 / ((1.0 + c) * (1.0 + c)));
  }
  EXPECT_NEAR(sphMin / n, 1.0 / (2.0 * kPi * kPi), 1e-4);
  EXPECT_NEAR(cubeMin / n, 1.0 / 24.0, 1e-3);
  EXPECT_NEAR(dpMin / n, 1.0 / 32.0, 1e-3);
  EXPECT_GT(sphMin, 1.2 * cubeMin);
  EXPECT_GT(cubeMin, 1.3 * dpMin);
}

TEST(LatLong, RayTriangleDistance) {
  const glm::dvec3 a(-1, -2, -1), b(1, -2, -1), c(0, -2, 1);
  EXPECT_DOUBLE_EQ(rayTriangleDistance({0, 0, 0}, {0, -1, 0}, a, b, c), 2.0);
  EXPECT_EQ(rayTriangleDistance({0, 0, 0}, {0, 1, 0}, a, b, c), -1.0);  // behind
  EXPECT_EQ(rayTriangleDistance({3, 0, 0}, {0, -1, 0}, a, b, c), -1.0);
  // On an edge: a hit only with the tolerance.
  const glm::dvec3 onEdge = glm::normalize(glm::dvec3(0, -2, -1));
  EXPECT_GT(rayTriangleDistance({0, 0, 0}, onEdge, a, b, c, 1e-9), 0.0);
}

/// Longitude `lon` brought into [lonMin, lonMax] by whole turns, if any brings it there.
bool longitudeInside(double lon, const LatLongBounds& b, double eps) {
  for (int k = -2; k <= 2; ++k) {
    const double l = lon + 2.0 * kPi * k;
    if (l >= b.lonMinRad - eps && l <= b.lonMaxRad + eps) return true;
  }
  return false;
}

TEST(LatLong, TriangleBoundsHoldEveryPointAndAreTight) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> pos(-3.0, 3.0), bary(0.0, 1.0);
  const glm::dvec3 light(0.2, 0.5, -0.1);
  const std::vector<glm::dvec3> dirs = sphereDirections(40000, 5);
  for (const glm::dvec3& pole : {glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(1, 1, 0))}) {
    const LatLongFrame f = latLongFrame(pole);
    int seamCrossing = 0, withPole = 0;
    for (int t = 0; t < 400; ++t) {
      const glm::dvec3 a(pos(rng), pos(rng), pos(rng)), b(pos(rng), pos(rng), pos(rng)),
          c(pos(rng), pos(rng), pos(rng));
      const LatLongBounds bd = latLongTriangleBounds(f, light, a, b, c);
      if (!bd.valid) continue;
      seamCrossing += bd.lonMinRad < -kPi || bd.lonMaxRad > kPi;
      withPole += bd.pole != 0;
      double latLo = 1e9, latHi = -1e9;
      for (int s = 0; s < 3000; ++s) {
        double u = bary(rng), v = bary(rng);
        if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
        if (s % 4 == 1) v = 0.0;  // on the edges, where the bulges are
        if (s % 4 == 2) u = 0.0;
        if (s % 4 == 3) v = 1.0 - u;
        const glm::dvec3 p = a + u * (b - a) + v * (c - a);
        const LatLong ll = latLong(f, p - light);
        ASSERT_GE(ll.latitudeRad, bd.latMinRad - 1e-9);
        ASSERT_LE(ll.latitudeRad, bd.latMaxRad + 1e-9);
        ASSERT_TRUE(longitudeInside(ll.longitudeRad, bd, 1e-9)) << t;
        latLo = std::min(latLo, ll.latitudeRad);
        latHi = std::max(latHi, ll.latitudeRad);
      }
      // Tight: directions that hit the triangle (a uniform sample of the sphere, where
      // points spread over its plane thin out near the light) come close to both bounds.
      if (t % 4 == 0) {
        for (const glm::dvec3& d : dirs) {
          if (rayTriangleDistance(light, d, a, b, c) < 0.0) continue;
          const LatLong ll = latLong(f, d);
          ASSERT_GE(ll.latitudeRad, bd.latMinRad - 1e-9);
          ASSERT_LE(ll.latitudeRad, bd.latMaxRad + 1e-9);
          ASSERT_TRUE(longitudeInside(ll.longitudeRad, bd, 1e-9)) << t;
          latLo = std::min(latLo, ll.latitudeRad);
          latHi = std::max(latHi, ll.latitudeRad);
        }
        EXPECT_LT(latLo - bd.latMinRad, 0.03) << t;
        EXPECT_LT(bd.latMaxRad - latHi, 0.03) << t;
      }
    }
    EXPECT_GT(seamCrossing, 5);
    EXPECT_GT(withPole, 5);
  }
}

TEST(LatLong, FloorUnderTheLightHoldsTheSouthPoleAndAnEdgeBulges) {
  const LatLongFrame f = latLongFrame({0, 1, 0});
  const glm::dvec3 light(0, 2, 0);
  const LatLongBounds floor = latLongTriangleBounds(f, light, {-5, 0, -5}, {5, 0, -5}, {0, 0, 5});
  ASSERT_TRUE(floor.valid);
  EXPECT_EQ(floor.pole, -1);
  EXPECT_DOUBLE_EQ(floor.latMinRad, -0.5 * kPi);
  EXPECT_DOUBLE_EQ(floor.lonMinRad, -kPi);
  EXPECT_DOUBLE_EQ(floor.lonMaxRad, kPi);
  // A ceiling edge from longitude 0 to longitude 170°, both ends 30° up: the arc passes
  // near the pole, far above its ends (its highest point: the ends' common latitude over
  // the cosine of half the longitude difference).
  const double lat = kPi / 6.0, dLon = 170.0 * kPi / 180.0;
  const glm::dvec3 p = latLongDirection(f, {0.0, lat}), q = latLongDirection(f, {dLon, lat});
  const glm::dvec3 r = latLongDirection(f, {0.5 * dLon, -0.3});
  const LatLongBounds ceil = latLongTriangleBounds(f, {0, 0, 0}, p, q, r);
  ASSERT_TRUE(ceil.valid);
  EXPECT_EQ(ceil.pole, 0);
  EXPECT_NEAR(ceil.latMaxRad, std::atan(std::tan(lat) / std::cos(0.5 * dLon)), 1e-12);
  EXPECT_GT(ceil.latMaxRad, 1.4);
  // Crossing the seam: vertices at ±170° give a 20° range across 180°.
  const glm::dvec3 s = latLongDirection(f, {170.0 * kPi / 180.0, 0.1});
  const glm::dvec3 t = latLongDirection(f, {-170.0 * kPi / 180.0, 0.1});
  const glm::dvec3 m = latLongDirection(f, {kPi, -0.2});
  const LatLongBounds seam = latLongTriangleBounds(f, {0, 0, 0}, s, t, m);
  ASSERT_TRUE(seam.valid);
  EXPECT_NEAR(seam.lonMinRad, 170.0 * kPi / 180.0, 1e-12);
  EXPECT_NEAR(seam.lonMaxRad, 190.0 * kPi / 180.0, 1e-12);
}

}  // namespace
}  // namespace sl::omni
