// Importance map, importance terms, backward-analysis scatter and collapse (RTW steps 1-2).
// See Importance.h for the exact definitions the GPU passes mirror.
#include "Importance.h"

#include <algorithm>
#include <cmath>

namespace sl::rtw {

namespace {

/// x clamped to [lo, hi]; NaN -> fallback.
float clampOr(float x, float lo, float hi, float fallback) {
  if (std::isnan(x)) return fallback;
  return std::min(std::max(x, lo), hi);
}

}  // namespace

ImportanceMap::ImportanceMap(int w, int h) {
  if (w < 1 || h < 1) return;
  width = w;
  height = h;
  values.assign(static_cast<size_t>(w) * static_cast<size_t>(h), 0.0f);
}

float eyeDepthTerm(float eyeDepthM, float nearM) {
  if (!(nearM > 0.0f) || !(eyeDepthM > nearM)) return 1.0f;
  return nearM / eyeDepthM;
}

float orientationTerm(float nDotL, float nDotV, float minCosL) {
  float minL = clampOr(minCosL, 0.01f, 1.0f, 0.1f);
  float v = nDotV > 0.0f ? std::min(nDotV, 1.0f) : 0.0f;
  float l = std::fabs(nDotL);
  l = l > minL ? l : minL;  // also maps NaN to minL
  return v / l;
}

float shadowEdgeTerm(float edge) {
  return clampOr(edge, 0.0f, 1.0f, 0.0f);
}

float combineImportance(const ImportanceSettings& s, float eyeDepthM, float nDotL, float nDotV,
                        float edge) {
  float e = 1.0f, o = 1.0f, k = 1.0f;
  if (s.eyeOn) {
    float w = clampOr(s.eyeWeight, 0.0f, 1.0f, 0.0f);
    e = 1.0f + w * (eyeDepthTerm(eyeDepthM, s.nearM) - 1.0f);
  }
  if (s.orientationOn) {
    float w = clampOr(s.orientationWeight, 0.0f, 1.0f, 0.0f);
    o = 1.0f + w * (orientationTerm(nDotL, nDotV, s.minCosL) - 1.0f);
  }
  if (s.edgeOn) {
    float w = clampOr(s.edgeWeight, 0.0f, 16.0f, 0.0f);
    k = 1.0f + w * shadowEdgeTerm(edge);
  }
  // e >= 1 - w >= 0 and o >= 0 by construction; max() only guards against a -0 or a
  // rounding below zero, so the value is always a valid atomicMax operand.
  return std::max((e * o) * k, 0.0f);
}

bool texelOfLightUv(int width, int height, glm::vec2 lightUv, glm::ivec2& texel) {
  float fx = std::floor(lightUv.x * static_cast<float>(width));
  float fy = std::floor(lightUv.y * static_cast<float>(height));
  // Written as negated comparisons so that NaN is rejected.
  if (!(fx >= 0.0f && fx < static_cast<float>(width))) return false;
  if (!(fy >= 0.0f && fy < static_cast<float>(height))) return false;
  texel = glm::ivec2(static_cast<int>(fx), static_cast<int>(fy));
  return true;
}

void scatterMax(ImportanceMap& map, glm::vec2 lightUv, float value) {
  if (!(value > 0.0f) || std::isinf(value)) return;
  glm::ivec2 t;
  if (!texelOfLightUv(map.width, map.height, lightUv, t)) return;
  float& dst = map.at(t.x, t.y);
  dst = std::max(dst, value);
}

std::vector<float> collapseColumnsMax(const ImportanceMap& map) {
  std::vector<float> out(static_cast<size_t>(std::max(map.width, 0)), 0.0f);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) out[x] = std::max(out[x], map.at(x, y));
  return out;
}

std::vector<float> collapseRowsMax(const ImportanceMap& map) {
  std::vector<float> out(static_cast<size_t>(std::max(map.height, 0)), 0.0f);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) out[y] = std::max(out[y], map.at(x, y));
  return out;
}

float halfMassWidth(const std::vector<float>& values) {
  auto mass = [](float v) { return (v > 0.0f && std::isfinite(v)) ? double(v) : 0.0; };
  double total = 0.0;
  for (float v : values) total += mass(v);
  if (!(total > 0.0)) return 0.0f;
  const double half = 0.5 * total;
  // Two pointers: for every end, the latest start whose run still holds half the mass.
  size_t best = values.size(), start = 0;
  double run = 0.0;
  for (size_t end = 0; end < values.size(); ++end) {
    run += mass(values[end]);
    while (start < end && run - mass(values[start]) >= half) run -= mass(values[start++]);
    if (run >= half) best = std::min(best, end - start + 1);
  }
  return float(double(best) / double(values.size()));
}

}  // namespace sl::rtw
