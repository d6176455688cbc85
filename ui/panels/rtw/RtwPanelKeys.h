// The publication keys each RTW / DA-RTW panel observes (core/Renderer.h, Publication),
// plain C++ so that tests/gl can request exactly what a panel draws. Each panel's
// observedKeys() returns its list; the main window requests them while the panel shows.
#pragma once

#include <set>
#include <string>

#include "algo/rtw/Rotation.h"

namespace sl::ui::rtw {

/// Importance map panel: the raw IM and the collapsed / blurred 1D maps.
inline std::set<std::string> importancePanelKeys() {
  return {"importance", "importance.x", "importance.y", "importance.x.blurred",
          "importance.y.blurred"};
}

/// Covariance panel: the IM it draws the ellipses over, the moment sums, the light
/// frustum and the renderer's PCA and rotation numbers.
inline std::set<std::string> covariancePanelKeys() {
  return {"importance",
          "moment.I",
          "moment.xI",
          "moment.yI",
          "moment.xxI",
          "moment.yyI",
          "moment.xyI",
          "light.extent.x",
          "light.extent.y",
          sl::rtw::kHoldThresholdKey,
          "pca.valid",
          "e_x",
          "e_y",
          "rotation.held",
          "rotation.step_deg",
          "rotation.deg",
          "rotation.changes",
          "light.area",
          "pca.scale.x",
          "pca.scale.y",
          "pca.anisotropy",
          "eigen.1",
          "eigen.2",
          "pca.spread",
          "pca.min_anisotropy",
          "pca.min_spread",
          "rotation.too_round",
          "rotation.too_concentrated",
          "rotation.mode",
          "pca.axis_deg",
          "prediction.valid",
          "prediction.reason",
          "prediction.current_deg",
          "prediction.best_deg",
          "prediction.gain",
          "prediction.margin",
          "prediction.score.current",
          "prediction.score.best",
          "prediction.weight",
          "prediction.curve"};
}

/// Warp functions panel: the 1D maps before and after the blur, the warp maps.
inline std::set<std::string> warpPanelKeys() {
  return {"warp.x",
          "warp.y",
          "importance.x",
          "importance.y",
          "importance.x.blurred",
          "importance.y.blurred"};
}

/// Shadow map panel: the map, the unwarped contrast map and the warp (for its grid).
inline std::set<std::string> shadowMapPanelKeys() {
  return {"shadow map", "shadow map.uniform", "warp.x", "warp.y"};
}

/// Moment mip chain panel: every level image and the sums ("moment.*"), the light
/// frustum and the renderer's mean and covariance.
inline std::set<std::string> momentPanelKeys() {
  return {"moment.*", "light.extent.x", "light.extent.y", "mean.x",      "mean.y",
          "cov.xx",   "cov.xy",         "cov.yy",         "pca.scale.x", "pca.scale.y"};
}

}  // namespace sl::ui::rtw
