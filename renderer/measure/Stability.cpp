// Stability of a configuration over frames (Stability.h).
#include "Stability.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sl::measure {

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

}  // namespace sl::measure
