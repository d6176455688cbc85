// The LiSPSM-warped virtual map of fvsm and virtual-tiled (fvsm.warp, tile.warp = lispsm;
// Giegl & Wimmer 2007 use LiSPSM with focusing in every result): the focused warp is the one
// `lispsm` fits (warp::fitFocusedWarp), each tile's matrix is the warp's cropped to the tile's
// uv rectangle (warp::uvRectCrop) and sees exactly its part of the warped map, and on a
// ground plane seen at a grazing angle the SMTMM in the warped map asks for fewer texels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "algo/Focus.h"
#include "algo/fvsm/Fvsm.h"
#include "algo/warp/PerspectiveWarp.h"

namespace sl {
namespace {

glm::dvec3 clipDiv(const glm::dmat4& m, const glm::dvec3& p, double* w = nullptr) {
  const glm::dvec4 c = m * glm::dvec4(p, 1.0);
  if (w) *w = c.w;
  return glm::dvec3(c) / c.w;
}

// A camera 2 m above a 100 m square ground (a 1 m high box of scene bounds), looking along it
// slightly down; the light from the side and above: LiSPSM's textbook case.
struct GroundScene {
  Camera camera;
  Aabb bounds;
  glm::dvec3 towards;
  double aspect = 16.0 / 9.0;
  GroundScene() {
    camera.position = {0.0f, 2.0f, 40.0f};
    camera.target = {0.0f, 1.0f, 20.0f};
    camera.fovYDeg = 50.0f;
    camera.nearM = 0.5f;
    camera.farM = 200.0f;
    bounds.extend(glm::vec3(-50.0f, 0.0f, -50.0f));
    bounds.extend(glm::vec3(50.0f, 1.0f, 50.0f));
    towards = glm::normalize(glm::dvec3(1.0, 1.0, 0.2));
  }
};

TEST(FvsmWarp, TheFocusedWarpIsFitWarpOnViewFrustumIntersectScene) {
  const GroundScene s;
  warp::WarpSettings settings;
  settings.kind = warp::WarpKind::Lispsm;
  warp::WarpFit focused;
  ASSERT_FALSE(warp::fitFocusedWarp(s.camera, s.aspect, s.bounds, s.towards, settings, focused));
  ASSERT_TRUE(focused.warped()) << focused.fallbackReason;
  // By hand: the intersection body, the box's corners as depth-only points.
  const auto inside = intersectFrustumWithBox(
      s.camera.frustumCorners(float(s.aspect), s.camera.nearM, s.camera.farM), s.bounds);
  ASSERT_FALSE(inside.empty());
  const std::vector<glm::dvec3> body(inside.begin(), inside.end());
  const auto box = s.bounds.corners();
  settings.depthOnly.assign(box.begin(), box.end());
  const warp::ViewFrustum view =
      warp::ViewFrustum::fromCamera(s.camera, s.aspect).clippedToBody(body);
  warp::WarpFit byHand;
  ASSERT_FALSE(warp::fitWarp(view, body, s.towards, settings, byHand));
  EXPECT_EQ(glm::mat4(focused.mapFrame().viewProj), glm::mat4(byHand.mapFrame().viewProj));
  EXPECT_DOUBLE_EQ(focused.nPrime, byHand.nPrime);
  EXPECT_DOUBLE_EQ(focused.nPrime, focused.nPrimeLispsm) << "eta = 0: n' is LiSPSM's";
  // Every point of the body lies in the warped map's [0, 1]² and depth range.
  const glm::dmat4 m(focused.mapFrame().viewProj);
  for (const glm::dvec3& p : body) {
    const glm::dvec3 ndc = clipDiv(m, p);
    EXPECT_LE(std::abs(ndc.x), 1.0 + 1e-5);
    EXPECT_LE(std::abs(ndc.y), 1.0 + 1e-5);
    EXPECT_LE(std::abs(ndc.z), 1.0 + 1e-5);
  }
}

TEST(FvsmWarp, UvRectCropMapsTheTileOntoItsOwnClipSquare) {
  const glm::dmat4 crop = warp::uvRectCrop({0.25, 0.5}, {0.5, 1.0});
  // The rectangle's corners go to clip ±1 for any w (the shift is times w).
  for (double w : {1.0, 0.3, 7.0}) {
    const glm::dvec4 lo = crop * glm::dvec4((2 * 0.25 - 1) * w, (2 * 0.5 - 1) * w, 0.2, w);
    const glm::dvec4 hi = crop * glm::dvec4((2 * 0.5 - 1) * w, (2 * 1.0 - 1) * w, 0.2, w);
    EXPECT_NEAR(lo.x / lo.w, -1.0, 1e-12);
    EXPECT_NEAR(lo.y / lo.w, -1.0, 1e-12);
    EXPECT_NEAR(hi.x / hi.w, 1.0, 1e-12);
    EXPECT_NEAR(hi.y / hi.w, 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(lo.z, 0.2);
    EXPECT_DOUBLE_EQ(lo.w, w);
  }
}

// Every tile of an n x n virtual map cut from the LiSPSM warp: a world point's uv in its tile
// is n uv − (i, j) of its uv in the warped map, its depth and w the warp's; so the tiles put
// together are the warped map, texel for texel.
TEST(FvsmWarp, TilesOfTheWarpedMapAreItsCrops) {
  const GroundScene s;
  warp::WarpSettings settings;
  settings.kind = warp::WarpKind::Lispsm;
  warp::WarpFit fit;
  ASSERT_FALSE(warp::fitFocusedWarp(s.camera, s.aspect, s.bounds, s.towards, settings, fit));
  ASSERT_TRUE(fit.warped());
  const glm::dmat4 full(fit.mapFrame().viewProj);
  const int n = 4;
  int checked = 0;
  // Points inside the body (view frustum ∩ scene): mixes of its vertices.
  const std::vector<glm::dvec3> body = warp::focusedBody(s.camera, s.aspect, s.bounds).body;
  ASSERT_GE(body.size(), 4u);
  for (int a = 0; a <= 10; ++a) {
    for (int b = 0; b <= 10; ++b) {
      const glm::dvec3& v0 = body[std::size_t(a + b) % body.size()];
      const glm::dvec3& v1 = body[std::size_t(3 * a + 1) % body.size()];
      const glm::dvec3& v2 = body[std::size_t(5 * b + 2) % body.size()];
      const glm::dvec3 p = glm::mix(glm::mix(v0, v1, a / 10.0), v2, b / 20.0);
      double w = 0.0;
      const glm::dvec3 ndc = clipDiv(full, p, &w);
      const glm::dvec2 uv = glm::dvec2(ndc) * 0.5 + 0.5;
      ASSERT_TRUE(uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0) << a << " " << b;
      const glm::ivec2 cell = glm::min(glm::ivec2(uv * double(n)), glm::ivec2(n - 1));
      const glm::dvec2 lo = glm::dvec2(cell) / double(n), hi = glm::dvec2(cell + 1) / double(n);
      double wTile = 0.0;
      const glm::dvec3 tile = clipDiv(warp::uvRectCrop(lo, hi) * full, p, &wTile);
      const glm::dvec2 uvTile = glm::dvec2(tile) * 0.5 + 0.5;
      EXPECT_NEAR(uvTile.x, uv.x * n - cell.x, 1e-9);
      EXPECT_NEAR(uvTile.y, uv.y * n - cell.y, 1e-9);
      EXPECT_GE(uvTile.x, -1e-9);
      EXPECT_LE(uvTile.x, 1.0 + 1e-9);
      EXPECT_NEAR(tile.z, ndc.z, 1e-12) << "the same depth";
      EXPECT_DOUBLE_EQ(wTile, w) << "the same w: the bias model's w powers hold per tile";
      ++checked;
    }
  }
  EXPECT_GT(checked, 60);
}

// The mechanism that makes LiSPSM cheaper for fvsm: on the ground seen at a grazing angle,
// the uniform map must be fine everywhere the camera is near (a high need there), while the
// warp spends more of its uv near the camera; the SMTMM's needs on the CPU reference
// (buildSmtmm on the plane's exact eye depths) ask for fewer texels in all (the sum over
// entries of 2^(need u + need v), the texels of one map fine enough for each entry).
TEST(FvsmWarp, TheWarpedSmtmmAsksForFewerTexelsOnTheGround) {
  const GroundScene s;
  const int w = 160, h = 90;
  const glm::dmat4 view(s.camera.view());
  const double tanY = std::tan(glm::radians(double(s.camera.fovYDeg)) * 0.5);
  const double tanX = tanY * s.aspect;
  std::vector<float> depth(std::size_t(w) * h, 0.0f);
  const glm::dmat4 eyeToWorld = glm::inverse(view);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const glm::dvec2 ndc((x + 0.5) / w * 2.0 - 1.0, (y + 0.5) / h * 2.0 - 1.0);
      const glm::dvec3 dirEye(ndc.x * tanX, ndc.y * tanY, -1.0);  // at eye depth 1
      const glm::dvec3 o(eyeToWorld * glm::dvec4(0, 0, 0, 1));
      const glm::dvec3 d = glm::dvec3(eyeToWorld * glm::dvec4(dirEye, 0.0));
      if (d.y >= 0.0) continue;
      const double t = -o.y / d.y;  // ground y = 0; eye depth = t (dirEye.z = −1)
      const glm::dvec3 hit = o + t * d;
      if (std::abs(hit.x) > 50.0 || std::abs(hit.z) > 50.0 || t > s.camera.farM) continue;
      depth[std::size_t(y) * w + x] = float(t);
    }
  }
  fvsm::EyeDepthView ev;
  ev.width = w;
  ev.height = h;
  ev.tanHalfFovX = tanX;
  ev.tanHalfFovY = tanY;
  ev.eyeDepthM = depth;
  glm::dmat4 uvFromClip(1.0);
  uvFromClip[0][0] = uvFromClip[1][1] = 0.5;
  uvFromClip[3][0] = uvFromClip[3][1] = 0.5;

