// The shared bias model as plain math (ShadowBias.h).
#include "ShadowBias.h"

#include <algorithm>
#include <cmath>

namespace sl {

glm::mat3 lightNormalMatrix(const glm::mat4& lightViewProj) {
  return glm::transpose(glm::inverse(glm::mat3(lightViewProj)));
}

LightPlaneMatrix lightPlaneMatrix(const glm::mat4& m) {
  LightPlaneMatrix p;
  const bool affine = m[0][3] == 0.0f && m[1][3] == 0.0f && m[2][3] == 0.0f && m[3][3] == 1.0f;
  if (affine) {  // bit for bit what the orthographic model always used
    p.normal = lightNormalMatrix(m);
    return p;
  }
  const glm::mat4 it = glm::transpose(glm::inverse(m));
  p.normal = glm::mat3(it);
  p.offset = glm::vec3(it[3]);
  return p;
}

glm::vec2 receiverDepthGradient(const LightPlaneMatrix& plane, const glm::vec3& N,
                                const glm::vec3& P) {
  glm::vec3 m = plane.normal * N - plane.offset * glm::dot(N, P);
  if (!(std::abs(m.z) > 1e-4f * glm::length(m))) return glm::vec2(0.0f);
  return -glm::vec2(m) / m.z;
}

glm::vec2 receiverDepthGradient(const glm::mat3& normalMatrix, const glm::vec3& N) {
  return receiverDepthGradient(LightPlaneMatrix{normalMatrix, glm::vec3(0.0f)}, N, glm::vec3(0.0f));
}

float windowDepthPerM(float depthPerMAtUnitW, float clipW, float power) {
  return depthPerMAtUnitW / std::pow(clipW, power);
}

float depthPerMAtUnitW(bool perspective, float depthRangeM, float nearM, float farM) {
  if (perspective) return farM * nearM / (farM - nearM);
  return 1.0f / (depthRangeM > 0.0f ? depthRangeM : 1.0f);
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

glm::vec4 mapUvzw(const DepthMapFrame& map, glm::vec3 P) {
  const glm::vec4 c = map.viewProj * glm::vec4(P, 1.0f);
  const float w = c.w > 1e-6f ? c.w : 1e-6f;
  return glm::vec4(glm::vec3(c) / w * 0.5f + 0.5f, w);
}

MapReceiver receiverInMap(const DepthMapFrame& map, glm::vec3 P, glm::vec3 N,
                          glm::vec3 towardsLight, glm::vec2 localTexelUv,
                          const ShadowBiasSettings& s) {
  const float w = mapUvzw(map, P).w;
  const float texelM = std::max(localTexelUv.x * map.extentM.x * std::pow(w, map.extentWPower.x),
                                localTexelUv.y * map.extentM.y * std::pow(w, map.extentWPower.y));
  const float cosL = std::clamp(glm::dot(N, towardsLight), -1.0f, 1.0f);
  const float sinL = std::sqrt(std::max(1.0f - cosL * cosL, 0.0f));
  const glm::vec3 offset = P + N * (s.normalTexels * texelM * sinL);
  const glm::vec3 uvz = glm::vec3(mapUvzw(map, offset));
  MapReceiver r;
  r.uv = glm::vec2(uvz);
  r.z = uvz.z;
  r.gradient = receiverDepthGradient(lightPlaneMatrix(map.viewProj), N, P);
  r.bias = shadowDepthBias(s, r.gradient, localTexelUv, texelM,
                           windowDepthPerM(map.depthPerM, w, map.depthWPower));
  return r;
}

float planeDistanceAlongRay(glm::vec3 lightPosM, glm::vec3 dir, glm::vec3 P, glm::vec3 N) {
  const float nd = glm::dot(N, dir);
  if (std::abs(nd) < 1e-6f * glm::length(N)) return -1.0f;
  const float t = glm::dot(N, P - lightPosM) / nd;
  return t > 0.0f ? t : -1.0f;
}

float receiverDistanceAt(glm::vec3 lightPosM, glm::vec3 dir, glm::vec3 P, glm::vec3 N) {
  const float t = planeDistanceAlongRay(lightPosM, dir, P, N);
  return t > 0.0f ? t : glm::length(P - lightPosM);
}

float distanceBiasM(float windowBias, float depthPerM, float clipW, float distanceM) {
  return windowBias / depthPerM * distanceM / clipW;
}

}  // namespace sl
