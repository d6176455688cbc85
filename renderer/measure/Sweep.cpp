// A quick sweep on one renderer; see Sweep.h.
#include "measure/Sweep.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>

#include "algo/metrics/BenchStats.h"
#include "core/ViewSide.h"
#include "measure/Measure.h"

namespace sl::measure {

std::vector<Camera> sweepCameras(const Scene& scene, const Camera& fixed, int frames) {
  if (!scene.paths.empty() && !scene.paths[0].keys.empty())
    return pathCameras(scene.paths[0], frames, 0.0).measured;
  return std::vector<Camera>(std::size_t(std::max(frames, 0)), fixed);
}

SweepFrame measureSweepFrame(Renderer& r, const std::shared_ptr<const Scene>& scene,
                             const Light& light, const SweepConfig& config, const Camera& camera,
                             int width, int height, bool first) {
  SweepFrame m;
  try {
    if (r.scene() != scene) r.setScene(scene);
    if (auto e = r.setTechnique(config.techniqueId)) throw std::runtime_error(*e);
    syncParams(r.params(), config.own);
    syncParams(r.rendererParams(), config.shared);
    if (first) r.resetTemporalState();
    r.setLight(light);
    r.setCamera(camera);
    if (auto e = r.renderFrame(width, height, 0)) m.problem = *e;
    m.ms = r.stats().totalMs;
    m.bytes = double(r.stats().memory.bytes());
    // A frame with no covered pixel measured nothing: its error is n/a, never 0.
    const ShadowErrorStats error = r.computeError().stats;
    if (error.covered > 0) m.errorPct = error.errorPct;
  } catch (const std::exception& e) {
    m.problem = e.what();
  }
  return m;
}

SweepPosition runSweep(
    Renderer& r, const std::shared_ptr<const Scene>& scene, const Light& light,
    const std::vector<SweepConfig>& configs, const std::vector<Camera>& cameras, int width,
    int height, SweepPosition from, const std::atomic<bool>* stop,
    const std::function<void(std::size_t, std::size_t, const SweepFrame&)>& onFrame,
    std::size_t maxFrames) {
  std::size_t measured = 0;
  for (std::size_t c = from.config; c < configs.size(); ++c)
    for (std::size_t f = c == from.config ? from.frame : 0; f < cameras.size(); ++f) {
      if (stop && stop->load()) return {c, f};
      if (maxFrames > 0 && measured == maxFrames) return {c, f};
      const SweepFrame m =
          measureSweepFrame(r, scene, light, configs[c], cameras[f], width, height, f == 0);
      ++measured;
      if (onFrame) onFrame(c, f, m);
      if (!m.problem.empty()) return {c, f};
    }
  return {configs.size(), 0};
}

double sweepMedian(std::vector<double> values) {
  if (values.empty() ||
      !std::all_of(values.begin(), values.end(), [](double x) { return std::isfinite(x); }))
    return std::numeric_limits<double>::quiet_NaN();
  return median(values);
}

}  // namespace sl::measure