  LightFit ortho;
  ASSERT_FALSE(fitDirectionalLight(s.camera, float(s.aspect), s.bounds, glm::vec3(s.towards),
                                   FocusSettings{}, ortho));
  warp::WarpSettings settings;
  settings.kind = warp::WarpKind::Lispsm;
  warp::WarpFit fit;
  ASSERT_FALSE(warp::fitFocusedWarp(s.camera, s.aspect, s.bounds, s.towards, settings, fit));
  ASSERT_TRUE(fit.warped());
  const auto smtmmOf = [&](const glm::mat4& lightViewProj) {
    return fvsm::buildSmtmm(ev, {40, 23}, uvFromClip * glm::dmat4(lightViewProj) * eyeToWorld,
                            fvsm::FootprintMeasure::Box);
  };
  const auto uniform = smtmmOf(ortho.viewProj);
  const auto warped = smtmmOf(fit.mapFrame().viewProj);
  double texelsUniform = 0.0, texelsWarped = 0.0;
  int covered = 0, maxUniform = 0, maxWarped = 0;
  for (std::size_t i = 0; i < uniform.size(); ++i) {
    ASSERT_EQ(uniform[i].covered, warped[i].covered) << i;
    if (!uniform[i].covered) continue;
    ++covered;
    texelsUniform += std::exp2(uniform[i].needLog2.x + uniform[i].needLog2.y);
    texelsWarped += std::exp2(warped[i].needLog2.x + warped[i].needLog2.y);
    maxUniform = std::max({maxUniform, uniform[i].needLog2.x, uniform[i].needLog2.y});
    maxWarped = std::max({maxWarped, warped[i].needLog2.x, warped[i].needLog2.y});
  }
  std::printf("ground, %d entries: summed need %.3g texels uniform, %.3g LiSPSM; max log2 %d, %d\n",
              covered, texelsUniform, texelsWarped, maxUniform, maxWarped);
  EXPECT_GT(covered, 300);
  EXPECT_LT(texelsWarped, 0.5 * texelsUniform);
  EXPECT_LT(maxWarped, maxUniform);
}

}  // namespace
}  // namespace sl
