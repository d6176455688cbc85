// Stamminger and Drettakis' post-perspective shadow map (algo/warp/PostPerspective): the
// three light cases (point in front, inverted behind, directional across), the slide-back,
// the fallback for a light along the view axis, and the bias model's projective frame.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "algo/ShadowBias.h"
#include "algo/warp/PostPerspective.h"

using namespace sl;
using namespace sl::warp;

namespace {

ViewFrustum camera() {
  ViewFrustum v;
  v.eye = {0, 1.7, 0};
  v.forward = {0, 0, -1};
  v.up = {0, 1, 0};
  v.nearM = 0.5;
  v.farM = 40.0;
  v.fovYRad = glm::radians(60.0);
  v.aspect = 1.0;
  return v;
}

/// The view frustum's corners as the body (the whole frustum is the receiver region).
std::vector<glm::dvec3> frustumBody(const ViewFrustum& v) {
  const auto c = v.corners();
  return {c.begin(), c.end()};
}

const glm::dvec3 kBoxLo(-60, -1, -60), kBoxHi(60, 20, 20);

PsmFit fitFor(const glm::dvec3& towardsLight, const ViewFrustum& v = camera()) {
  const std::vector<glm::dvec3> body = frustumBody(v);
  const std::vector<glm::dvec3> casters = castersTowardsLight(body, towardsLight, kBoxLo, kBoxHi);
  PsmFit fit;
  const auto err = fitPostPerspective(v, body, casters, towardsLight, PsmSettings{}, fit);
  EXPECT_FALSE(err) << *err;
  return fit;
}

/// Receivers inside the frustum and occluders up their light rays: same uv, the occluder
/// nearer the light (smaller window depth); everything in the map.
void expectRaysAndOrder(const PsmFit& fit, const glm::dvec3& towardsLight) {
  const ViewFrustum v = camera();
  const glm::dvec3 L = glm::normalize(towardsLight);
  for (double depth : {0.6, 2.0, 8.0, 30.0})
    for (double sx : {-0.8, 0.0, 0.7})
      for (double sy : {-0.9, 0.5}) {
        const glm::dvec3 P =
            v.eye + depth * (v.forward + sx * v.tanHalfX() * v.right() + sy * v.tanHalfY() * v.up);
        const glm::dvec3 r = fit.mapUvz(P);
        EXPECT_GE(r.x, -1e-6);
        EXPECT_LE(r.x, 1 + 1e-6);
        EXPECT_GE(r.y, -1e-6);
        EXPECT_LE(r.y, 1 + 1e-6);
        EXPECT_GE(r.z, 0.0);
        EXPECT_LE(r.z, 1.0);
        for (double s : {0.3, 2.0}) {
          const glm::dvec3 O = P + s * L;
          if (O.y > kBoxHi.y) continue;
          const glm::dvec3 o = fit.mapUvz(O);
          EXPECT_NEAR(o.x, r.x, 1e-7) << "depth " << depth << " s " << s;
          EXPECT_NEAR(o.y, r.y, 1e-7) << "depth " << depth << " s " << s;
          EXPECT_LT(o.z, r.z) << "the occluder must be nearer the light; depth " << depth;
        }
      }
}

}  // namespace

TEST(PostPerspective, LightInFrontIsAPointLightAtItsVanishingPoint) {
  const glm::dvec3 towards(0.2, 0.6, -0.7);  // ahead of the viewer, above
  const PsmFit fit = fitFor(towards);
  EXPECT_EQ(fit.lightCase, PsmLightCase::Point);
  EXPECT_GT(fit.lightPP.w, 0.0);
  expectRaysAndOrder(fit, towards);
}

TEST(PostPerspective, LightBehindTheViewerIsInvertedAndKeepsTheDepthOrder) {
  const glm::dvec3 towards(-0.3, 0.6, 0.75);  // behind the viewer, above
  const PsmFit fit = fitFor(towards);
  EXPECT_EQ(fit.lightCase, PsmLightCase::Inverted);
  EXPECT_LT(fit.lightPP.w, 0.0);
  expectRaysAndOrder(fit, towards);
  // Without the negated depth row the order would be reversed: an occluder then reads
  // farther than its receiver. The inverted map's depth decreases away from L'.
  const glm::dvec3 P = camera().eye + 5.0 * camera().forward;
  EXPECT_LT(fit.mapUvz(P + 1.0 * glm::normalize(towards)).z, fit.mapUvz(P).z);
}

