// How far the 3D view's mouse and keys move the camera, scaled to the view and to the scene:
// a drag across the view's height orbits a fixed angle whatever the window's size, a wheel
// notch moves a fixed share of the distance to the target (never through it, never beyond a
// few scene sizes), a pan keeps the point under the cursor under it, and flying covers a fixed
// share of the scene per second. Plain math on Camera; the GUI's handlers call it.
#pragma once

#include "algo/Camera.h"

namespace sl {

/// The rates, in units of the view's height and the scene's size.
struct NavigationRates {
  float orbitDegPerViewHeight = 180.0f;  ///< a drag across the view's height orbits this far
  float dollyShareOfDistance = 0.15f;    ///< a notch towards the target moves this share of it
  float minDistanceSceneSizes = 1e-3f;   ///< dollying in stops this close to the target
  float maxDistanceSceneSizes = 4.0f;    ///< dollying out stops this far from the target
  float flySceneSizesPerS = 0.35f;       ///< flying speed
  float fastFlySpeedFactor = 4.0f;       ///< with Shift held
  float maxFlyTickS = 0.1f;              ///< a longer tick (a stalled frame) flies this long only
};

/// The length the rates scale with: the diagonal of the scene's bounds; for a scene without
/// extent (empty or invalid bounds, a single point) the camera's distance to its target, and
/// 1 m when that is zero or not finite too.
float navigationScaleM(const Aabb& sceneBounds, const Camera& camera);

/// Degrees of orbit per pixel of drag: orbitDegPerViewHeight / viewHeightPx; 0 for a view
/// without height (nothing turns).
float orbitDegPerPixel(int viewHeightPx, const NavigationRates& rates = {});
/// `camera` orbited around its target by a drag of (dxPx, dyPx) (right: the camera goes left
/// around the target; down: it goes up). Unchanged for a view without height.
Camera orbitByDrag(const Camera& camera, float dxPx, float dyPx, int viewHeightPx,
                   const NavigationRates& rates = {});

/// Degrees of look (turning in place) per pixel: a drag across the view's height turns the
/// view by its vertical field of view; 0 for a view without height.
float lookDegPerPixel(const Camera& camera, int viewHeightPx);
/// `camera` turned in place by a drag of (dxPx, dyPx) (right: it turns right; down: down).
Camera lookByDrag(const Camera& camera, float dxPx, float dyPx, int viewHeightPx);

/// Metres per pixel of pan at the target's depth, 2 d tan(fovY / 2) / viewHeightPx with d the
/// distance to the target: the point under the cursor there follows the cursor. 0 for a view
/// without height or a camera at its target.
float panMetresPerPixel(const Camera& camera, int viewHeightPx);
/// `camera` (position and target) panned by a drag of (dxPx, dyPx), screen y down.
Camera panByDrag(const Camera& camera, float dxPx, float dyPx, int viewHeightPx);

/// The factor a distance is scaled by for `notches` wheel notches (positive: towards the
/// target), (1 - dollyShareOfDistance)^notches: a notch in and a notch out cancel.
float dollyFactor(float notches, const NavigationRates& rates = {});
/// The distance to the target after `notches` notches from `distanceM`: distanceM times
/// dollyFactor, in at most to minDistanceSceneSizes and out at most to maxDistanceSceneSizes
/// times `sceneScaleM`. A camera already beyond a limit is never moved further past it (nor
/// pulled back to it). A distance that is zero or not finite, or notches that are not
/// finite, leave the distance as it is.
float dolliedDistanceM(float distanceM, float notches, float sceneScaleM,
                       const NavigationRates& rates = {});
/// `camera` moved along its view direction by `notches` wheel notches (dolliedDistanceM with
/// navigationScaleM). A camera at its target (no direction) stays.
Camera dollyByWheel(const Camera& camera, float notches, const Aabb& sceneBounds,
                    const NavigationRates& rates = {});

/// Flying speed in metres per second: flySceneSizesPerS scene sizes, times
/// fastFlySpeedFactor when `fast`.
float flySpeedMPerS(float sceneScaleM, bool fast, const NavigationRates& rates = {});
/// Metres flown in a tick of `dtS` seconds (clamped to [0, maxFlyTickS]; not finite: 0).
float flyStepM(float sceneScaleM, float dtS, bool fast, const NavigationRates& rates = {});

}  // namespace sl
