// algo/omni: the cube's face selection, uv and texel round trips, agreement with the
// technique's glm::lookAt + 90° perspective per face, the faces a spot cone reaches, the
// dual paraboloid's mapping and inverse, and both sampling densities (the analytic ratios:
// cube corner / centre = 3√3, paraboloid rim / centre = 4; each integrates to the texel count).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "algo/omni/OmniMapping.h"

namespace sl::omni {
namespace {

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

TEST(OmniCube, FaceSelectionIsTheMajorAxis) {
  EXPECT_EQ(selectCubeFace({1, 0.2, -0.3}), 0);
  EXPECT_EQ(selectCubeFace({-1, 0.2, -0.3}), 1);
  EXPECT_EQ(selectCubeFace({0.1, 2, -0.3}), 2);
  EXPECT_EQ(selectCubeFace({0.1, -2, -0.3}), 3);
  EXPECT_EQ(selectCubeFace({0.1, 0.2, 3}), 4);
  EXPECT_EQ(selectCubeFace({0.1, 0.2, -3}), 5);
  // Ties: x before y before z.
  EXPECT_EQ(selectCubeFace({1, 1, 1}), 0);
  EXPECT_EQ(selectCubeFace({0, -1, 1}), 3);
  for (int f = 0; f < kCubeFaces; ++f) {
    const CubeFaceBasis b = cubeFaceBasis(f);
    EXPECT_EQ(selectCubeFace(b.forward), f);
    // Right-handed as glm::lookAt builds it: right = forward x up.
    EXPECT_NEAR(glm::length(glm::cross(b.forward, b.up) - b.right), 0.0, 1e-15) << f;
    const CubeCoord c = cubeFaceUv(b.forward);
    EXPECT_EQ(c.uv, glm::dvec2(0.5));
  }
}

TEST(OmniCube, UvAndTexelRoundTrips) {
  for (const glm::dvec3& d : sphereDirections(20000, 1)) {
    const CubeCoord c = cubeFaceUv(d);
    ASSERT_GE(c.uv.x, 0.0);
    ASSERT_LE(c.uv.x, 1.0);
    ASSERT_GE(c.uv.y, 0.0);
    ASSERT_LE(c.uv.y, 1.0);
    EXPECT_NEAR(glm::length(cubeDirection(c.face, c.uv) - d), 0.0, 1e-12);
  }
  for (int res : {1, 7, 1024}) {
    for (const glm::dvec3& d : sphereDirections(2000, 2)) {
      const CubeTexel t = cubeTexel(d, res);
      const CubeTexel back = cubeTexel(cubeTexelCentreDirection(t, res), res);
      EXPECT_EQ(back.face, t.face);
      EXPECT_EQ(back.texel, t.texel);
    }
  }
}

TEST(OmniCube, UvEqualsTheFacesPerspectiveProjection) {
  // The technique renders face f through cubeFaceView and a 90° glm::perspective: the
  // projected uv of a point must be cubeFaceUv of its direction from the light.
  const glm::vec3 light(0.3f, 1.7f, -0.4f);
  const glm::mat4 proj = glm::perspective(glm::radians(90.0f), 1.0f, 0.05f, 20.0f);
  for (const glm::dvec3& d : sphereDirections(5000, 3)) {
    const CubeCoord c = cubeFaceUv(d);
    const glm::vec3 P = light + 3.0f * glm::vec3(d);
    const glm::vec4 clip = proj * cubeFaceView(c.face, light) * glm::vec4(P, 1.0f);
    const glm::dvec2 uv = glm::dvec2(clip.x, clip.y) / double(clip.w) * 0.5 + 0.5;
    EXPECT_NEAR(uv.x, c.uv.x, 2e-6);
    EXPECT_NEAR(uv.y, c.uv.y, 2e-6);
  }
}

TEST(OmniCube, DensityCornerOverCentreIsThreeRootThree) {
  const int res = 1024;
  const double centre = cubeTexelsPerSteradian({0, 0, -1}, res);
  EXPECT_DOUBLE_EQ(centre, 512.0 * 512.0);
  const double corner = cubeTexelsPerSteradian({1, 1, 1}, res);
  EXPECT_NEAR(corner / centre, 3.0 * std::sqrt(3.0), 1e-12);
  // Edge midpoint: r = √2.
  EXPECT_NEAR(cubeTexelsPerSteradian({1, 0, 1}, res) / centre, 2.0 * std::sqrt(2.0), 1e-12);
  // The density integrates to the texel count: the sum over every texel centre of
  // (solid angle of the texel) = 4 pi, with solid angle ~ 1 / density.
  const int n = 64;
  double omega = 0.0;
  for (int f = 0; f < kCubeFaces; ++f)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        omega += 1.0 / cubeTexelsPerSteradian(cubeTexelCentreDirection({f, {x, y}}, n), n);
  EXPECT_NEAR(omega, 4.0 * std::numbers::pi, 1e-3);
}

TEST(OmniCube, FacesInASpotCone) {
  const double deg = std::numbers::pi / 180.0;
  // Straight down: -y alone below 45°, the four sides join above.
  EXPECT_EQ(cubeFacesInCone({0, -1, 0}, 44.0 * deg), 1u << 3);
  EXPECT_EQ(cubeFacesInCone({0, -1, 0}, 46.0 * deg), (1u << 3) | 0b110011u);
  // Along a cube diagonal: the three faces meeting at that corner, whatever the angle.
  const glm::dvec3 diag = glm::normalize(glm::dvec3(1, 1, -1));
  EXPECT_EQ(cubeFacesInCone(diag, 1.0 * deg), (1u << 0) | (1u << 2) | (1u << 5));
  // Brute force: a face is in the mask iff some sampled direction of the cone is on it
  // (sampling can only miss faces the cone barely grazes).
  const auto dirs = sphereDirections(60000, 4);
  for (const glm::dvec3& axis : sphereDirections(40, 5)) {
    for (double half : {10.0, 30.0, 50.0, 80.0}) {
      const std::uint32_t mask = cubeFacesInCone(axis, half * deg);
      std::uint32_t sampled = 0;
      for (const glm::dvec3& d : dirs)
        if (glm::dot(d, axis) > std::cos(half * deg)) sampled |= 1u << selectCubeFace(d);
      EXPECT_EQ(sampled & ~mask, 0u) << "a sampled face is missing from the mask";
      for (int f = 0; f < kCubeFaces; ++f)
        if ((mask & ~sampled) & (1u << f)) {
          EXPECT_GT(cubeFaceAngularDistance(f, axis), half * deg - 2.0 * deg)
              << "face " << f << " in the mask, far inside the cone, yet never sampled";
        }
    }
  }
}

TEST(OmniCube, AngularDistanceToAFace) {
  const double deg = std::numbers::pi / 180.0;
  EXPECT_DOUBLE_EQ(cubeFaceAngularDistance(0, {1, 0.3, -0.2}), 0.0);
  // From straight down to +x: the side plane x = |y| at 45°.
  EXPECT_NEAR(cubeFaceAngularDistance(0, {0, -1, 0}), 45.0 * deg, 1e-12);
  // From -x to +x: the nearest directions are the four edge rays, acos(-1/√3) = 125.26°.
  EXPECT_NEAR(cubeFaceAngularDistance(0, {-1, 0, 0}), std::acos(-1.0 / std::sqrt(3.0)), 1e-12);
}

TEST(OmniParaboloid, MappingAndInverseRoundTrip) {
  for (const glm::dvec3& axis : {glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(0.3, -1, 0.5))}) {
    const ParaboloidFrame f = paraboloidFrame(axis);
    EXPECT_NEAR(glm::length(glm::cross(f.x, f.y) - f.axis), 0.0, 1e-15);
    EXPECT_EQ(paraboloidUv(f, axis).half, 0);
    EXPECT_NEAR(glm::length(paraboloidUv(f, axis).uv - glm::dvec2(0.5)), 0.0, 1e-15);
    EXPECT_EQ(paraboloidUv(f, -axis).half, 1);
    for (const glm::dvec3& d : sphereDirections(20000, 6)) {
      const ParaboloidCoord c = paraboloidUv(f, d);
      EXPECT_EQ(c.half, glm::dot(d, f.axis) >= 0.0 ? 0 : 1);
      // Inside the disc of radius 0.5.
      ASSERT_LE(glm::length(c.uv - 0.5), 0.5 + 1e-12);
      EXPECT_NEAR(glm::length(paraboloidDirection(f, c.half, c.uv) - d), 0.0, 1e-12);
    }
    // The rim (split plane) maps to radius 0.5 on both halves.
    const ParaboloidCoord rim = paraboloidUv(f, f.x);
    EXPECT_NEAR(glm::length(rim.uv - 0.5), 0.5, 1e-15);
  }
}

TEST(OmniParaboloid, DensityRimOverCentreIsFour) {
  const int res = 2048;
  const ParaboloidFrame f = paraboloidFrame({0, 1, 0});
  const double centre = paraboloidTexelsPerSteradian(f, {0, 1, 0}, res);
  EXPECT_DOUBLE_EQ(centre, double(res) * res / 16.0);
  EXPECT_DOUBLE_EQ(paraboloidTexelsPerSteradian(f, {1, 0, 0}, res) / centre, 4.0);
  EXPECT_DOUBLE_EQ(paraboloidTexelsPerSteradian(f, {0, -1, 0}, res), centre);
  // Integrates to pi texels... of the disc: sum of the solid angles of the texels inside
  // the disc of each half = 2 pi per half.
  const int n = 512;
  double omega = 0.0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const glm::dvec2 uv = (glm::dvec2(x, y) + 0.5) / double(n);
      if (glm::length(uv - 0.5) > 0.5) continue;
      omega += 1.0 / paraboloidTexelsPerSteradian(f, paraboloidDirection(f, 0, uv), n);
    }
  EXPECT_NEAR(omega, 2.0 * std::numbers::pi, 2e-2);
}

