// The shared bias model's CPU mirror (algo/ShadowBias.h) per selected map: a map split into
// 2x2 sub-maps, each with its own matrix, must see a receiver exactly as the whole map
// does — same plane depth at the same texel centre, same bias — because the model works in
// the selected map's light uv with that map's local texel size. Orthographic (directional)
// and perspective (spot) maps alike: the sub-map of a perspective map is perspective too,
// and the w-divide, texel size x w and depth per metre / w^2 happen per map.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "algo/ShadowBias.h"

namespace sl {
namespace {

// Splits `whole` into its 2x2 sub-maps and checks that each sees the receivers of a tilted
// plane exactly as the whole map does.
void expectSubMapsMatchWholeMap(const DepthMapFrame& whole, glm::vec3 towardsLightDir,
                                bool pointLight, glm::vec3 lightPos) {
  constexpr int kRes = 1024;
  const ShadowBiasSettings bias{0.5f, 0.25f, 0.001f};

  // A tilted receiver at a few points spread over all four quarters.
  const glm::vec3 N = glm::normalize(glm::vec3(0.2f, 1.0f, -0.4f));
  for (glm::vec3 P : {glm::vec3(-4.0f, 0.3f, -3.0f), glm::vec3(5.0f, -0.2f, -2.0f),
                      glm::vec3(-3.0f, 0.1f, 6.0f), glm::vec3(2.5f, 0.4f, 4.5f)}) {
    const glm::vec3 towardsLight = pointLight ? glm::normalize(lightPos - P) : towardsLightDir;
    const MapReceiver w = receiverInMap(whole, P, N, towardsLight, glm::vec2(1.0f / kRes), bias);
    const int kx = w.uv.x >= 0.5f, ky = w.uv.y >= 0.5f;
    SCOPED_TRACE("sub-map " + std::to_string(kx + 2 * ky));
    // Sub-map (kx, ky): the quarter of the light uv square as its own [0, 1], res / 2.
    // clip' = 2 clip + (1 - 2k) w: a perspective map's sub-map keeps its w.
    glm::mat4 s(1.0f);
    s[0][0] = s[1][1] = 2.0f;
    s[3][0] = 1.0f - 2.0f * float(kx);
    s[3][1] = 1.0f - 2.0f * float(ky);
    const DepthMapFrame sub{s * whole.viewProj, 0.5f * whole.extentM, whole.depthPerM};
    const MapReceiver r =
        receiverInMap(sub, P, N, towardsLight, glm::vec2(1.0f / (kRes / 2)), bias);
    EXPECT_NEAR(r.uv.x, 2.0f * w.uv.x - float(kx), 1e-5f);
    EXPECT_NEAR(r.uv.y, 2.0f * w.uv.y - float(ky), 1e-5f);
    EXPECT_NEAR(r.z, w.z, 1e-6f);
    EXPECT_NEAR(r.bias, w.bias, 1e-7f);
    EXPECT_GT(r.bias, 0.0f);
    // The plane at the centre of the texel each one samples (the same world texel).
    const glm::ivec2 tw(glm::floor(w.uv * float(kRes)));
    const glm::vec2 centreWhole = (glm::vec2(tw) + 0.5f) / float(kRes);
    const glm::ivec2 ts = tw - glm::ivec2(kx, ky) * (kRes / 2);
    const glm::vec2 centreSub = (glm::vec2(ts) + 0.5f) / float(kRes / 2);
    EXPECT_NEAR(receiverDepthAt(r.uv, r.z, r.gradient, centreSub),
                receiverDepthAt(w.uv, w.z, w.gradient, centreWhole), 1e-6f);
  }
}

TEST(ShadowBias, SubMapWithItsOwnMatrixSeesTheReceiverAsTheWholeMapDoes) {
  constexpr float kHalfM = 10.0f, kNearM = 1.0f, kFarM = 41.0f;
  const glm::vec3 towardsLight = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
  const glm::mat4 view = glm::lookAt(20.0f * towardsLight, glm::vec3(0.0f), {0.0f, 0.0f, -1.0f});
  const glm::mat4 proj = glm::ortho(-kHalfM, kHalfM, -kHalfM, kHalfM, kNearM, kFarM);
  const DepthMapFrame whole{proj * view, glm::vec2(2.0f * kHalfM), 1.0f / (kFarM - kNearM)};
  expectSubMapsMatchWholeMap(whole, towardsLight, false, glm::vec3(0.0f));
}

TEST(ShadowBias, PerspectiveSubMapSeesTheReceiverAsTheWholePerspectiveMapDoes) {
  // A spot 20 m above the origin looking down with a 90 degree frustum: its sub-maps are
  // perspective as well (each has its own w-divide, texel size x w, depth per metre / w^2).
  constexpr float kNearM = 1.0f, kFarM = 41.0f, kFovDeg = 90.0f;
  const glm::vec3 lightPos(3.0f, 20.0f, 2.0f);
  const glm::mat4 view = glm::lookAt(lightPos, glm::vec3(0.0f), {0.0f, 0.0f, -1.0f});
  const glm::mat4 proj = glm::perspective(glm::radians(kFovDeg), 1.0f, kNearM, kFarM);
  const float extent = 2.0f * std::tan(glm::radians(0.5f * kFovDeg));
  const DepthMapFrame whole{proj * view, glm::vec2(extent),
                            depthPerMAtUnitW(true, 0.0f, kNearM, kFarM)};
  ASSERT_GT(mapUvzw(whole, glm::vec3(0.0f)).w, 15.0f);  // really perspective
  expectSubMapsMatchWholeMap(whole, glm::vec3(0.0f), true, lightPos);
}

TEST(ShadowBias, OrthographicMapIsTheAffineFormulaBitForBit) {
  // The perspective-capable model must leave directional maps exactly as before: w = 1,
  // uvz = M P * 0.5 + 0.5, texel and depth per metre unscaled, gradient from the 3x3 part.
  const glm::vec3 towardsLight = glm::normalize(glm::vec3(-0.4f, 1.0f, 0.3f));
  const glm::mat4 vp = glm::ortho(-7.0f, 9.0f, -6.0f, 8.0f, 0.5f, 30.0f) *
                       glm::lookAt(15.0f * towardsLight, glm::vec3(1.0f), {0.0f, 1.0f, 0.0f});
  const DepthMapFrame map{vp, glm::vec2(16.0f, 14.0f), 1.0f / 29.5f};
  const ShadowBiasSettings bias{0.7f, 0.3f, 0.002f};
  const glm::vec3 N = glm::normalize(glm::vec3(0.1f, 1.0f, 0.5f)), P(0.3f, 0.2f, -1.7f);
  const glm::vec2 t(1.0f / 2048.0f);
  const MapReceiver r = receiverInMap(map, P, N, towardsLight, t, bias);
  const float texelM = std::max(t.x * 16.0f, t.y * 14.0f);
  const float cosL = glm::dot(N, towardsLight), sinL = std::sqrt(1.0f - cosL * cosL);
  const glm::vec3 uvz =
      glm::vec3(vp * glm::vec4(P + N * (bias.normalTexels * texelM * sinL), 1.0f)) * 0.5f + 0.5f;
  const glm::vec2 g = receiverDepthGradient(lightNormalMatrix(vp), N);
  EXPECT_EQ(r.uv, glm::vec2(uvz));
  EXPECT_EQ(r.z, uvz.z);
  EXPECT_EQ(r.gradient, g);
  EXPECT_EQ(r.bias, shadowDepthBias(bias, g, t, texelM, map.depthPerM));
}

// --- Distance maps (the cube's faces store the distance from the light along each texel
// centre's ray; GLSL: SL_DEPTH_MAP_STORES_DISTANCE in depth_map_test.glsl).

TEST(ShadowBiasDistance, PlaneDistanceAlongRayMeetsThePlane) {
  const glm::vec3 light(0.3f, 1.0f, -0.2f);
  const glm::vec3 N = glm::normalize(glm::vec3(0.2f, 1.0f, -0.1f)), P(0.5f, 0.1f, 0.4f);
  for (glm::vec3 target :
       {glm::vec3(2.0f, 0.0f, 1.0f), glm::vec3(-1.5f, 0.2f, -3.0f), glm::vec3(0.3f, 0.0f, -0.2f)}) {
    const glm::vec3 dir = glm::normalize(target - light);
    const float t = planeDistanceAlongRay(light, dir, P, N);
    ASSERT_GT(t, 0.0f);
    EXPECT_NEAR(glm::dot(N, light + t * dir - P), 0.0f, 1e-6f) << "on the plane";
    EXPECT_EQ(receiverDistanceAt(light, dir, P, N), t);
  }
  // Straight down onto the floor y = 0 from 1 m: 1 m; at 45 degrees: sqrt 2.
  const glm::vec3 up(0, 1, 0), above(0, 1, 0);
  EXPECT_FLOAT_EQ(planeDistanceAlongRay(above, {0, -1, 0}, glm::vec3(5, 0, 5), up), 1.0f);
  EXPECT_FLOAT_EQ(planeDistanceAlongRay(above, glm::normalize(glm::vec3(1, -1, 0)), {}, up),
                  std::sqrt(2.0f));
  // A ray inside the plane's direction or away from it never meets it: -1, and the receiver
  // falls back to its own distance.
  EXPECT_EQ(planeDistanceAlongRay(above, {1, 0, 0}, {}, up), -1.0f);
  EXPECT_EQ(planeDistanceAlongRay(above, {0, 1, 0}, {}, up), -1.0f);
  EXPECT_FLOAT_EQ(receiverDistanceAt(above, {0, 1, 0}, glm::vec3(3, 0, 4), up), std::sqrt(26.0f));
}

TEST(ShadowBiasDistance, BiasInMetresMovesTheReceiverByTheWindowBias) {
  // A 90 degree face (the cube's): a receiver at distance d along a slanted ray, moved
  // towards the light by distanceBiasM(b) along that ray, rises by b in window depth (to
  // first order: a centimetre at 2..4.4 m, so within 1 %; float window depth near 1 adds
  // under 0.1 %: tolerance 2 %).
  constexpr float kNearM = 0.1f, kFarM = 10.0f;
  const glm::vec3 light(0.0f);
  const glm::mat4 vp = glm::perspective(glm::radians(90.0f), 1.0f, kNearM, kFarM) *
                       glm::lookAt(light, glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
  const DepthMapFrame face{vp, glm::vec2(2.0f), depthPerMAtUnitW(true, 0.0f, kNearM, kFarM)};
  for (glm::vec3 P : {glm::vec3(0.0f, 0.0f, -2.0f), glm::vec3(1.5f, -0.8f, -2.0f),
                      glm::vec3(-3.0f, 2.9f, -3.1f)}) {
    const glm::vec4 c = mapUvzw(face, P);
    const float d = glm::length(P - light);
    const float perM = windowDepthPerM(face.depthPerM, c.w);
    const float b = 1e-2f * perM;  // a centimetre of axial depth, in window depth
    const float m = distanceBiasM(b, perM, c.w, d);
    EXPECT_NEAR(m, 1e-2f * d / c.w, 1e-8f);  // the ray's secant times a centimetre
    const glm::vec3 moved = P - m * glm::normalize(P - light);
    EXPECT_NEAR(c.z - mapUvzw(face, moved).z, b, 0.02f * b) << P.x;
  }
}

}  // namespace
}  // namespace sl
