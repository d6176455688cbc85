// The warp's map as the lookup's bias model sees it (WarpFit::mapFrame): metres per unit of
// s and t and window depth per metre against finite differences of the warp's own matrix,
// and depth-only points (casters) that widen the depth range and nothing else.
#include <gtest/gtest.h>

#include <cmath>

#include "algo/ShadowBias.h"
#include "algo/warp/PerspectiveWarp.h"

namespace sl::warp {
namespace {

glm::dvec4 uvzw(const glm::dmat4& m, const glm::dvec3& p) {
  const glm::dvec4 c = m * glm::dvec4(p, 1.0);
  return {glm::dvec3(c) / c.w * 0.5 + 0.5, c.w};
}

struct WarpScene {
  ViewFrustum view;
  std::vector<glm::dvec3> body;
  glm::dvec3 towards;
};

WarpScene alongTheGround() {
  WarpScene s;
  s.view.eye = {0, 2, 0};
  s.view.forward = glm::normalize(glm::dvec3(0, -0.05, -1));
  s.view.up =
      glm::normalize(glm::cross(glm::cross(s.view.forward, glm::dvec3(0, 1, 0)), s.view.forward));
  s.view.nearM = 0.5;
  s.view.farM = 200.0;
  s.view.fovYRad = 1.0;
  s.view.aspect = 16.0 / 9.0;
  const auto c = s.view.corners();
  s.body.assign(c.begin(), c.end());
  s.towards = glm::normalize(glm::dvec3(0.5, 1.2, 0.3));
  return s;
}

TEST(WarpMapFrame, ExtentAndDepthPerMetreFollowTheirPowersOfW) {
  const WarpScene s = alongTheGround();
  for (double eta : {0.0, 0.5, 1.0}) {
    SCOPED_TRACE(eta);
    WarpSettings ws;
    ws.kind = WarpKind::Eta;
    ws.eta = eta;
    WarpFit fit;
    ASSERT_FALSE(fitWarp(s.view, s.body, s.towards, ws, fit));
    ASSERT_TRUE(fit.warped());
    const DepthMapFrame f = fit.mapFrame();
    const glm::dmat4 m(f.viewProj);
    for (double a : {0.1, 0.5, 0.9}) {
      const glm::dvec3 p = glm::mix(s.body[0], s.body[6], a);  // inside the frustum
      const glm::dvec4 q = uvzw(m, p);
      const double w = q.w, h = 1e-4;
      const double ds = uvzw(m, p + h * fit.space.x).x - q.x;
      const double dt = uvzw(m, p + h * fit.space.z).y - q.y;
      const double dz = uvzw(m, p + h * fit.space.y).z - q.z;
      EXPECT_NEAR(h / std::abs(ds), f.extentM.x * std::pow(w, f.extentWPower.x),
                  1e-3 * h / std::abs(ds));
      EXPECT_NEAR(h / std::abs(dt), f.extentM.y * std::pow(w, f.extentWPower.y),
                  1e-3 * h / std::abs(dt));
      EXPECT_NEAR(std::abs(dz) / h, windowDepthPerM(f.depthPerM, float(w), f.depthWPower),
                  1e-3 * std::abs(dz) / h);
      EXPECT_NEAR(uvzw(m, p + h * fit.space.x).y, q.y, 1e-9) << "t does not move with light x";
    }
  }
}

TEST(WarpMapFrame, DepthOnlyPointsWidenOnlyTheDepthRange) {
  const WarpScene s = alongTheGround();
  WarpSettings ws;
  WarpFit plain, widened;
  ASSERT_FALSE(fitWarp(s.view, s.body, s.towards, ws, plain));
  // A caster 50 m above the body's highest point, over its near face (w = n'), where the
  // depth range is narrowest (window depth per metre falls with 1/w).
  glm::dvec3 nearest = s.body[0];
  for (const glm::dvec3& p : s.body)
    if (plain.space.toLight(p).z < plain.space.toLight(nearest).z) nearest = p;
  const glm::dvec3 caster =
      nearest + (plain.hi.y - glm::dot(nearest, plain.space.y) + 50.0) * plain.space.y;
  ws.depthOnly = {caster};
  ASSERT_FALSE(fitWarp(s.view, s.body, s.towards, ws, widened));
  EXPECT_EQ(widened.nPrime, plain.nPrime);
  EXPECT_EQ(widened.lo.x, plain.lo.x);
  EXPECT_EQ(widened.hi.z, plain.hi.z);
  EXPECT_EQ(widened.tanHalfX, plain.tanHalfX);
  EXPECT_GT(widened.hi.y, plain.hi.y + 49.0);
  // The caster is inside the widened map's depth range, outside the plain one's.
  const double zw = uvzw(glm::dmat4(widened.lightProj * widened.lightView), caster).z;
  const double zp = uvzw(glm::dmat4(plain.lightProj * plain.lightView), caster).z;
  EXPECT_GE(zw, 0.0);
  EXPECT_LE(zw, 1.0);
  EXPECT_TRUE(zp < 0.0 || zp > 1.0);
  ws.depthOnly = {glm::dvec3(NAN)};
  EXPECT_EQ(*fitWarp(s.view, s.body, s.towards, ws, widened),
            "warp: a depth-only point is not finite");
}

TEST(WarpMapFrame, WindowDepthPerMetrePower) {
  EXPECT_FLOAT_EQ(windowDepthPerM(8.0f, 2.0f), 2.0f);  // a spot's frustum: w^2
  EXPECT_FLOAT_EQ(windowDepthPerM(8.0f, 2.0f, 1.0f), 4.0f);
}

}  // namespace
}  // namespace sl::warp