TEST(PostPerspective, LightAcrossTheViewIsDirectionalInPostPerspectiveSpace) {
  const glm::dvec3 towards(0.3, 1.0, 0.0);  // perpendicular to the view vector
  const PsmFit fit = fitFor(towards);
  EXPECT_EQ(fit.lightCase, PsmLightCase::Directional);
  EXPECT_NEAR(fit.lightPP.w, 0.0, 1e-12);
  expectRaysAndOrder(fit, towards);
  // The warp of an overhead light: near receivers get more of the map than far ones.
  const ViewFrustum v = camera();
  const double nearSpan =
      fit.mapUvz(v.eye + 1.0 * v.forward).y - fit.mapUvz(v.eye + 2.0 * v.forward).y;
  const double farSpan =
      fit.mapUvz(v.eye + 20.0 * v.forward).y - fit.mapUvz(v.eye + 21.0 * v.forward).y;
  EXPECT_GT(std::abs(nearSpan), 10.0 * std::abs(farSpan));
}

TEST(PostPerspective, CastersBehindTheViewerSlideTheCameraBack) {
  const glm::dvec3 towards(0.0, 0.5, 1.0);  // low, from behind: casters behind the eye
  const PsmFit fit = fitFor(towards);
  EXPECT_GT(fit.slideBackM, 0.0);
  // The near plane stays where the body starts, seen from the slid eye.
  EXPECT_NEAR(fit.nearM, camera().nearM + fit.slideBackM, 1e-9);
  // A caster behind the eye on a receiver's ray is in front of the virtual camera and in the map.
  const glm::dvec3 P = camera().eye + glm::dvec3(0, -1.5, -3.0);
  const glm::dvec3 O = P + 6.0 * glm::normalize(towards);
  ASSERT_LT(glm::dot(O - camera().eye, camera().forward), 0.0);
  const glm::dvec4 h = fit.viewProj * glm::dvec4(O, 1.0);
  EXPECT_GT(h.w, 0.0);
  const glm::dvec3 o = fit.mapUvz(O), r = fit.mapUvz(P);
  EXPECT_NEAR(o.x, r.x, 1e-7);
  EXPECT_NEAR(o.y, r.y, 1e-7);
  EXPECT_GE(o.z, 0.0);
  EXPECT_LT(o.z, r.z);
}

TEST(PostPerspective, LightExactlyAlongTheViewAxisFallsBackToUniformAndSaysWhy) {
  for (const glm::dvec3 towards : {glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1)}) {
    const PsmFit fit = fitFor(towards);
    EXPECT_TRUE(fit.uniform());
    EXPECT_NE(fit.reason.find("view axis"), std::string::npos) << fit.reason;
  }
}

TEST(PostPerspective, BadInputIsNamed) {
  PsmFit fit;
  const std::vector<glm::dvec3> none;
  auto err = fitPostPerspective(camera(), none, none, {0, 1, 0}, PsmSettings{}, fit);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("empty"), std::string::npos);
  const std::vector<glm::dvec3> body = frustumBody(camera());
  err = fitPostPerspective(camera(), body, none, {0, 0, 0}, PsmSettings{}, fit);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("light direction"), std::string::npos);
  PsmSettings bad;
  bad.extraSlideM = -1.0;
  err = fitPostPerspective(camera(), body, none, {0, 1, 0}, bad, fit);
  ASSERT_TRUE(err);
  EXPECT_NE(err->find("slide"), std::string::npos);
}

