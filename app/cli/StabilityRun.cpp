// Running configurations frame by frame for the stability commands; see StabilityRun.h.
#include "StabilityRun.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "algo/InputFile.h"

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
  int referenceFrames = 0, measuredFrames = 0, renderedFrames = 0;
  std::vector<const FrameSample*> order;
  for (const StabilityFrame& f : frames) order.push_back(&f.sample);
  s.failure = firstFailureText(order);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const FrameSample& f = frames[k].sample;
    s.hasRotation = s.hasRotation || f.hasRotation;
    // A failed frame, warm-up or not, is counted and measures nothing.
    s.renderErrors += f.failed() ? 1 : 0;
    if (int(k) < warmup) continue;
    ++s.framesCounted;
    s.glErrors += int(f.glErrors.size());
    if (f.failed()) continue;
    ++renderedFrames;
    if (frames[k].stepMeasured) {
      s.rotationStepsMeasured = true;
      const double step = std::abs(frames[k].rotationStepDeg);
      if (step > kRotationEpsDeg) {
        ++s.rotationChanges;
        s.lastRotationChangeFrame = int(k);
      }
      s.maxRotationStepDeg = std::max(s.maxRotationStepDeg, step);
    }
    if (f.maskChange) {
      s.maskChangesMeasured = true;
      if (f.maskChange->changed > 0) {
        ++s.maskChangeFrames;
        s.lastMaskChangeFrame = int(k);
      }
      s.maxMaskChangedPct = std::max(s.maxMaskChangedPct, f.maskChange->pct);
    }
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
    if (f.aliasing.pixels > 0) {  // no covered pixel with a shadow-map coordinate: none
      am.push_back(f.aliasing.mean);
      ap.push_back(f.aliasing.p95);
      ax.push_back(f.aliasing.max);
    }
    if (f.flicker && f.flicker->compared > 0) flick.push_back(f.flicker->pct);
    ms.push_back(f.totalMs);
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
  // Not measured (NaN), never 0: aliasing without a pixel to summarise, flicker without two
  // consecutive frames compared against the reference.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto medianOrNan = [&](const std::vector<double>& v) { return v.empty() ? nan : median(v); };
  s.aliasingMean = medianOrNan(am);
  s.aliasingP95 = medianOrNan(ap);
  s.aliasingMax = medianOrNan(ax);
  s.flickerPct = medianOrNan(flick);
  s.flickerPctMean = flick.empty() ? nan : 0.0;
  s.flickerPctMax = flick.empty() ? nan : 0.0;
  for (double v : flick) s.flickerPctMean += v / double(flick.size());
  for (double v : flick) s.flickerPctMax = std::max(s.flickerPctMax, v);
  s.totalMs = median(ms);
  for (double v : ms) s.totalMsMax = std::max(s.totalMsMax, v);
  if (renderedFrames == 0 && s.framesCounted > 0) {
    // No counted frame rendered: nothing was measured (null in JSON, "n/a" in text).
    for (double* v :
         {&s.maxRotationStepDeg, &s.maxMaskChangedPct, &s.errorPct, &s.falseLitPct,
          &s.falseShadowPct, &s.covered, &s.aliasingMean, &s.aliasingP95, &s.aliasingMax,
          &s.flickerPct, &s.flickerPctMean, &s.flickerPctMax, &s.totalMs, &s.totalMsMax})
      *v = std::numeric_limits<double>::quiet_NaN();
  }
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
  if (s.failed()) j["failure"] = s.failure;
  return j;
}

std::vector<std::vector<StabilityFrame>> runFrames(
    std::vector<std::unique_ptr<ConfigRunner>>& runners, const std::vector<Camera>& cameras,
    const MeasureOptions& opts, ReferenceCache* reference, ProgressBar& progress,
    const std::vector<std::vector<Camera>>& between) {
  std::vector<std::vector<StabilityFrame>> out(runners.size());
  const std::vector<Camera> none;
  for (std::size_t f = 0; f < cameras.size(); ++f) {
    for (std::size_t i = 0; i < runners.size(); ++i) {
      StabilityFrame fr;
      fr.sample = renderBetweenAndMeasure(*runners[i], f < between.size() ? between[f] : none,
                                          cameras[f], opts, reference);
      // The rotation step is from the last frame that rendered; a failed frame has none.
      for (auto it = out[i].rbegin(); it != out[i].rend() && !fr.sample.failed(); ++it)
        if (!it->sample.failed()) {
          fr.rotationStepDeg = angleStepDeg(it->sample.rotationDeg, fr.sample.rotationDeg);
          fr.stepMeasured = true;
          break;
        }
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
  if (s.failed()) {  // measured nothing
    json j = {{"frame", k}, {"render_error", cutText(s.renderError)}};
    if (!s.glErrors.empty()) j["gl_errors"] = s.glErrors;
    return j;
  }
  json j = {{"frame", k},
            {"rotation_deg", s.rotationDeg},
            {"rotation_step_deg", fr.stepMeasured ? json(fr.rotationStepDeg) : json(nullptr)},
            {"e_x", s.ex},
            {"held", s.held},
            {"mask_changed_pct", s.maskChange ? json(s.maskChange->pct) : json(nullptr)},
            {"mask_changed_pixels", s.maskChange ? json(s.maskChange->changed) : json(nullptr)},
            {"total_ms", s.totalMs}};
  if (s.hasReference) {
    j["error_pct"] = s.error.covered > 0 ? json(s.error.errorPct) : json(nullptr);
    j["flicker_pct"] = s.flicker && s.flicker->compared > 0 ? json(s.flicker->pct) : json(nullptr);
  }
  if (!s.renderError.empty()) j["render_error"] = s.renderError;
  if (!s.glErrors.empty()) j["gl_errors"] = s.glErrors;
  if (!s.nonFiniteNumbers.empty()) j["non_finite_numbers"] = s.nonFiniteNumbers;
  return j;
}

}  // namespace sl::cli
