// What both stability runs share (one technique, or a suite of cases): running
// configurations frame by frame, the per-frame record and the summary whose names the
// suite's expectations use. See Stability.cpp and Suite.cpp.
#pragma once

#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "CliCommon.h"
#include "measure/Measure.h"

namespace sl::cli {

/// The largest orbit a frame (degrees, either way): `stability --orbit` and a suite's
/// `orbit_deg_per_frame`. A larger step is the same view as a smaller one the other way.
inline constexpr double kMaxOrbitDegPerFrame = 180.0;

/// Signed smallest difference of two angles in degrees, in [-180, 180).
double angleStepDeg(double from, double to);
/// A camera orbiting the point it looks at on the ground (y = scene floor), so a slow
/// orbit keeps the same part of the scene in view; a camera looking up orbits its target.
Camera orbitCentred(Camera cam, const Scene& scene);
/// "%.6g".
std::string fmt(double v);

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
nlohmann::json summaryJson(const StabilitySummary& s);
nlohmann::json frameJson(std::size_t k, const StabilityFrame& fr);

/// Runs `runners` over `cameras`, interleaved frame by frame; right before its frame f each
/// renders `between[f]` unmeasured (a path's in-between frames, MeasureCameras; none when
/// `between` is shorter).
std::vector<std::vector<StabilityFrame>> runFrames(
    std::vector<std::unique_ptr<ConfigRunner>>& runners, const std::vector<Camera>& cameras,
    const MeasureOptions& opts, ReferenceCache* reference, ProgressBar& progress,
    const std::vector<std::vector<Camera>>& between = {});

/// `stability --suite`: runs the suite file's cases, prints the tables and expectations,
/// writes `jsonPath` (when not empty); 1 when an expectation fails. Suite.cpp.
int runSuite(const std::string& file, double framesScale,
             const std::optional<std::pair<int, int>>& sizeOverride,
             const std::vector<std::string>& onlyCases,
             const std::vector<std::string>& onlyTechniques, const std::string& jsonPath);

/// Reads and checks a suite file as runSuite does before any case runs (keys, techniques,
/// parameters, expectations, scene names; not the frame sizes, which need a GL context).
/// Returns the number of cases; throws UsageError naming the file and the JSON path. Needs
/// no GL: the fuzz target tests/fuzz/fuzz_json.cpp calls it. Suite.cpp.
std::size_t checkSuiteFile(const std::string& file);

}  // namespace sl::cli
