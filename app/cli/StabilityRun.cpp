// Running configurations frame by frame for the stability commands; see StabilityRun.h.
#include "StabilityRun.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "algo/InputFile.h"

using nlohmann::json;

namespace sl::cli {

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
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
