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

namespace {

/// d(clip xyz / w) / dP along world direction d (the quotient rule on the map's matrix).
glm::vec3 ndcDerivative(const glm::mat4& M, const glm::vec4& h, glm::vec3 d) {
  const glm::vec4 dh = M * glm::vec4(d, 0.0f);
  return (glm::vec3(dh) * h.w - glm::vec3(h) * dh.w) / (h.w * h.w);
}

/// Two unit vectors perpendicular to unit `l` and to each other.
void perpendicularPair(glm::vec3 l, glm::vec3& e1, glm::vec3& e2) {
  const glm::vec3 a = std::abs(l.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
  e1 = glm::normalize(a - glm::dot(a, l) * l);
  e2 = glm::cross(l, e1);
}

}  // namespace

glm::vec2 projectiveMetresPerUv(const glm::mat4& M, glm::vec3 P, glm::vec3 towardsLight) {
  const glm::vec4 h = M * glm::vec4(P, 1.0f);
  glm::vec3 e1, e2;
  perpendicularPair(glm::normalize(towardsLight), e1, e2);
  // uv = 0.5 ndc + 0.5: J's columns are d(uv)/d(e1), d(uv)/d(e2).
  const glm::vec2 a = 0.5f * glm::vec2(ndcDerivative(M, h, e1));
  const glm::vec2 b = 0.5f * glm::vec2(ndcDerivative(M, h, e2));
  const float det = a.x * b.y - b.x * a.y;
  if (!(std::abs(det) > 0.0f)) return glm::vec2(0.0f);
  // J^-1 = [b.y, -b.x; -a.y, a.x] / det: its columns are metres (in e1, e2) per unit u, v.
  return glm::vec2(glm::length(glm::vec2(b.y, -a.y)), glm::length(glm::vec2(-b.x, a.x))) /
         std::abs(det);
}

float projectiveDepthPerM(const glm::mat4& M, glm::vec3 P, glm::vec3 towardsLight) {
  const glm::vec4 h = M * glm::vec4(P, 1.0f);
  return std::abs(0.5f * ndcDerivative(M, h, glm::normalize(towardsLight)).z);
}

MapReceiver receiverInMap(const DepthMapFrame& map, glm::vec3 P, glm::vec3 N,
                          glm::vec3 towardsLight, glm::vec2 localTexelUv,
                          const ShadowBiasSettings& s) {
  const float w = mapUvzw(map, P).w;
  float texelM = 0.0f;
  if (map.projective) {
    const glm::vec2 perUv = projectiveMetresPerUv(map.viewProj, P, towardsLight);
    texelM = std::max(localTexelUv.x * perUv.x, localTexelUv.y * perUv.y);
  } else {
    texelM = std::max(localTexelUv.x * map.extentM.x * std::pow(w, map.extentWPower.x),
                      localTexelUv.y * map.extentM.y * std::pow(w, map.extentWPower.y));
  }
  const float cosL = std::clamp(glm::dot(N, towardsLight), -1.0f, 1.0f);
  const float sinL = std::sqrt(std::max(1.0f - cosL * cosL, 0.0f));
  const glm::vec3 offset = P + N * (s.normalTexels * texelM * sinL);
  const glm::vec3 uvz = glm::vec3(mapUvzw(map, offset));
  MapReceiver r;
  r.uv = glm::vec2(uvz);
  r.z = uvz.z;
  r.gradient = receiverDepthGradient(lightPlaneMatrix(map.viewProj), N, P);
  r.bias = shadowDepthBias(s, r.gradient, localTexelUv, texelM,
                           map.projective ? projectiveDepthPerM(map.viewProj, P, towardsLight)
                                          : windowDepthPerM(map.depthPerM, w, map.depthWPower));
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
