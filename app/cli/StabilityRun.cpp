// Running configurations frame by frame for the stability commands; see StabilityRun.h.
#include "StabilityRun.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

using nlohmann::json;

namespace sl::cli {

/// Signed smallest difference of two angles in degrees, in [-180, 180).
double angleStepDeg(double from, double to) {
  double d = std::fmod(to - from + 540.0, 360.0);
  if (d < 0) d += 360.0;
  return d - 180.0;
}

/// A camera orbiting the point it looks at on the ground (y = scene floor), so a slow
/// orbit keeps the same part of the scene in view; a camera looking up orbits its target.
Camera orbitCentred(Camera cam, const Scene& scene) {
  const glm::vec3 f = cam.forward();
  const float floorY = scene.bounds.valid() ? scene.bounds.min.y : 0.0f;
  if (f.y < -0.02f) {
    float t = (floorY - cam.position.y) / f.y;
    if (t > 0.0f && std::isfinite(t)) cam.target = cam.position + t * f;
  }
  return cam;
}

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

constexpr double kRotationEpsDeg = 1e-6;  ///< smaller steps are float noise, not a change

StabilitySummary summariseStability(const std::vector<StabilityFrame>& frames, int warmup) {
  StabilitySummary s;
  std::vector<double> err, fl, fs, cov, am, ap, ax, flick, ms;
  int referenceFrames = 0, measuredFrames = 0;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const FrameSample& f = frames[k].sample;
    s.hasRotation = s.hasRotation || f.hasRotation;
    if (int(k) < warmup) continue;
    ++s.framesCounted;
    const double step = std::abs(frames[k].rotationStepDeg);
    if (step > kRotationEpsDeg) {
      ++s.rotationChanges;
      s.lastRotationChangeFrame = int(k);
    }
    s.maxRotationStepDeg = std::max(s.maxRotationStepDeg, step);
    if (f.maskChange && f.maskChange->changed > 0) {
      ++s.maskChangeFrames;
      s.lastMaskChangeFrame = int(k);
    }
    if (f.maskChange) s.maxMaskChangedPct = std::max(s.maxMaskChangedPct, f.maskChange->pct);
    if (f.hasReference) {
      ++referenceFrames;
      cov.push_back(double(f.error.covered));
    }
    if (f.hasReference && f.error.covered > 0) {  // no covered pixel: nothing measured
      ++measuredFrames;
      err.push_back(f.error.errorPct);
      fl.push_back(f.error.falseLitPct);
      fs.push_back(f.error.falseShadowPct);
    }
    am.push_back(f.aliasing.mean);
    ap.push_back(f.aliasing.p95);
    ax.push_back(f.aliasing.max);
    if (f.flicker) flick.push_back(f.flicker->pct);
    ms.push_back(f.totalMs);
    s.renderErrors += f.renderError.empty() ? 0 : 1;
    s.glErrors += int(f.glErrors.size());
    s.nonFiniteNumbers += int(f.nonFiniteNumbers.size());
  }
  if (referenceFrames > 0 && measuredFrames == 0) {
    // Compared with the reference, but no frame had a covered pixel: not measured (NaN,
    // null in JSON, "n/a" in text), not a perfect 0.
    s.errorPct = s.falseLitPct = s.falseShadowPct = std::numeric_limits<double>::quiet_NaN();
  } else {
    s.errorPct = median(err);
    s.falseLitPct = median(fl);
    s.falseShadowPct = median(fs);
  }
  s.covered = median(cov);
  s.aliasingMean = median(am);
  s.aliasingP95 = median(ap);
  s.aliasingMax = median(ax);
  s.flickerPct = median(flick);
  for (double v : flick) s.flickerPctMean += v / double(flick.size());
  for (double v : flick) s.flickerPctMax = std::max(s.flickerPctMax, v);
  s.totalMs = median(ms);
  for (double v : ms) s.totalMsMax = std::max(s.totalMsMax, v);
  return s;
}

json summaryJson(const StabilitySummary& s) {
  json j = json::object();
  for (const auto& [k, v] : s.metrics()) {
    if (!std::isfinite(v))
      j[k] = nullptr;  // not measured (an error metric without a covered pixel)
    else if (v == std::floor(v) && std::abs(v) < 1e15)
      j[k] = static_cast<long long>(v);  // counts (and round values) as integers
    else
      j[k] = v;
  }
  j["has_rotation"] = s.hasRotation;
  return j;
}

std::vector<std::vector<StabilityFrame>> runFrames(
    std::vector<std::unique_ptr<ConfigRunner>>& runners, const std::vector<Camera>& cameras,
    const MeasureOptions& opts, ReferenceCache* reference, ProgressBar& progress) {
  std::vector<std::vector<StabilityFrame>> out(runners.size());
  for (std::size_t f = 0; f < cameras.size(); ++f) {
    for (std::size_t i = 0; i < runners.size(); ++i) {
      StabilityFrame fr;
      fr.sample = runners[i]->renderAndMeasure(cameras[f], opts, reference);
      const double previous = out[i].empty() ? 0.0 : out[i].back().sample.rotationDeg;
      fr.rotationStepDeg = angleStepDeg(previous, fr.sample.rotationDeg);
      out[i].push_back(std::move(fr));
      progress.step("frame " + std::to_string(f + 1) + "/" + std::to_string(cameras.size()) + "  " +
                        runners[i]->spec().label,
                    i + 1 == runners.size());
    }
  }
  return out;
}

json frameJson(std::size_t k, const StabilityFrame& fr) {
  const FrameSample& s = fr.sample;
  json j = {{"frame", k},
            {"rotation_deg", s.rotationDeg},
            {"rotation_step_deg", fr.rotationStepDeg},
            {"e_x", s.ex},
            {"held", s.held},
            {"mask_changed_pct", s.maskChange ? s.maskChange->pct : 0.0},
            {"mask_changed_pixels", s.maskChange ? s.maskChange->changed : 0},
            {"total_ms", s.totalMs}};
  if (s.hasReference) {
    j["error_pct"] = s.error.covered > 0 ? json(s.error.errorPct) : json(nullptr);
    j["flicker_pct"] = s.flicker ? s.flicker->pct : 0.0;
  }
  if (!s.renderError.empty()) j["render_error"] = s.renderError;
  if (!s.glErrors.empty()) j["gl_errors"] = s.glErrors;
  if (!s.nonFiniteNumbers.empty()) j["non_finite_numbers"] = s.nonFiniteNumbers;
  return j;
}

}  // namespace sl::cli
