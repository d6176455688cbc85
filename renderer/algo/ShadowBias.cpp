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

}  // namespace sl
