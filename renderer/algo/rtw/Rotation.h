// Directionality-aware RTW (seed 000): the per-frame rotation of the light's image plane,
// R_k = R' R_{k-1}, from the principal axis of the previous frame's (already rotated) IM,
// with the poster's vibration threshold. Pure state update, no GL.
//
// Which way it turns (the one thing to get right):
//  - R (RotationState::R) maps coordinates in the ROTATED light image plane (the IM / SM
//    axes of frame k, q) to the UNROTATED base light image plane (p, the axes of
//    sl::lightBaseView):  p = R q.  Its columns are the SM's x and y axes in base coords:
//    R = [[c, -s], [s, c]] (rows), c = cos φ, s = sin φ, φ = angle of the SM x axis.
//    This is the poster's matrix that "rotates the light view frustum".
//  - The light VIEW matrix needs the inverse, q = R^T p: pass lightViewRotation(state)
//    (= transpose(R)) as sl::FocusSettings::rotation, whose view is
//    imagePlaneRotation(rotation) * lightBaseView(L).
//  - The IM of frame k-1 lives in q_{k-1} coordinates; its principal axis there is
//    e = (e_x, e_y). R' = [[e_x, -e_y], [e_y, e_x]] (rows) = rotation by θ = atan2(e_y,
//    e_x); R_k = R' R_{k-1} (2D rotations commute, so R_{k-1} R' is the same). Then
//    q_k = R'^T q_{k-1} and R'^T e = (1, 0): the principal axis lies on the SM's x axis in
//    frame k. In glm (column-major): R' = glm::mat2(e_x, e_y, -e_y, e_x).
//  - e_x > 0 (momentsFromTop's sign rule), so one step turns by at most ±90°; an axis
//    exactly along y (e = (0, 1)) turns by +90°.
#pragma once

#include <glm/mat2x2.hpp>

#include "Moments.h"

namespace sl::rtw {

/// The vibration threshold on e_x: the parameter's key (also the number published under it),
/// default and range (seed 000 uses 0.9999). DA-RTW's declaration, its panel and
/// updateRotation read them here.
inline constexpr const char* kHoldThresholdKey = "pca.threshold";
inline constexpr double kDefaultHoldThreshold = 0.9999;
inline constexpr double kMinHoldThreshold = 0.9;
inline constexpr double kMaxHoldThreshold = 1.0;

struct RotationState {
  glm::mat2 R{1.0f};            ///< R_k: rotated (SM) plane -> base light plane, p = R q
  double accumulatedDeg = 0.0;  ///< Σ |stepDeg| over the applied steps (total turning)
  int changes = 0;              ///< updates that changed R
  int frames = 0;               ///< updateRotation calls since reset()

  /// R = identity (R_0), counters to 0.
  void reset() { *this = RotationState{}; }
  /// Angle φ of R in degrees, atan2(R[0][1], R[0][0]), in (-180, 180].
  double angleDeg() const;
};

/// What one update did.
struct RotationUpdate {
  bool valid = false;            ///< the stats had a principal axis (MomentStats::valid)
  bool held = false;             ///< valid but e_x > threshold: R_k = R_{k-1} (vibration hold)
  bool tooRound = false;         ///< valid but anisotropy < minAnisotropy: R_k = R_{k-1} (not held)
  bool tooConcentrated = false;  ///< valid, thin enough, but spread < minSpread: R_k = R_{k-1}
  bool rotated = false;          ///< R changed: valid, not held, and e_y != 0
  float e_x = 1.0f, e_y = 0.0f;  ///< the principal axis used ((1, 0) when not valid)
  float stepDeg = 0.0f;          ///< atan2(e_y, e_x) in degrees if rotated, else 0
};

/// One frame of seed 000's pass (a)-(b). threshold is clamped to [0.9, 1] (NaN ->
/// default). Not valid (all-zero IM, isotropic Σ): R unchanged, never NaN. Held when
/// e_x > threshold (threshold 1 never holds). Otherwise R = R' R computed in float and
/// re-orthonormalised: (c, s) = first column / hypot, R = mat2(c, s, -s, c).
/// minAnisotropy (clamped to [0, 1], NaN -> 0): with (λ1 − λ2) / (λ1 + λ2) below it, R is
/// left as it is (tooRound; not a vibration hold): an importance that is not elongated has
/// no direction worth turning the map for. 0 = the poster (every valid axis counts).
/// minSpread (clamped to [0, 1], NaN -> 0): with `spread` (the wider of the half-mass widths
/// of the collapsed 1D importance, as a share of the map: rtw::halfMassWidth) below it, R is
/// left as it is (tooConcentrated): half of the importance sits in a small part of the map,
/// which the separable warp already gives its texels whatever the angle. Checked after the
/// anisotropy gate, before the hold.
RotationUpdate updateRotation(RotationState& state, const MomentStats& stats,
                              float threshold = float(kDefaultHoldThreshold),
                              float minAnisotropy = 0.0f, float spread = 1.0f,
                              float minSpread = 0.0f);

/// transpose(state.R): the rotation to pass as sl::FocusSettings::rotation (light view).
glm::mat2 lightViewRotation(const RotationState& state);

/// R' = [[e_x, -e_y], [e_y, e_x]] (rows) as a glm (column-major) matrix.
glm::mat2 relativeRotation(float e_x, float e_y);

}  // namespace sl::rtw
