// The GPU warped shadow map against its exact CPU reference (algo/rtw/WarpedRaster.h),
// texel by texel, and the per-pixel warped lookup coordinate against warpedLookup.
//
// The exact map holds, at each warped texel centre, the covering triangle's depth PLANE
// evaluated at the inverse-warped (unwarped) light uv: an orthographic light's depth is
// affine in unwarped light space, not in warped space. Interpolating depth linearly in
// warped space (rasterising warped vertices, even on tessellated edges) is wrong inside
// long triangles; this test measures exactly that.
//
// Coverage: the GPU rasterises (tessellated) straight edges in warped space while the CPU
// tests the exact edges in unwarped space, so the two may disagree on silhouettes only.
//  - interior texel: the CPU texel and its 8 neighbours (those inside the map) hold the
//    same triangle, or are all empty. There the GPU must match: empty -> exactly 1.0;
//    covered -> |gpu - cpu| <= kDepthTolerance.
//  - silhouette texel: any other. Only coverage is compared (one side far = 1.0, the other
//    not), and at most kSilhouetteMismatchFraction of them may disagree.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "GlTestEnv.h"
#include "algo/Focus.h"
#include "algo/rtw/Warp.h"
#include "algo/rtw/WarpedRaster.h"

namespace sl {
namespace {

// Window-depth tolerance on interior texels. The exact GPU pass evaluates the same plane
// in float at a float inverse-table position: the table's GLSL arithmetic (division: 2.5
// ulp) moves (u, v) by a few ulp of 1.0 (~2.4e-7), which changes z by |grad z| times that
// (|grad z| = window depth per unit of light uv, at most ~1 on the interior texels of
// these scenes, see the printed maxima), and the float plane evaluation adds a few ulp of
// z (~6e-8 each). That is < 2e-6; 2e-5 leaves a factor 10 for the vertex transform (fma
// contraction in the matrix product: ~1e-7 relative on each vertex's uvz). Measured: the
// unwarped control map (ordinary rasterisation, where linear interpolation IS exact)
// matches its CPU raster to <= 1.8e-7. A depth interpolated linearly in WARPED space is
// off by ~|grad z| x (the warp's bend inside a triangle): 1e-3..7e-3 on these scenes.
constexpr double kDepthTolerance = 2e-5;
// Silhouette texels whose coverage differs. The GPU's edges are straight in warped space
// between tessellated vertices (bend tolerance tessellation.tolerance = 0.25 texel here,
// long triangles pre-split by SceneGpu), so centres close to a true edge can flip.
// Measured with the exact-depth pass: 0.15-0.27 %; the unwarped control: <= 0.07 %; the
// linearly interpolated pass of before: up to 5.2 %; without tessellation 22-36 %.
constexpr double kSilhouetteMismatchFraction = 0.10;
// Lookup coordinate (warped uv, no normal offset): the same float matrix product and warp
// on both sides; 1e-5 covers fma contraction times the warp's local slope (measured: at
// most 4.2e-7 with densities up to 6).
constexpr float kLookupTolerance = 1e-5f;

/// The scene's triangles in light space. The CPU reference ignores alpha: a scene with
/// alpha-MASK materials cannot be compared this way.
std::vector<rtw::LightTriangle> sceneLightTriangles(const Scene& scene, const glm::mat4& vp) {
  std::vector<rtw::LightTriangle> tris;
  for (const MeshPrimitive& prim : scene.primitives) {
    EXPECT_NE(scene.materialOf(prim).alphaMode, AlphaMode::Mask)
        << prim.name << ": alpha-tested casters are not modelled by the CPU raster";
    rtw::appendLightTriangles(vp, prim.positions, prim.indices, tris);
  }
  return tris;
}

/// Plane gradient |dz/du| + |dz/dv| of a light triangle (window depth per unit uv).
double gradientL1(const rtw::LightTriangle& t) {
  const glm::dvec3 a(t.v[0]), b(t.v[1]), c(t.v[2]);
  const glm::dvec3 n = glm::cross(b - a, c - a);
  return n.z == 0.0 ? 0.0 : (std::abs(n.x) + std::abs(n.y)) / std::abs(n.z);
}

struct DepthParity {
  size_t interiorCovered = 0, interiorEmpty = 0, interiorOff = 0;
  double maxInteriorError = 0.0, sumInteriorError = 0.0, maxInteriorGradient = 0.0;
  std::vector<double> interiorErrors;  ///< |gpu - cpu| of every covered interior texel
  size_t silhouette = 0, silhouetteMismatch = 0;
};

DepthParity compareDepth(const FloatImage& gpu, const rtw::WarpedRaster& cpu,
                         const std::vector<rtw::LightTriangle>& tris,
                         double depthTolerance = kDepthTolerance) {
  DepthParity p;
  const int n = cpu.size;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const size_t t = size_t(j) * size_t(n) + size_t(i);
      const int id = cpu.triangle[t];
      bool uniform = true;
      for (int dy = -1; dy <= 1 && uniform; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int x = i + dx, y = j + dy;
          if (x < 0 || y < 0 || x >= n || y >= n) continue;
          if (cpu.triangle[size_t(y) * size_t(n) + size_t(x)] != id) {
            uniform = false;
            break;
          }
        }
      const float g = gpu.values[t], c = cpu.depth[t];
      if (!uniform) {
        ++p.silhouette;
        if ((g == 1.0f) != (id < 0)) ++p.silhouetteMismatch;
        continue;
      }
      if (id < 0) {
        ++p.interiorEmpty;
        if (g != 1.0f) ++p.interiorOff;
        continue;
      }
      ++p.interiorCovered;
      const double e = std::abs(double(g) - double(c));
      p.maxInteriorError = std::max(p.maxInteriorError, e);
      p.sumInteriorError += e;
      p.interiorErrors.push_back(e);
      p.maxInteriorGradient = std::max(p.maxInteriorGradient, gradientL1(tris[size_t(id)]));
      if (!(e <= depthTolerance)) ++p.interiorOff;
    }
  return p;
}

struct Case {
  const char* scene;
  int smRes, imRes;
  const char* camera = nullptr;  ///< a bookmark of the scene; null: its first
};

// One frame of rtw-backward with every bias at 0 (the map must hold the exact depth; the
// lookup coordinate must be the unbiased one), publishing on.
void checkParity(const Case& k) {
  const std::string label = std::string(k.scene) + (k.camera ? std::string("/") + k.camera : "");
  SCOPED_TRACE(label + " sm " + std::to_string(k.smRes) + " im " + std::to_string(k.imRes));
  auto r = test::makeRenderer(k.scene, "rtw-backward");
  ASSERT_TRUE(r);
  if (k.camera) {
    const Camera* cam = test::bookmark(*r->scene(), k.camera);
    ASSERT_TRUE(cam) << "no camera " << k.camera;
    r->setCamera(*cam);
  }
  ParamSet& p = r->params();
  ASSERT_FALSE(p.set("resolution", k.smRes));
  ASSERT_FALSE(p.set("im.resolution", k.imRes));
  for (const char* key : {"bias.normal", "bias.slope", "bias.constant"}) {
    auto err = p.set(key, 0.0);
    ASSERT_FALSE(err) << key << ": " << *err
                      << " (the bias parameters were renamed: update this test)";
    ASSERT_EQ(p.get(key), 0.0) << key;
  }
  // Silhouettes bend to within a quarter texel (the default, 1 texel, may move a caster's
  // edge past the one-texel margin around the CPU's silhouettes that "interior" assumes).
  ASSERT_FALSE(p.set("tessellation.tolerance", 0.25));
  r->requestPublications({"*"});
  const int w = 320, h = 180;
  ASSERT_FALSE(r->renderFrame(w, h, 0));
  test::expectNoGlErrors(*r);
  const Publication& pub = r->publication();
  ASSERT_TRUE(pub.images.count("shadow map"));
  const FloatImage& gpu = pub.images.at("shadow map");
  ASSERT_EQ(gpu.width, k.smRes);
  ASSERT_EQ(gpu.height, k.smRes);
  const rtw::WarpMaps maps{pub.curves.at("warp.x"), pub.curves.at("warp.y")};
  ASSERT_EQ(maps.x.size(), size_t(k.imRes + 1));
  ASSERT_EQ(maps.y.size(), size_t(k.imRes + 1));

  // The light fit of that frame, exactly as the technique computes it (no rotation).
  LightFit fit;
  ASSERT_FALSE(fitDirectionalLight(r->camera(), float(w) / float(h), r->scene()->bounds,
                                   r->light().directionalTowards(), FocusSettings{}, fit));
  const std::vector<rtw::LightTriangle> tris = sceneLightTriangles(*r->scene(), fit.viewProj);
  const rtw::WarpedRaster cpu = rtw::rasterizeWarped(maps, k.smRes, tris);

  // How strong the warp is (the largest local density du'/du of either axis).
  float density = 1.0f;
  for (const auto* edges : {&maps.x, &maps.y})
    for (int e = 0; e < k.imRes; ++e)
      density = std::max(density,
                         1.0f + float(k.imRes) * ((*edges)[size_t(e) + 1] - (*edges)[size_t(e)]));

  DepthParity d = compareDepth(gpu, cpu, tris);
  double p99 = 0.0;
  if (!d.interiorErrors.empty()) {
    auto nth =
        d.interiorErrors.begin() + std::ptrdiff_t(0.99 * double(d.interiorErrors.size() - 1));
    std::nth_element(d.interiorErrors.begin(), nth, d.interiorErrors.end());
    p99 = *nth;
  }
  std::printf(
      "[%s sm %d im %d] warp density up to %.1f; interior: %zu covered + %zu empty, %zu off "
      "(> %.0e), max |gpu - cpu| %.3e, mean %.3e, p99 %.3e, max |grad z| %.2f; silhouette: %zu, "
      "coverage differs on %zu (%.2f %%)\n",
      label.c_str(), k.smRes, k.imRes, density, d.interiorCovered, d.interiorEmpty, d.interiorOff,
      kDepthTolerance, d.maxInteriorError,
      d.interiorCovered ? d.sumInteriorError / double(d.interiorCovered) : 0.0, p99,
      d.maxInteriorGradient, d.silhouette, d.silhouetteMismatch,
      d.silhouette ? 100.0 * double(d.silhouetteMismatch) / double(d.silhouette) : 0.0);
  EXPECT_GT(d.interiorCovered, size_t(k.smRes) * size_t(k.smRes) / 4) << "too little to compare";
  EXPECT_EQ(d.interiorOff, 0u) << "interior texels off; max error " << d.maxInteriorError;
  EXPECT_LE(double(d.silhouetteMismatch), kSilhouetteMismatchFraction * double(d.silhouette));

  // Control: the unwarped contrast map (when published) is an ordinary depth map, which
  // rasterisation gets right (depth IS affine in unwarped uv); it must match the identity
  // CPU raster under the same criteria. This checks the light fit, the triangles, the
  // layout and the zero bias of the comparison itself.
  if (auto it = pub.images.find("shadow map.uniform"); it != pub.images.end()) {
    const rtw::WarpedRaster plain = rtw::rasterizeWarped(rtw::WarpMaps{}, k.smRes, tris);
    const DepthParity u = compareDepth(it->second, plain, tris);
    std::printf(
        "[%s sm %d im %d] control (unwarped map): interior %zu covered, %zu off, max |gpu - "
        "cpu| %.3e; silhouette coverage differs on %zu of %zu\n",
        label.c_str(), k.smRes, k.imRes, u.interiorCovered, u.interiorOff, u.maxInteriorError,
        u.silhouetteMismatch, u.silhouette);
    EXPECT_EQ(u.interiorOff, 0u) << "unwarped control: max error " << u.maxInteriorError;
    EXPECT_LE(double(u.silhouetteMismatch), kSilhouetteMismatchFraction * double(u.silhouette));
  }

  // The lookup coordinate the resolve pass used, per covered pixel.
  const FrameReadback fb = r->readback();
  ASSERT_EQ(fb.texel.size(), fb.positions.size());
  size_t pixels = 0, lookupOff = 0;
  float maxLookupError = 0.0f;
  for (size_t i = 0; i < fb.positions.size(); ++i) {
    if (fb.positions[i].w <= 0.0f) continue;
    ++pixels;
    const glm::vec3 want = rtw::warpedLookup(maps, fit.viewProj, glm::vec3(fb.positions[i]));
    const float e = std::max(std::abs(fb.texel[i].x - want.x), std::abs(fb.texel[i].y - want.y));
    maxLookupError = std::max(maxLookupError, e);
    if (!(e <= kLookupTolerance)) ++lookupOff;
  }
  std::printf("[%s sm %d im %d] lookup: %zu pixels, %zu off (> %.0e), max error %.3e\n",
              label.c_str(), k.smRes, k.imRes, pixels, lookupOff, double(kLookupTolerance),
              double(maxLookupError));
  EXPECT_GT(pixels, size_t(w * h / 4));
  EXPECT_EQ(lookupOff, 0u) << "max lookup error " << maxLookupError;
}

// Seed 002's pass (warp.depth = interpolated, tessellation off, warp.split off): the
// vertex shader warps the scene's triangles as loaded and the rasteriser interpolates
// depth in warped space. Against rtw::rasterizeWarpedInterpolated, the same criteria as the
// exact pass: interior texels within kInterpolatedDepthTolerance, silhouettes (the same
// straight warped edges on both sides) within kInterpolatedSilhouetteMismatchFraction.
// Then the same map against the EXACT reference, which it must miss: that is the seed's
// depth error the exact pass removes.
//
// Tolerance: both sides interpolate the plane through the same three warped vertices; the
// GPU's warped positions differ by a few ulp (float warp, fma in the transform) and the
// rasteriser evaluates the plane in float from positions snapped to its sub-pixel grid:
// the depth moves by |dz/dx'| times that, window depth per warped texel times a fraction
// of a texel. Measured max: 1.8e-7 (printed per case); 2e-5 as for the exact pass.
constexpr double kInterpolatedDepthTolerance = 2e-5;
// Same edges on both sides, so only centres within rounding of an edge can flip (GL's
// top-left rule against the reference's inclusive edges). Measured: <= 0.04 %.
constexpr double kInterpolatedSilhouetteMismatchFraction = 0.02;

/// The GPU's interpolated map against the interpolating reference and against the exact one.
struct InterpolatedParity {
  DepthParity interpolated, exact;
};

InterpolatedParity checkInterpolatedParity(const Case& k) {
  SCOPED_TRACE(std::string(k.scene) + " sm " + std::to_string(k.smRes) + " im " +
               std::to_string(k.imRes) + " interpolated");
  InterpolatedParity result;
  DepthParity& d = result.interpolated;
  auto r = test::makeRenderer(k.scene, "rtw-backward");
  EXPECT_TRUE(r);
  if (!r) return result;
  ParamSet& p = r->params();
  EXPECT_FALSE(p.set("resolution", k.smRes));
  EXPECT_FALSE(p.set("im.resolution", k.imRes));
  for (const char* key : {"bias.normal", "bias.slope", "bias.constant"})
    EXPECT_FALSE(p.set(key, 0.0)) << key;
  EXPECT_FALSE(p.setFromString("warp.depth", "interpolated"));
  EXPECT_FALSE(p.set("tessellation", 0));
  EXPECT_FALSE(p.set("warp.split", 0));
  r->requestPublications({"shadow map", "warp.x", "warp.y"});
  const int w = 320, h = 180;
  EXPECT_FALSE(r->renderFrame(w, h, 0));
  test::expectNoGlErrors(*r);
  const Publication& pub = r->publication();
  EXPECT_TRUE(pub.images.count("shadow map"));
  if (!pub.images.count("shadow map")) return result;
  const FloatImage& gpu = pub.images.at("shadow map");
  const rtw::WarpMaps maps{pub.curves.at("warp.x"), pub.curves.at("warp.y")};
  LightFit fit;
  EXPECT_FALSE(fitDirectionalLight(r->camera(), float(w) / float(h), r->scene()->bounds,
                                   r->light().directionalTowards(), FocusSettings{}, fit));
  const std::vector<rtw::LightTriangle> tris = sceneLightTriangles(*r->scene(), fit.viewProj);
  const rtw::WarpedRaster cpu = rtw::rasterizeWarpedInterpolated(maps, k.smRes, tris);
  d = compareDepth(gpu, cpu, tris, kInterpolatedDepthTolerance);
  std::printf(
      "[%s sm %d im %d interpolated] interior: %zu covered + %zu empty, %zu off (> %.0e), max "
      "|gpu - cpu| %.3e; silhouette: %zu, coverage differs on %zu (%.2f %%)\n",
      k.scene, k.smRes, k.imRes, d.interiorCovered, d.interiorEmpty, d.interiorOff,
      kInterpolatedDepthTolerance, d.maxInteriorError, d.silhouette, d.silhouetteMismatch,
      d.silhouette ? 100.0 * double(d.silhouetteMismatch) / double(d.silhouette) : 0.0);
  EXPECT_GT(d.interiorCovered, size_t(k.smRes) * size_t(k.smRes) / 4) << "too little to compare";
  EXPECT_EQ(d.interiorOff, 0u) << "interior texels off; max error " << d.maxInteriorError;
  EXPECT_LE(double(d.silhouetteMismatch),
            kInterpolatedSilhouetteMismatchFraction * double(d.silhouette));
  // The same GPU map against the exact reference: what the seed's interpolation gets wrong.
  const DepthParity& e = result.exact =
      compareDepth(gpu, rtw::rasterizeWarped(maps, k.smRes, tris), tris);
  std::printf(
      "[%s sm %d im %d interpolated vs exact] interior: %zu covered, %zu off (> %.0e), "
      "max %.3e\n",
      k.scene, k.smRes, k.imRes, e.interiorCovered, e.interiorOff, kDepthTolerance,
      e.maxInteriorError);
  return result;
}

TEST(RtwWarpedParity, InterpolatedDepthMatchesTheInterpolatingCpuReference) {
  // plane-box's ground is two triangles: the interpolation misses the exact depth on a
  // large part of it.
  const DepthParity e = checkInterpolatedParity({"plane-box", 256, 128}).exact;
  EXPECT_GT(double(e.interiorOff), 0.25 * double(e.interiorCovered))
      << "the interpolated map should differ from the exact one";
  checkInterpolatedParity({"diagonal", 256, 128});
}

// plane-box: its 20 m ground is two long triangles reaching far outside the focused map,
// seen under a warp concentrated on the shadow; the box and its sides.
TEST(RtwWarpedParity, PlaneBoxDepthMapAndLookupMatchTheExactCpuReference) {
  checkParity({"plane-box", 128, 64});
  checkParity({"plane-box", 256, 128});
  // Low sun-side view at 6 degrees: strong perspective aliasing, a steeper warp.
  checkParity({"plane-box", 256, 128, "grazing"});
}

// diagonal: a long ground quad (two triangles, 84 x 32 m) and a row of thin posts at 45
// degrees to the light's axes.
TEST(RtwWarpedParity, DiagonalDepthMapAndLookupMatchTheExactCpuReference) {
  checkParity({"diagonal", 128, 64});
  checkParity({"diagonal", 256, 128});
}

}  // namespace
}  // namespace sl
