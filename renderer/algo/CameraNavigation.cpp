// Camera rates scaled to the view and the scene (see CameraNavigation.h).
#include "algo/CameraNavigation.h"

#include <algorithm>
#include <cmath>

namespace sl {

float navigationScaleM(const Aabb& sceneBounds, const Camera& camera) {
  if (sceneBounds.valid()) {
    const float diagonalM = glm::length(sceneBounds.size());
    if (std::isfinite(diagonalM) && diagonalM > 0.0f) return diagonalM;
  }
  const float distanceM = glm::length(camera.position - camera.target);
  if (std::isfinite(distanceM) && distanceM > 0.0f) return distanceM;
  return 1.0f;
}

float orbitDegPerPixel(int viewHeightPx, const NavigationRates& rates) {
  if (viewHeightPx <= 0) return 0.0f;
  return rates.orbitDegPerViewHeight / static_cast<float>(viewHeightPx);
}

Camera orbitByDrag(const Camera& camera, float dxPx, float dyPx, int viewHeightPx,
                   const NavigationRates& rates) {
  const float degPerPx = orbitDegPerPixel(viewHeightPx, rates);
  if (degPerPx == 0.0f) return camera;
  Camera moved = camera;
  moved.orbit(-dxPx * degPerPx, dyPx * degPerPx);
  return moved;
}

float lookDegPerPixel(const Camera& camera, int viewHeightPx) {
  if (viewHeightPx <= 0) return 0.0f;
  return camera.fovYDeg / static_cast<float>(viewHeightPx);
}

Camera lookByDrag(const Camera& camera, float dxPx, float dyPx, int viewHeightPx) {
  const float degPerPx = lookDegPerPixel(camera, viewHeightPx);
  if (degPerPx == 0.0f) return camera;
  Camera moved = camera;
  moved.look(-dxPx * degPerPx, -dyPx * degPerPx);
  return moved;
}

float panMetresPerPixel(const Camera& camera, int viewHeightPx) {
  if (viewHeightPx <= 0) return 0.0f;
  const float distanceM = glm::length(camera.position - camera.target);
  if (!std::isfinite(distanceM)) return 0.0f;
  return 2.0f * distanceM * std::tan(glm::radians(camera.fovYDeg) * 0.5f) /
         static_cast<float>(viewHeightPx);
}

Camera panByDrag(const Camera& camera, float dxPx, float dyPx, int viewHeightPx) {
  const float mPerPx = panMetresPerPixel(camera, viewHeightPx);
  if (mPerPx == 0.0f) return camera;
  Camera moved = camera;
  moved.pan(-dxPx * mPerPx, dyPx * mPerPx);
  return moved;
}

float dollyFactor(float notches, const NavigationRates& rates) {
  return std::pow(1.0f - rates.dollyShareOfDistance, notches);
}

float dolliedDistanceM(float distanceM, float notches, float sceneScaleM,
                       const NavigationRates& rates) {
  if (!std::isfinite(distanceM) || distanceM <= 0.0f || !std::isfinite(notches) || notches == 0.0f)
    return distanceM;
  const float scaled = distanceM * dollyFactor(notches, rates);
  if (notches > 0.0f) {  // in: not closer than the nearest allowed, not pushed back out to it
    const float nearestM = rates.minDistanceSceneSizes * sceneScaleM;
    return distanceM <= nearestM ? distanceM : std::max(scaled, nearestM);
  }
  const float farthestM = rates.maxDistanceSceneSizes * sceneScaleM;
  return distanceM >= farthestM ? distanceM : std::min(scaled, farthestM);
}

Camera dollyByWheel(const Camera& camera, float notches, const Aabb& sceneBounds,
                    const NavigationRates& rates) {
  const glm::vec3 offset = camera.position - camera.target;
  const float distanceM = glm::length(offset);
  if (!std::isfinite(distanceM) || distanceM <= 0.0f) return camera;
  const float newDistanceM =
      dolliedDistanceM(distanceM, notches, navigationScaleM(sceneBounds, camera), rates);
  if (newDistanceM == distanceM) return camera;
  Camera moved = camera;
  moved.position = camera.target + offset * (newDistanceM / distanceM);
  return moved;
}

float flySpeedMPerS(float sceneScaleM, bool fast, const NavigationRates& rates) {
  return rates.flySceneSizesPerS * sceneScaleM * (fast ? rates.fastFlySpeedFactor : 1.0f);
}

float flyStepM(float sceneScaleM, float dtS, bool fast, const NavigationRates& rates) {
  if (!std::isfinite(dtS)) return 0.0f;
  return flySpeedMPerS(sceneScaleM, fast, rates) * std::clamp(dtS, 0.0f, rates.maxFlyTickS);
}

}  // namespace sl