// Solid angle of the spherical triangle a b c (unit vectors; Van Oosterom and Strackee 1983).
double triangleSolidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const double num = std::abs(glm::dot(a, glm::cross(b, c)));
  const double den = 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a);
  return 2.0 * std::atan2(num, den);
}
/// The solid angle of the texel whose uv corners are lo..hi, mapped by `dir`.
template <class Dir>
double texelSolidAngle(Dir dir, glm::dvec2 lo, glm::dvec2 hi) {
  const glm::dvec3 a = dir({lo.x, lo.y}), b = dir({hi.x, lo.y}), c = dir({hi.x, hi.y}),
                   d = dir({lo.x, hi.y});
  return triangleSolidAngle(a, b, c) + triangleSolidAngle(a, c, d);
}

TEST(OmniDensity, MeasuredTexelSolidAnglesMatchTheAnalyticRatios) {
  // Measured: the exact solid angle of real texels (their four corner directions through
  // the inverse mappings), independent of the density formulas. docs/techniques/omni-lights.md
  // quotes these lines.
  const int res = 1024;
  const double t = 1.0 / res;
  auto cube = [](glm::dvec2 uv) { return cubeDirection(4, uv); };
  const double centre = texelSolidAngle(cube, {0.5, 0.5}, {0.5 + t, 0.5 + t});
  const double corner = texelSolidAngle(cube, {1.0 - t, 1.0 - t}, {1.0, 1.0});
  const double cubeRatio = centre / corner;
  const ParaboloidFrame f = paraboloidFrame({0, 1, 0});
  auto disc = [&](glm::dvec2 uv) { return paraboloidDirection(f, 0, uv); };
  const double pCentre = texelSolidAngle(disc, {0.5, 0.5}, {0.5 + t, 0.5 + t});
  const double pRim = texelSolidAngle(disc, {1.0 - t, 0.5}, {1.0, 0.5 + t});
  const double discRatio = pCentre / pRim;
  std::printf("cube %d^2: texels per sr, corner / centre = %.4f (analytic 3√3 = %.4f)\n", res,
              cubeRatio, 3.0 * std::sqrt(3.0));
  std::printf("paraboloid %d^2: texels per sr, rim / centre = %.4f (analytic 4)\n", res, discRatio);
  EXPECT_NEAR(cubeRatio, 3.0 * std::sqrt(3.0), 0.02);
  EXPECT_NEAR(discRatio, 4.0, 0.02);
  // And each measured texel against the density formula at its centre direction.
  EXPECT_NEAR(centre * cubeTexelsPerSteradian(cube({0.5 + t / 2, 0.5 + t / 2}), res), 1.0, 1e-3);
  EXPECT_NEAR(pRim * paraboloidTexelsPerSteradian(f, disc({1.0 - t / 2, 0.5 + t / 2}), res), 1.0,
              1e-2);
}

TEST(OmniStoredDistance, NormalisedByNearAndFarAndInverted) {
  // What cube/distance.frag and dual-paraboloid/depth.frag store: 0 at near, 1 at far
  // (the cleared "nothing"), affine in between; distanceFromStored inverts it.
  const double n = 0.0057, f = 5.7;
  EXPECT_EQ(storedDistance(n, n, f), 0.0);
  EXPECT_EQ(storedDistance(f, n, f), 1.0);
  EXPECT_DOUBLE_EQ(storedDistance(0.5 * (n + f), n, f), 0.5);
  EXPECT_DOUBLE_EQ(distanceFromStored(1.0, n, f), f);
  EXPECT_DOUBLE_EQ(distanceFromStored(0.0, n, f), n);
  for (double d = n; d <= f; d += 0.37)
    EXPECT_NEAR(distanceFromStored(storedDistance(d, n, f), n, f), d, 1e-15 * f) << d;
}

}  // namespace
}  // namespace sl::omni
