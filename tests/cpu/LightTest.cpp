// The light model (algo/Light), the spot's perspective frustum (algo/Focus fitSpotLight) and
// the shared bias model's perspective case (algo/ShadowBias): exact answers on small cases.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "algo/Focus.h"
#include "algo/Light.h"
#include "algo/ShadowBias.h"

namespace sl {
namespace {

bool near(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) {
  return glm::length(a - b) <= eps;
}

TEST(Light, DirectionalKeepsAzimuthElevationAndDefaults) {
  const Light l;
  EXPECT_EQ(l.type, LightType::Directional);
  EXPECT_FLOAT_EQ(l.azimuthDeg, 35.0f);
  EXPECT_FLOAT_EQ(l.elevationDeg, 50.0f);
  const Light up = Light::directional(0.0f, 90.0f);
  EXPECT_TRUE(near(up.towardsLight({3, -2, 7}), {0, 1, 0}));
  const Light east = Light::directional(90.0f, 0.0f);  // from +z towards +x
  EXPECT_TRUE(near(east.towardsLight({0, 0, 0}), {1, 0, 0}));
  EXPECT_TRUE(east.illuminates({1e6f, -5, 3}));
  EXPECT_FLOAT_EQ(east.falloff({1, 2, 3}), 1.0f);
  const Light back = Light::directionalFromTowards({0.25f, 0.8660254f, 0.4330127f});
  EXPECT_NEAR(back.azimuthDeg, 30.0f, 1e-3f);
  EXPECT_NEAR(back.elevationDeg, 60.0f, 1e-3f);
}

TEST(Light, PointTowardsAndRange) {
  const Light p = Light::point({0, 4, 0}, 5.0f);
  EXPECT_FALSE(p.validate());
  EXPECT_TRUE(near(p.towardsLight({0, 0, 0}), {0, 1, 0}));
  EXPECT_TRUE(near(p.towardsLight({3, 4, 0}), {-1, 0, 0}));
  EXPECT_TRUE(p.illuminates({3, 0, 0}));                           // 5 m: on the range
  EXPECT_FALSE(p.illuminates({3.1f, 0, 0}));                       // beyond
  EXPECT_TRUE(Light::point({0, 4, 0}).illuminates({1e4f, 0, 0}));  // range 0 = infinite
  EXPECT_FLOAT_EQ(p.falloff({0, 4, 0}), 1.0f);
  EXPECT_NEAR(p.falloff({0, 4 - 2.5f, 0}), (1 - 0.0625f) * (1 - 0.0625f), 1e-6f);  // d/r = 1/2
  EXPECT_FLOAT_EQ(p.falloff({0, -1.01f, 0}), 0.0f);
}

TEST(Light, SpotConeInsideOutsideAndFalloff) {
  const Light s = Light::spot({0, 10, 0}, {0, -2, 0}, 30.0f, 20.0f);
  EXPECT_FALSE(s.validate());
  EXPECT_TRUE(near(s.spotAxis(), {0, -1, 0}));
  const float r29 = 10.0f * std::tan(glm::radians(29.0f)),
              r31 = 10.0f * std::tan(glm::radians(31.0f));
  EXPECT_TRUE(s.illuminates({r29, 0, 0}));
  EXPECT_FALSE(s.illuminates({r31, 0, 0}));
  EXPECT_FALSE(s.illuminates({0, 11, 0}));      // behind
  EXPECT_FLOAT_EQ(s.falloff({0, 0, 0}), 1.0f);  // inside the inner cone
  const float r25 = 10.0f * std::tan(glm::radians(25.0f));
  const float f = s.falloff({0, 0, r25});
  EXPECT_GT(f, 0.0f);
  EXPECT_LT(f, 1.0f);
  EXPECT_FLOAT_EQ(s.falloff({r31, 0, 0}), 0.0f);
}

TEST(Light, ValidateNamesWhatIsWrong) {
  auto err = [](const Light& l) { return l.validate().value_or(""); };
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(err(Light::directional(nan, 10)).find("not finite"), std::string::npos);
  EXPECT_NE(err(Light::directional(0, 95)).find("elevation"), std::string::npos);
  EXPECT_NE(err(Light::point({nan, 0, 0})).find("position"), std::string::npos);
  EXPECT_NE(err(Light::point({0, 1, 0}, -1)).find("range"), std::string::npos);
  EXPECT_NE(err(Light::spot({0, 1, 0}, {0, 0, 0}, 30)).find("direction is zero"),
            std::string::npos);
  EXPECT_NE(err(Light::spot({0, 1, 0}, {0, -1, 0}, 90)).find("outer cone"), std::string::npos);
  EXPECT_NE(err(Light::spot({0, 1, 0}, {0, -1, 0}, 0)).find("outer cone"), std::string::npos);
  EXPECT_NE(err(Light::spot({0, 1, 0}, {0, -1, 0}, 30, 40)).find("inner cone"), std::string::npos);
  EXPECT_NE(err(Light::spot({0, 1, 0}, {0, -1, 0}, 30, -1)).find("inner cone"), std::string::npos);
  EXPECT_NE(err(Light::spot({0, 1, 0}, {0, -1, 0}, 30, 0, -2)).find("range"), std::string::npos);
  EXPECT_FALSE(Light::spot({0, 1, 0}, {0, -1, 0}, kMaxSpotConeDeg, kMaxSpotConeDeg, 3).validate());
}

// One rule for every entry point (--light, presets, suites, the GUI): no cone wider than
// kMaxSpotConeDeg; the glTF loader narrows its (legal) wider cones to it instead.
TEST(Light, SpotConesWiderThanTheLimitAreRefusedNamingIt) {
  const std::string e =
      Light::spot({0, 1, 0}, {0, -1, 0}, 89.9999f).validate().value_or("accepted");
  EXPECT_EQ(e,
            "spot light: outer cone angle must be in (0, 89] degrees, got 89.9999 "
            "(kMaxSpotConeDeg: one perspective shadow map covers less than a half-space)");
  EXPECT_TRUE(
      Light::spot({0, 1, 0}, {0, -1, 0}, std::nextafter(kMaxSpotConeDeg, 90.0f)).validate());
}

TEST(Light, DescribeAndTypeNames) {
  EXPECT_EQ(Light::directional(35, 50).describe(), "directional az 35 el 50");
  EXPECT_EQ(Light::point({0, 4, 0}, 10).describe(), "point at (0, 4, 0) range 10 m");
  EXPECT_EQ(Light::spot({0, 4, 0}, {0, -1, 0}, 30, 20).describe(),
            "spot at (0, 4, 0) dir (0, -1, 0) cone 30/20 deg range inf");
  EXPECT_EQ(lightTypeList({LightType::Directional, LightType::Spot}), "directional, spot");
  EXPECT_EQ(lightTypeFromName("point"), LightType::Point);
  EXPECT_FALSE(lightTypeFromName("area"));
}

// ---- the spot's frustum --------------------------------------------------------------------

TEST(FitSpotLight, EveryPointInTheConeLandsInTheMap) {
  Aabb box;
  box.extend(glm::vec3(-6, 0, -6));
  box.extend(glm::vec3(6, 1.5f, 6));
  const Light s = Light::spot({1.5f, 5, 2}, {-0.25f, -5, -2}, 40, 30, 20);
  LightFit fit;
  ASSERT_FALSE(fitSpotLight(s, box, fit));
  EXPECT_TRUE(fit.perspective);
  EXPECT_GT(fit.nearM, 0.0f);
  EXPECT_LT(fit.nearM, fit.farM);
  EXPECT_NEAR(fit.extentM.x, 2.0f * std::tan(glm::radians(40.0f)), 1e-5f);
  int inside = 0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j)
      for (float y : {0.0f, 0.75f, 1.5f}) {
        glm::vec3 p(-6 + 0.3f * float(i), y, -6 + 0.3f * float(j));
        if (!s.illuminates(p)) continue;
        ++inside;
        glm::vec4 c = fit.viewProj * glm::vec4(p, 1);
        ASSERT_GT(c.w, 0.0f);
        glm::vec3 ndc = glm::vec3(c) / c.w;
        EXPECT_LE(std::abs(ndc.x), 1.0f);
        EXPECT_LE(std::abs(ndc.y), 1.0f);
        EXPECT_LE(std::abs(ndc.z), 1.0f) << p.x << " " << p.y << " " << p.z;
      }
  EXPECT_GT(inside, 1000);
}

TEST(FitSpotLight, RefusesWhatItCannotFit) {
  Aabb box;
  box.extend(glm::vec3(-1, 0, -1));
  box.extend(glm::vec3(1, 1, 1));
  LightFit fit;
  EXPECT_TRUE(fitSpotLight(Light::point({0, 3, 0}), box, fit));
  EXPECT_TRUE(fitSpotLight(Light::spot({0, 3, 0}, {0, -1, 0}, 30), Aabb{}, fit));
}

// A spot aimed away from the scene, or whose range ends before it, lights nothing: a valid
// frustum (the frame renders, all shadowed), not an error.
TEST(FitSpotLight, SceneOutsideTheConeIsAValidEmptyFit) {
  Aabb box;
  box.extend(glm::vec3(-1, 0, -1));
  box.extend(glm::vec3(1, 1, 1));
  for (const Light& s : {Light::spot({0, 3, 0}, {0, 1, 0}, 30),               // looks away
                         Light::spot({0, 30, 0}, {0, -1, 0}, 30, 0, 5),       // range
                         Light::spot({0, 3, 0}, {0, -1, 0}, 30, 0, 1.5f)}) {  // tiny range
    LightFit fit;
    ASSERT_FALSE(fitSpotLight(s, box, fit));
    EXPECT_TRUE(fit.sceneOutside);
    EXPECT_GT(fit.nearM, 0.0f);
    EXPECT_LT(fit.nearM, fit.farM);
    for (const glm::vec3& c : box.corners()) EXPECT_FALSE(s.illuminates(c));
  }
  LightFit fit;
  ASSERT_FALSE(fitSpotLight(Light::spot({0, 3, 0}, {0, -1, 0}, 30), box, fit));
  EXPECT_FALSE(fit.sceneOutside);
}

// ---- the bias model with a perspective matrix ----------------------------------------------

/// Window coordinates (uv, depth in 0..1) of world point p.
glm::vec3 windowOf(const glm::mat4& m, const glm::vec3& p) {
  glm::vec4 c = m * glm::vec4(p, 1);
  return glm::vec3(c) / c.w * 0.5f + 0.5f;
}

TEST(ShadowBias, OrthographicPlaneMatrixIsTheNormalMatrix) {
  const glm::mat4 m = glm::ortho(-3.f, 4.f, -2.f, 5.f, 0.5f, 30.f) *
                      glm::lookAt(glm::vec3(2, 9, 1), glm::vec3(0), glm::vec3(0, 1, 0));
  const LightPlaneMatrix p = lightPlaneMatrix(m);
  EXPECT_EQ(p.normal, lightNormalMatrix(m));
  EXPECT_EQ(p.offset, glm::vec3(0.0f));
  const glm::vec3 N = glm::normalize(glm::vec3(0.2f, 1, -0.3f));
  EXPECT_EQ(receiverDepthGradient(p, N, {5, 6, 7}), receiverDepthGradient(lightNormalMatrix(m), N));
  EXPECT_FLOAT_EQ(depthPerMAtUnitW(false, 25.0f, 0, 0), 1.0f / 25.0f);
  EXPECT_FLOAT_EQ(windowDepthPerM(0.04f, 1.0f), 0.04f);
}

TEST(ShadowBias, PerspectiveGradientMatchesThePlaneSeenThroughTheMatrix) {
  const float n = 0.8f, f = 14.0f;
  const glm::mat4 m = glm::perspective(glm::radians(70.0f), 1.0f, n, f) *
                      glm::lookAt(glm::vec3(1, 6, 2), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));
  const LightPlaneMatrix plane = lightPlaneMatrix(m);
  EXPECT_NE(plane.offset, glm::vec3(0.0f));
  for (glm::vec3 N : {glm::vec3(0, 1, 0), glm::normalize(glm::vec3(0.4f, 1, -0.2f)),
                      glm::normalize(glm::vec3(1, 0.3f, 0.5f))}) {
    const glm::vec3 P(0.3f, 0.2f, -0.4f);
    // Two tangent directions of the plane through P.
    glm::vec3 t1 = glm::normalize(glm::cross(N, glm::vec3(0.3f, 0.1f, 1)));
    glm::vec3 t2 = glm::cross(N, t1);
    const glm::vec3 w0 = windowOf(m, P);
    const glm::vec2 g = receiverDepthGradient(plane, N, P);
    // Window depth of far-away points of the same plane, predicted from the gradient:
    // affine in uv, so exact up to rounding even a metre away.
    for (glm::vec3 q : {P + 0.7f * t1, P - 0.5f * t2, P + 0.9f * t1 + 0.6f * t2}) {
      const glm::vec3 w = windowOf(m, q);
      const float predicted = receiverDepthAt(glm::vec2(w0), w0.z, g, glm::vec2(w));
      EXPECT_NEAR(predicted, w.z, 2e-5f) << N.x << " " << N.y << " " << N.z;
    }
  }
  // Window depth per metre along the axis at view depth d: f n / ((f - n) d^2).
  const float d = 6.0f, perM = windowDepthPerM(depthPerMAtUnitW(true, 0, n, f), d);
  const glm::vec3 eye(1, 6, 2), axis = glm::normalize(-eye);
  const float dz =
      windowOf(m, eye + axis * (d + 0.01f)).z - windowOf(m, eye + axis * (d - 0.01f)).z;
  EXPECT_NEAR(perM, dz / 0.02f, 1e-3f * perM);
}

}  // namespace
}  // namespace sl