TEST(PostPerspective, ExtraSlideBackWeakensTheWarp) {
  const glm::dvec3 towards(0.3, 1.0, -0.2);
  const ViewFrustum v = camera();
  const std::vector<glm::dvec3> body = frustumBody(v);
  const auto casters = castersTowardsLight(body, towards, kBoxLo, kBoxHi);
  PsmFit paper, slid;
  PsmSettings s;
  ASSERT_FALSE(fitPostPerspective(v, body, casters, towards, s, paper));
  s.extraSlideM = 10.0;
  ASSERT_FALSE(fitPostPerspective(v, body, casters, towards, s, slid));
  EXPECT_NEAR(slid.slideBackM, paper.slideBackM + 10.0, 1e-9);
  auto share = [&](const PsmFit& f) {  // the map's share given to the first 2 m
    return std::abs(f.mapUvz(v.eye + 0.5 * v.forward).y - f.mapUvz(v.eye + 2.5 * v.forward).y);
  };
  EXPECT_LT(share(slid), share(paper));
}

// The bias model's projective frame: metres per uv from the matrix's derivatives equal the
// orthographic extent for an orthographic matrix, and match finite differences on the PSM.
TEST(PostPerspective, ProjectiveBiasFrameMatchesTheMatrix) {
  glm::mat4 ortho(1.0f);
  ortho[0][0] = 2.0f / 8.0f;   // x: 8 m across
  ortho[2][1] = 2.0f / 20.0f;  // world z -> clip y: 20 m
  ortho[1][2] = -2.0f / 5.0f;  // world y (towards the light) -> depth: 5 m
  const glm::vec2 perUv = projectiveMetresPerUv(ortho, {1, 2, 3}, {0, 1, 0});
  EXPECT_NEAR(perUv.x, 8.0f, 1e-4f);
  EXPECT_NEAR(perUv.y, 20.0f, 1e-4f);
  EXPECT_NEAR(projectiveDepthPerM(ortho, {1, 2, 3}, {0, 1, 0}), 1.0f / 5.0f, 1e-6f);

  const glm::dvec3 towards(-0.3, 0.6, 0.75);
  const PsmFit fit = fitFor(towards);
  const DepthMapFrame frame = fit.mapFrame();
  ASSERT_TRUE(frame.projective);
  const glm::dvec3 P = camera().eye + glm::dvec3(0.4, -1.2, -6.0);
  const glm::vec2 m = projectiveMetresPerUv(frame.viewProj, glm::vec3(P), glm::vec3(towards));
  // Moving across the light by e changes uv by J e: |J^-1| columns bound the uv step back.
  const glm::dvec3 L = glm::normalize(towards);
  const glm::dvec3 e1 = glm::normalize(glm::cross(L, glm::dvec3(0, 0, 1)));
  const double h = 1e-3;
  const glm::dvec2 du = glm::dvec2(fit.mapUvz(P + h * e1)) - glm::dvec2(fit.mapUvz(P));
  // A step of h metres moves uv by at least h / max(m) in some direction and never more than
  // h / min over the columns' shortest: check it is consistent with the column lengths.
  EXPECT_GT(glm::length(du), 0.0);
  EXPECT_LE(h / glm::length(du), 1.01 * std::sqrt(double(m.x) * m.x + double(m.y) * m.y));
  const float dz = projectiveDepthPerM(frame.viewProj, glm::vec3(P), glm::vec3(towards));
  const double fd = std::abs(fit.mapUvz(P + h * L).z - fit.mapUvz(P).z) / h;
  EXPECT_NEAR(dz, fd, 0.02 * fd);
}

// The near plane is pushed to the nearest scene part in view: a ground box under an eye
// 1.7 m up, looking level with a 60 degree field: the frustum's lower plane meets the
// ground's top at 1.7 / tan(30 degrees); a box behind the eye is not in view.
TEST(PostPerspective, NearestDepthInViewIsWhereTheFrustumMeetsTheGround) {
  Aabb ground;
  ground.extend({-50, -1, -50});
  ground.extend({50, 0, 50});
  Aabb behind;
  behind.extend({-1, 0, 5});
  behind.extend({1, 2, 6});
  const std::vector<Aabb> boxes{ground, behind};
  const auto d = nearestDepthInView(camera(), boxes);
  ASSERT_TRUE(d);
  EXPECT_NEAR(*d, 1.7 / std::tan(glm::radians(30.0)), 1e-3);
  EXPECT_FALSE(nearestDepthInView(camera(), std::span<const Aabb>(&behind, 1)));
}
