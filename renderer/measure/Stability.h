// Stability of a configuration over frames, the measuring half of `shadowlab-cli stability`
// and its suites: the per-frame record (a FrameSample and the rotation's step), the summary
// over the counted frames and the metric names a suite's expectations use; the orbit a
// stability run moves its camera along. No GL of its own, no Qt.
#pragma once

#include <limits>
#include <map>
#include <string>
#include <vector>

#include "measure/Measure.h"

namespace sl::measure {

/// Signed smallest difference of two angles in degrees, in [-180, 180).
double angleStepDeg(double from, double to);
/// A camera orbiting the point it looks at on the ground (y = scene floor), so a slow
/// orbit keeps the same part of the scene in view; a camera looking up orbits its target.
Camera orbitCentred(Camera cam, const Scene& scene);

/// Per-frame record of one configuration in a stability run.
struct StabilityFrame {
  FrameSample sample;
  double rotationStepDeg = 0.0;  ///< change of rotation_deg since the previous frame
  bool stepMeasured = false;     ///< a previous frame rendered (the first has no step)
};

/// Aggregates of one configuration over the counted frames (index >= warmup).
struct StabilitySummary {
  int framesCounted = 0;
  int rotationChanges = 0;
  double maxRotationStepDeg = 0.0;
  int lastRotationChangeFrame = -1;
  int maskChangeFrames = 0;
  double maxMaskChangedPct = 0.0;
  int lastMaskChangeFrame = -1;
  /// NaN (not measured) when compared with the reference but no frame had a covered pixel.
  double errorPct = 0, falseLitPct = 0, falseShadowPct = 0;
  double covered = 0;
  double aliasingMean = 0, aliasingP95 = 0, aliasingMax = 0;
  double flickerPct = 0, flickerPctMean = 0, flickerPctMax = 0;
  double totalMs = 0;                                        ///< median frame
  double totalMsMax = 0;                                     ///< the worst frame
  int renderErrors = 0, glErrors = 0, nonFiniteNumbers = 0;  ///< failed frames: all of them
  bool hasRotation = false;
  /// Whether a counted frame had a previous frame to compare with: without one (fewer than
  /// two frames) the rotation steps and mask changes are not measured (NaN in metrics()).
  bool rotationStepsMeasured = false, maskChangesMeasured = false;
  /// The first failed frame and why ("" when every frame rendered). A failed frame is
  /// counted in render_errors and measures nothing: every other metric is over the frames
  /// that rendered, and NaN (not measured) when none did.
  std::string failure;
  bool failed() const { return !failure.empty(); }

  /// Why `name` is NaN (not measured) when it is: no covered pixel, no shadow-map coordinate,
  /// fewer than two frames to compare.
  static std::string notMeasuredReason(const std::string& name) {
    if (name.rfind("aliasing_", 0) == 0) return "no covered pixel with a shadow-map coordinate";
    if (name.rfind("flicker_", 0) == 0)
      return "no pixel covered in two consecutive frames with the reference";
    if (name.find("rotation") != std::string::npos || name.find("mask_change") != std::string::npos)
      return "fewer than 2 frames: nothing to compare";
    return "no covered pixel";
  }
  /// The metrics that count what went wrong, still meaningful when frames failed.
  static bool isFailureCount(const std::string& name) {
    return name == "render_errors" || name == "gl_errors" || name == "non_finite_numbers";
  }
  /// The metrics by name (the names expectations use).
  std::map<std::string, double> metrics() const {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto steps = [&](double v) { return rotationStepsMeasured ? v : nan; };
    auto changes = [&](double v) { return maskChangesMeasured ? v : nan; };
    return {{"frames", framesCounted},
            {"rotation_changes", steps(rotationChanges)},
            {"max_rotation_step_deg", steps(maxRotationStepDeg)},
            {"last_rotation_change_frame", steps(lastRotationChangeFrame)},
            {"mask_change_frames", changes(maskChangeFrames)},
            {"max_mask_changed_pct", changes(maxMaskChangedPct)},
            {"last_mask_change_frame", changes(lastMaskChangeFrame)},
            {"error_pct", errorPct},
            {"false_lit_pct", falseLitPct},
            {"false_shadow_pct", falseShadowPct},
            {"covered_pixels", covered},
            {"aliasing_mean", aliasingMean},
            {"aliasing_p95", aliasingP95},
            {"aliasing_max", aliasingMax},
            {"flicker_pct", flickerPct},
            {"flicker_pct_mean", flickerPctMean},
            {"flicker_pct_max", flickerPctMax},
            {"total_ms", totalMs},
            {"total_ms_max", totalMsMax},
            {"render_errors", renderErrors},
            {"gl_errors", glErrors},
            {"non_finite_numbers", nonFiniteNumbers}};
  }
};

/// Aggregates the frames with index >= warmup; failed frames are counted in every frame.
StabilitySummary summariseStability(const std::vector<StabilityFrame>& frames, int warmup);

}  // namespace sl::measure
