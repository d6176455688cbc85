// The exact warped shadow map (algo/rtw/WarpedRaster): identity against a plain rasteriser,
// analytic planes through strong warps, the inverse tables, long triangles, the lookup.
// Every expected value here is computed independently of WarpedRaster.cpp's arithmetic
// (different barycentric formulation, analytic planes).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "algo/rtw/Warp.h"
#include "algo/rtw/WarpedRaster.h"

namespace sl::rtw {
namespace {

/// Portable deterministic floats in [lo, hi) (std distributions differ between libraries).
struct Lcg {
  std::uint64_t s;
  float next(float lo, float hi) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return lo + (hi - lo) * float(double(s >> 40) / double(1ull << 24));
  }
};

/// A strongly non-uniform warp: importance = floor + Gaussian peaks (sigma in uv units).
std::vector<float> peakedWarp(int n, std::vector<std::pair<float, float>> peaks, float floor) {
  std::vector<float> imp(static_cast<size_t>(n), floor);
  for (int i = 0; i < n; ++i) {
    float u = (float(i) + 0.5f) / float(n);
    for (auto [c, sigma] : peaks)
      imp[size_t(i)] += std::exp(-(u - c) * (u - c) / (2 * sigma * sigma));
  }
  return warpFromImportance(imp);
}

WarpMaps strongWarp() {
  return {peakedWarp(64, {{0.3f, 0.03f}, {0.8f, 0.05f}}, 0.01f),
          peakedWarp(100, {{0.65f, 0.02f}}, 0.005f)};
}

/// Independent plain rasteriser at the exact texel centres: barycentrics from the 2x2
/// system (p - a) = l1 (b - a) + l2 (c - a), z = a.z + l1 (b.z - a.z) + l2 (c.z - a.z).
struct Plain {
  std::vector<float> depth;
  std::vector<int> tri;
};
bool planeBySolve(const LightTriangle& t, double pu, double pv, double& z) {
  const glm::dvec3 a(t.v[0]), b(t.v[1]), c(t.v[2]);
  const glm::dvec2 d1(b - a), d2(c - a), q(pu - a.x, pv - a.y);
  const double det = d1.x * d2.y - d1.y * d2.x;
  if (std::abs(det) < 1e-12) return false;
  const double l1 = (q.x * d2.y - q.y * d2.x) / det;
  const double l2 = (d1.x * q.y - d1.y * q.x) / det;
  if (l1 < 0.0 || l2 < 0.0 || l1 + l2 > 1.0) return false;
  z = a.z + l1 * (b.z - a.z) + l2 * (c.z - a.z);
  return true;
}
Plain plainRaster(int res, const std::vector<LightTriangle>& tris) {
  Plain p{std::vector<float>(size_t(res) * size_t(res), 1.0f),
          std::vector<int>(size_t(res) * size_t(res), -1)};
  std::vector<double> best(p.depth.size(), 2.0);
  for (int j = 0; j < res; ++j)
    for (int i = 0; i < res; ++i)
      for (size_t k = 0; k < tris.size(); ++k) {
        double z;
        const size_t t = size_t(j) * size_t(res) + size_t(i);
        if (planeBySolve(tris[k], (i + 0.5) / res, (j + 0.5) / res, z) && z >= 0.0 && z <= 1.0 &&
            z < best[t]) {
          best[t] = z;
          p.depth[t] = float(z);
          p.tri[t] = int(k);
        }
      }
  return p;
}

std::vector<LightTriangle> randomTriangles(int count, std::uint64_t seed) {
  Lcg g{seed};
  std::vector<LightTriangle> tris;
  for (int k = 0; k < count; ++k) {
    // Sizes from a tenth of the map to more than the map; z in [0.05, 0.95] at the
    // vertices, so every point of the triangle is inside the depth range.
    float cu = g.next(-0.1f, 1.1f), cv = g.next(-0.1f, 1.1f), r = g.next(0.02f, 0.7f);
    LightTriangle t;
    for (glm::vec3& p : t.v) p = {cu + g.next(-r, r), cv + g.next(-r, r), g.next(0.05f, 0.95f)};
    tris.push_back(t);
  }
  return tris;
}

/// The plane of the covering-triangle tests: window depth at light uv (u, v).
double plane(double u, double v) {
  return 0.3 + 0.25 * u + 0.15 * v;
}

/// One triangle of that plane covering the whole map, its vertices outside (0, 1)^2.
LightTriangle coveringPlaneTriangle() {
  LightTriangle big;
  const glm::dvec2 corners[3] = {{-1.0, -1.0}, {3.0, -1.0}, {-1.0, 3.0}};
  for (int k = 0; k < 3; ++k)
    big.v[size_t(k)] = glm::vec3(float(corners[k].x), float(corners[k].y),
                                 float(plane(corners[k].x, corners[k].y)));
  return big;
}

// ---------------------------------------------------------------------------------------

TEST(WarpedRaster, InverseTableOfTheIdentityIsTheTexelCentre) {
  for (int res : {1, 64, 100, 256}) {
    std::vector<float> t = inverseWarpTable({}, res);
    ASSERT_EQ(t.size(), size_t(res));
    for (int i = 0; i < res; ++i) EXPECT_EQ(t[size_t(i)], (float(i) + 0.5f) / float(res));
    std::vector<float> zeros(65, 0.0f);
    std::vector<float> tz = inverseWarpTable(zeros, res);
    for (int i = 0; i < res; ++i) EXPECT_NEAR(tz[size_t(i)], (i + 0.5) / res, 1.2e-7);
  }
  EXPECT_TRUE(inverseWarpTable({}, 0).empty());
}

// The unwarped map (empty WarpMaps, and all-zero warp edges) is an ordinary rasteriser
// sampling texel centres: same coverage, same depth (both exact in double, so only the
// final float rounding can differ: 1e-6 is generous).
TEST(WarpedRaster, IdentityWarpEqualsAPlainRasteriser) {
  std::vector<LightTriangle> tris = randomTriangles(60, 7);
  WarpMaps zeros{std::vector<float>(65, 0.0f), std::vector<float>(33, 0.0f)};
  for (int res : {64, 128})
    for (const WarpMaps* maps : std::initializer_list<const WarpMaps*>{nullptr, &zeros}) {
      WarpedRaster r = rasterizeWarped(maps ? *maps : WarpMaps{}, res, tris);
      Plain p = plainRaster(res, tris);
      ASSERT_EQ(r.size, res);
      ASSERT_EQ(r.depth.size(), p.depth.size());
      size_t covered = 0, coverageDiffers = 0;
      for (size_t t = 0; t < p.depth.size(); ++t) {
        covered += p.tri[t] >= 0;
        if ((r.triangle[t] >= 0) != (p.tri[t] >= 0)) {
          ++coverageDiffers;
          continue;
        }
        EXPECT_NEAR(r.depth[t], p.depth[t], 1e-6f) << "res " << res << " texel " << t;
      }
      EXPECT_GT(covered, p.depth.size() / 2);
      EXPECT_EQ(coverageDiffers, 0u) << "res " << res << (maps ? " zeros" : " empty");
      EXPECT_EQ(rasterizeWarpedDepth(maps ? *maps : WarpMaps{}, res, tris), r.depth);
    }
}

// One plane triangle covering the whole map through a strong warp: every texel equals the
// analytic plane at the inverse-warped centre (1e-6: the float vertices round the plane by
// ~1e-7). Interpolating linearly in warped space instead (what a rasteriser of the warped
// vertices does: the vertices lie outside (0, 1), where the warp is the identity, so it
// gives the plane at the WARPED centre) is off by more than 0.01 here.
TEST(WarpedRaster, CoveringPlaneIsThePlaneAtTheInverseWarpedCentre) {
  const WarpMaps maps = strongWarp();
  const std::vector<LightTriangle> tris{coveringPlaneTriangle()};
  for (int res : {128, 256}) {
    WarpedRaster r = rasterizeWarped(maps, res, tris);
    std::vector<float> tx = inverseWarpTable(maps.x, res), ty = inverseWarpTable(maps.y, res);
    double maxLinearError = 0.0;
    for (int j = 0; j < res; ++j)
      for (int i = 0; i < res; ++i) {
        const size_t t = size_t(j) * size_t(res) + size_t(i);
        ASSERT_EQ(r.triangle[t], 0) << i << "," << j;
        EXPECT_NEAR(r.depth[t], plane(tx[size_t(i)], ty[size_t(j)]), 1e-6) << i << "," << j;
        maxLinearError = std::max(maxLinearError, std::abs(plane((i + 0.5) / res, (j + 0.5) / res) -
                                                           plane(tx[size_t(i)], ty[size_t(j)])));
      }
    EXPECT_GT(maxLinearError, 0.01) << "the warp is not strong enough to test anything";
  }
}

// Seed 002's interpolated map of the same covering triangle: its vertices lie outside
// (0, 1), where the warp is the identity, so the warped triangle is the triangle itself and
// linear interpolation in warped space gives the plane at the WARPED texel centre (not at
// the inverse-warped one, as the exact map does): the error is the warp's displacement
// times the plane's gradient, > 0.01 here.
TEST(WarpedRaster, InterpolatedDepthIsThePlaneAtTheWarpedCentre) {
  const WarpMaps maps = strongWarp();
  const std::vector<LightTriangle> tris{coveringPlaneTriangle()};
  const int res = 128;
  const WarpedRaster interp = rasterizeWarpedInterpolated(maps, res, tris);
  const WarpedRaster exact = rasterizeWarped(maps, res, tris);
  ASSERT_EQ(interp.size, res);
  double maxOff = 0.0;
  for (int j = 0; j < res; ++j)
    for (int i = 0; i < res; ++i) {
      const size_t t = size_t(j) * size_t(res) + size_t(i);
      ASSERT_EQ(interp.triangle[t], 0) << i << "," << j;
      EXPECT_NEAR(interp.depth[t], plane((i + 0.5) / res, (j + 0.5) / res), 1e-6) << i << "," << j;
      maxOff = std::max(maxOff, std::abs(double(interp.depth[t]) - double(exact.depth[t])));
    }
  EXPECT_GT(maxOff, 0.01);
}

// With no warp the interpolated map is an ordinary rasteriser, like the exact one.
TEST(WarpedRaster, InterpolatedWithoutAWarpEqualsAPlainRasteriser) {
  std::vector<LightTriangle> tris = randomTriangles(60, 11);
  for (int res : {64, 100}) {
    const WarpedRaster r = rasterizeWarpedInterpolated(WarpMaps{}, res, tris);
    const Plain p = plainRaster(res, tris);
    size_t coverageDiffers = 0;
    for (size_t t = 0; t < p.depth.size(); ++t) {
      if ((r.triangle[t] >= 0) != (p.tri[t] >= 0)) {
        ++coverageDiffers;
        continue;
      }
      EXPECT_NEAR(r.depth[t], p.depth[t], 1e-6f) << "res " << res << " texel " << t;
    }
    EXPECT_EQ(coverageDiffers, 0u) << "res " << res;
  }
  EXPECT_EQ(rasterizeWarpedInterpolated(WarpMaps{}, 0, tris).size, 0);
}

// A small triangle in the warped map: its vertices move by the warp, its edges stay
// straight between them (coverage of the warped triangle, not of the bent one).
TEST(WarpedRaster, InterpolatedCoverageIsTheWarpedStraightTriangle) {
  const WarpMaps maps = strongWarp();
  const LightTriangle t{
      {glm::vec3(0.2f, 0.55f, 0.4f), glm::vec3(0.9f, 0.6f, 0.5f), glm::vec3(0.25f, 0.75f, 0.6f)}};
  LightTriangle warped = t;
  for (glm::vec3& p : warped.v) {
    const glm::vec2 w = warpUv(maps, glm::vec2(p));
    p = glm::vec3(w, p.z);
  }
  const int res = 96;
  const WarpedRaster r = rasterizeWarpedInterpolated(maps, res, std::vector<LightTriangle>{t});
  const Plain p = plainRaster(res, {warped});
  size_t covered = 0;
  for (size_t k = 0; k < p.depth.size(); ++k) {
    EXPECT_EQ(r.triangle[k] >= 0, p.tri[k] >= 0) << k;
    if (p.tri[k] < 0) continue;
    ++covered;
    EXPECT_NEAR(r.depth[k], p.depth[k], 1e-6f) << k;
  }
  EXPECT_GT(covered, 100u);
}

// warpCoordinate(table[i]) is the texel centre (Warp.h: round trip to 1e-6), for strong
// warps, power-of-two and other sizes.
TEST(WarpedRaster, InverseTableRoundTrips) {
  const WarpMaps maps = strongWarp();
  for (const std::vector<float>* edges : {&maps.x, &maps.y})
    for (int res : {128, 256, 1000}) {
      std::vector<float> t = inverseWarpTable(*edges, res);
      for (int i = 0; i < res; ++i)
        EXPECT_NEAR(warpCoordinate(*edges, t[size_t(i)]), (i + 0.5) / res, 1e-6) << i;
    }
}

// Tables are non-decreasing and inside (0, 1); strictly increasing with an importance floor.
// With zero-importance runs (no floor) the table jumps over them, still non-decreasing.
TEST(WarpedRaster, InverseTablesAreMonotonic) {
  const WarpMaps maps = strongWarp();
  std::vector<float> gaps(50, 0.0f);
  for (int i = 10; i < 18; ++i) gaps[size_t(i)] = 1.0f;
  for (int i = 30; i < 33; ++i) gaps[size_t(i)] = 3.0f;
  const std::vector<float> withGaps = warpFromImportance(gaps);
  for (int res : {128, 256, 777}) {
    for (const std::vector<float>* edges : {&maps.x, &maps.y}) {
      std::vector<float> t = inverseWarpTable(*edges, res);
      for (int i = 0; i + 1 < res; ++i) EXPECT_LT(t[size_t(i)], t[size_t(i) + 1]) << i;
      EXPECT_GT(t.front(), 0.0f);
      EXPECT_LT(t.back(), 1.0f);
    }
    std::vector<float> t = inverseWarpTable(withGaps, res);
    for (int i = 0; i + 1 < res; ++i) EXPECT_LE(t[size_t(i)], t[size_t(i) + 1]) << i;
    for (float u : t) {  // every sample lands inside an important run
      int texel = int(u * 50.0f);
      EXPECT_TRUE((texel >= 10 && texel <= 18) || (texel >= 30 && texel <= 33)) << u;
    }
  }
}

// A long thin triangle across the map with depth varying along it, through a strong warp:
//  - covered texels are exactly those whose inverse-warped centre is inside (independent
//    test), with the plane's depth there;
//  - the lookup agrees with the map: a point on the triangle looked up (warpedLookup)
//    finds a texel whose depth differs from its own by at most the plane's change across
//    that texel's footprint in UNWARPED space;
//  - linear interpolation of the warped vertices (today's rasterisation) is off by > 1e-3.
TEST(WarpedRaster, LongTriangleDepthIsExactThroughTheWarp) {
  const WarpMaps maps = strongWarp();
  LightTriangle tri{{glm::vec3(0.02f, 0.05f, 0.1f), glm::vec3(0.97f, 0.93f, 0.9f),
                     glm::vec3(0.99f, 0.86f, 0.85f)}};
  const std::vector<LightTriangle> tris{tri};
  // The plane z = A u + B v + C of the triangle (double).
  const glm::dvec3 a(tri.v[0]), b(tri.v[1]), c(tri.v[2]);
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double A = -n.x / n.z, B = -n.y / n.z, C = a.z - A * a.x - B * a.y;
  for (int res : {128, 256}) {
    WarpedRaster r = rasterizeWarped(maps, res, tris);
    size_t covered = 0;
    double maxLinearError = 0.0;
    // Warped vertices, for what linear interpolation in warped space would give.
    LightTriangle warped = tri;
    for (glm::vec3& p : warped.v) p = glm::vec3(warpUv(maps, glm::vec2(p)), p.z);
    for (int j = 0; j < res; ++j)
      for (int i = 0; i < res; ++i) {
        const size_t t = size_t(j) * size_t(res) + size_t(i);
        const double u = r.tableX[size_t(i)], v = r.tableY[size_t(j)];
        double z;
        const bool inside = planeBySolve(tri, u, v, z);
        ASSERT_EQ(inside, r.triangle[t] == 0) << i << "," << j;
        if (!inside) {
          EXPECT_EQ(r.depth[t], 1.0f);
          continue;
        }
        ++covered;
        EXPECT_NEAR(r.depth[t], A * u + B * v + C, 1e-6) << i << "," << j;
        double zLinear;
        if (planeBySolve(warped, (i + 0.5) / res, (j + 0.5) / res, zLinear))
          maxLinearError = std::max(maxLinearError, std::abs(zLinear - (A * u + B * v + C)));
      }
    EXPECT_GT(covered, size_t(res));
    EXPECT_GT(maxLinearError, 1e-3) << "res " << res;
    std::printf("long triangle %d^2: %zu texels, linear-in-warped-space error up to %.5f\n", res,
                covered, maxLinearError);

    // Lookup of points on the triangle (the identity matrix: light space = NDC).
    const glm::mat4 ndcToLight = glm::translate(glm::mat4(1.0f), glm::vec3(-1.0f)) *
                                 glm::scale(glm::mat4(1.0f), glm::vec3(2.0f));
    Lcg g{11};
    int checked = 0;
    for (int s = 0; s < 2000; ++s) {
      float l1 = g.next(0.0f, 1.0f), l2 = g.next(0.0f, 1.0f);
      if (l1 + l2 > 1.0f) l1 = 1.0f - l1, l2 = 1.0f - l2;
      const glm::vec3 p = tri.v[0] + l1 * (tri.v[1] - tri.v[0]) + l2 * (tri.v[2] - tri.v[0]);
      const glm::vec3 look = warpedLookup(maps, ndcToLight, p);  // p is light uvz already
      EXPECT_NEAR(look.z, p.z, 1e-6);
      EXPECT_EQ(glm::vec2(look), warpUv(maps, glm::vec2(lightSpaceOf(ndcToLight, p))));
      const int i = std::clamp(int(std::floor(look.x * float(res))), 0, res - 1);
      const int j = std::clamp(int(std::floor(look.y * float(res))), 0, res - 1);
      const size_t t = size_t(j) * size_t(res) + size_t(i);
      if (r.triangle[t] != 0) continue;  // the texel's centre is off the thin triangle
      const double du = unwarpCoordinate(maps.x, float(i + 1) / float(res)) -
                        unwarpCoordinate(maps.x, float(i) / float(res));
      const double dv = unwarpCoordinate(maps.y, float(j + 1) / float(res)) -
                        unwarpCoordinate(maps.y, float(j) / float(res));
      EXPECT_LE(std::abs(double(r.depth[t]) - double(p.z)),
                std::abs(A) * du + std::abs(B) * dv + 1e-6)
          << "sample " << s;
      ++checked;
    }
    EXPECT_GT(checked, 1000);
  }
}

TEST(WarpedRaster, NearestTriangleWinsAndDegenerateOrClippedOnesDoNot) {
  auto flat = [](float z, float u0, float v0, float u1, float v1) {
    return LightTriangle{{glm::vec3(u0, v0, z), glm::vec3(u1, v0, z), glm::vec3(u0, v1, z)}};
  };
  std::vector<LightTriangle> tris{
      flat(0.6f, -1.0f, -1.0f, 3.0f, 3.0f),  // everywhere
      flat(0.4f, -1.0f, -1.0f, 2.0f, 2.0f),  // u + v <= 1, nearer
      LightTriangle{{glm::vec3(0.1f, 0.1f, 0.0f), glm::vec3(0.9f, 0.9f, 0.0f),
                     glm::vec3(0.5f, 0.5f, 0.0f)}},  // degenerate (a line), nearest
      flat(-0.2f, 0.0f, 0.0f, 2.0f, 2.0f),           // behind the near plane: clipped
      flat(0.4f, -1.0f, -1.0f, 2.0f, 2.0f),          // tie with triangle 1: first kept
  };
  WarpedRaster r = rasterizeWarped(strongWarp(), 64, tris);
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) {
      const size_t t = size_t(j) * 64 + size_t(i);
      const double u = r.tableX[size_t(i)], v = r.tableY[size_t(j)];
      const bool lower = u + v <= 1.0;
      EXPECT_EQ(r.triangle[t], lower ? 1 : 0) << i << "," << j;
      EXPECT_EQ(r.depth[t], lower ? 0.4f : 0.6f);
    }
  EXPECT_EQ(lightTriangleArea2(tris[2]), 0.0);
  double z = -1.0;
  EXPECT_FALSE(lightTrianglePlaneAt(tris[2], 0.5, 0.5, z));
  EXPECT_TRUE(rasterizeWarped(WarpMaps{}, 0, tris).depth.empty());
}

