// DA-RTW image-plane rotation update (seed 000). See Rotation.h for the conventions.
#include "Rotation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/matrix.hpp>

namespace sl::rtw {

double RotationState::angleDeg() const {
  return std::atan2(static_cast<double>(R[0][1]), static_cast<double>(R[0][0])) * 180.0 /
         std::numbers::pi;
}

glm::mat2 relativeRotation(float e_x, float e_y) {
  return glm::mat2(e_x, e_y,    // column 0
                   -e_y, e_x);  // column 1
}

glm::mat2 lightViewRotation(const RotationState& state) {
  return glm::transpose(state.R);
}

RotationUpdate updateRotation(RotationState& state, const MomentStats& stats, float threshold,
                              float minAnisotropy, float spread, float minSpread) {
  float t = std::isnan(threshold)
                ? float(kDefaultHoldThreshold)
                : std::clamp(threshold, float(kMinHoldThreshold), float(kMaxHoldThreshold));
  ++state.frames;
  RotationUpdate u;
  if (!stats.valid || !std::isfinite(stats.ex) || !std::isfinite(stats.ey)) return u;
  u.valid = true;
  u.e_x = stats.ex;
  u.e_y = stats.ey;
  const float minA = std::isnan(minAnisotropy) ? 0.0f : std::clamp(minAnisotropy, 0.0f, 1.0f);
  if (stats.anisotropy < minA) {
    u.tooRound = true;
    return u;
  }
  const float minS = std::isnan(minSpread) ? 0.0f : std::clamp(minSpread, 0.0f, 1.0f);
  if (minS > 0.0f && !(spread >= minS)) {  // a NaN spread (not measured) does not turn
    u.tooConcentrated = true;
    return u;
  }
  if (stats.ex > t) {
    u.held = true;
    return u;
  }
  if (stats.ey == 0.0f) return u;  // e = (1, 0) exactly with threshold 1: nothing to do

  glm::mat2 r = relativeRotation(stats.ex, stats.ey) * state.R;
  float c = r[0][0], s = r[0][1];
  float len = std::hypot(c, s);
  if (!(len > 0.0f) || !std::isfinite(len)) return u;  // cannot happen for unit e; be safe
  c /= len;
  s /= len;
  state.R = glm::mat2(c, s, -s, c);

  u.rotated = true;
  u.stepDeg =
      static_cast<float>(std::atan2(static_cast<double>(stats.ey), static_cast<double>(stats.ex)) *
                         180.0 / std::numbers::pi);
  state.accumulatedDeg += std::fabs(static_cast<double>(u.stepDeg));
  ++state.changes;
  return u;
}

}  // namespace sl::rtw
