// The shared bias model's CPU mirror (algo/ShadowBias.h) per selected map: a map split into
// 2x2 sub-maps, each with its own matrix, must see a receiver exactly as the whole map
// does — same plane depth at the same texel centre, same bias — because the model works in
// the selected map's light uv with that map's local texel size.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "algo/ShadowBias.h"

namespace sl {
namespace {

TEST(ShadowBias, SubMapWithItsOwnMatrixSeesTheReceiverAsTheWholeMapDoes) {
  constexpr float kHalfM = 10.0f, kNearM = 1.0f, kFarM = 41.0f;
  constexpr int kRes = 1024;
  const glm::vec3 towardsLight = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
  const glm::mat4 view = glm::lookAt(20.0f * towardsLight, glm::vec3(0.0f), {0.0f, 0.0f, -1.0f});
  const glm::mat4 proj = glm::ortho(-kHalfM, kHalfM, -kHalfM, kHalfM, kNearM, kFarM);
  const DepthMapFrame whole{proj * view, glm::vec2(2.0f * kHalfM), 1.0f / (kFarM - kNearM)};
  const ShadowBiasSettings bias{0.5f, 0.25f, 0.001f};

  // A tilted receiver at a few points spread over all four quarters.
  const glm::vec3 N = glm::normalize(glm::vec3(0.2f, 1.0f, -0.4f));
  for (glm::vec3 P : {glm::vec3(-4.0f, 0.3f, -3.0f), glm::vec3(5.0f, -0.2f, -2.0f),
                      glm::vec3(-3.0f, 0.1f, 6.0f), glm::vec3(2.5f, 0.4f, 4.5f)}) {
    const MapReceiver w = receiverInMap(whole, P, N, towardsLight, glm::vec2(1.0f / kRes), bias);
    const int kx = w.uv.x >= 0.5f, ky = w.uv.y >= 0.5f;
    SCOPED_TRACE("sub-map " + std::to_string(kx + 2 * ky));
    // Sub-map (kx, ky): the quarter of the light uv square as its own [0, 1], res / 2.
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

}  // namespace
}  // namespace sl