// lightSpaceOf / lightTriangle / appendLightTriangles with a real orthographic light, and
// warpedLookup without a warp is the light-space position itself.
TEST(WarpedRaster, LightSpaceOfAnOrthographicLight) {
  const glm::mat4 view = glm::lookAt(glm::vec3(0, 10, 0), glm::vec3(0), glm::vec3(0, 0, -1));
  const glm::mat4 proj = glm::ortho(-10.0f, 10.0f, -5.0f, 5.0f, 1.0f, 21.0f);
  const glm::mat4 vp = proj * view;
  // World (x, y, z): light x = world x, light y = world -z, eye depth = 10 - y.
  const glm::vec3 p = lightSpaceOf(vp, {5.0f, 0.0f, 2.5f});
  EXPECT_NEAR(p.x, 0.75f, 1e-6f);
  EXPECT_NEAR(p.y, 0.25f, 1e-6f);
  EXPECT_NEAR(p.z, 0.45f, 1e-6f);  // depth 10 in [1, 21]
  EXPECT_EQ(warpedLookup(WarpMaps{}, vp, {5.0f, 0.0f, 2.5f}), p);
  const glm::vec3 wp = warpedLookup(strongWarp(), vp, {5.0f, 0.0f, 2.5f});
  EXPECT_EQ(wp.x, warpCoordinate(strongWarp().x, p.x));
  EXPECT_EQ(wp.y, warpCoordinate(strongWarp().y, p.y));
  EXPECT_EQ(wp.z, p.z);
  const std::vector<glm::vec3> pos{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}};
  const std::vector<std::uint32_t> idx{0, 1, 2, 0, 2, 3, 0, 1, 9, 1};  // 9: out of range
  std::vector<LightTriangle> out;
  appendLightTriangles(vp, pos, idx, out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].v[1], lightSpaceOf(vp, pos[1]));
  EXPECT_EQ(out[1].v[2], lightSpaceOf(vp, pos[3]));
  const LightTriangle t = lightTriangle(vp, pos[0], pos[2], pos[3]);
  EXPECT_EQ(t.v[0], out[1].v[0]);
  EXPECT_EQ(lightTriangleArea2(t), 0.0);  // the x = 0 wall is edge-on to the light
}

}  // namespace
}  // namespace sl::rtw
