// The shared bias model as plain math (ShadowBias.h).
#include "ShadowBias.h"

#include <algorithm>
#include <cmath>

namespace sl {

glm::mat3 lightNormalMatrix(const glm::mat4& lightViewProj) {
  return glm::transpose(glm::inverse(glm::mat3(lightViewProj)));
}

glm::vec2 receiverDepthGradient(const glm::mat3& normalMatrix, const glm::vec3& N) {
  glm::vec3 m = normalMatrix * N;
  if (!(std::abs(m.z) > 1e-4f * glm::length(m))) return glm::vec2(0.0f);
  return -glm::vec2(m) / m.z;
}

float receiverDepthAt(glm::vec2 uv, float z, glm::vec2 gradient, glm::vec2 centre) {
  return z + glm::dot(gradient, centre - uv);
}

float shadowDepthBias(const ShadowBiasSettings& s, glm::vec2 gradient, glm::vec2 localTexelUv,
                      float texelM, float depthPerM) {
  float rise = std::abs(gradient.x) * localTexelUv.x + std::abs(gradient.y) * localTexelUv.y;
  rise = std::min(rise, 10.0f * texelM * depthPerM);
  return s.slopeTexels * rise + s.constantM * depthPerM;
}

MapReceiver receiverInMap(const DepthMapFrame& map, glm::vec3 P, glm::vec3 N,
                          glm::vec3 towardsLight, glm::vec2 localTexelUv,
                          const ShadowBiasSettings& s) {
  const float texelM = std::max(localTexelUv.x * map.extentM.x, localTexelUv.y * map.extentM.y);
  const float cosL = std::clamp(glm::dot(N, towardsLight), -1.0f, 1.0f);
  const float sinL = std::sqrt(std::max(1.0f - cosL * cosL, 0.0f));
  const glm::vec3 offset = P + N * (s.normalTexels * texelM * sinL);
  const glm::vec3 uvz = glm::vec3(map.viewProj * glm::vec4(offset, 1.0f)) * 0.5f + 0.5f;
  MapReceiver r;
  r.uv = glm::vec2(uvz);
  r.z = uvz.z;
  r.gradient = receiverDepthGradient(lightNormalMatrix(map.viewProj), N);
  r.bias = shadowDepthBias(s, r.gradient, localTexelUv, texelM, map.depthPerM);
  return r;
}

}  // namespace sl
