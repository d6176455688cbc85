// A quick sweep on one renderer, what the GUI's Charts panel runs one frame per render-service
// job (so the view's frames go on between two of its frames): configurations one after another,
// each `frames` frames along the scene's first camera path (bench's frame spacing, pathCameras with
// no in-between frames), each frame's time, shadow memory and error against the exact reference,
// and the medians per configuration. Unlike runInterleaved (one renderer per configuration,
// interleaved frame by frame, warm-up frames) it reuses one renderer, so it suits a window that
// already holds several.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/Renderer.h"

namespace sl::measure {

/// One configuration with every parameter value (technique's and shared), as rendered.
struct SweepConfig {
  std::string techniqueId;
  ParamSet own;     ///< the technique's parameters
  ParamSet shared;  ///< the renderer's (rendererParamDecls)
};

/// What one frame of a configuration measured.
struct SweepFrame {
  double ms = 0.0;     ///< the whole frame (FrameStats::totalMs)
  double bytes = 0.0;  ///< the technique's shadow memory
  /// % of covered pixels; NaN when no pixel was covered (n/a, never 0).
  double errorPct = std::numeric_limits<double>::quiet_NaN();
  std::string problem;  ///< why the frame failed ("" when it rendered)
};

/// The cameras of a sweep: `frames` along the scene's first camera path (pathCameras, no
/// in-between frames), else `frames` times `fixed`.
std::vector<Camera> sweepCameras(const Scene& scene, const Camera& fixed, int frames);

/// Renders `config` from `camera` on `r` (the scene, the light; `first`: forget the temporal
/// state of earlier frames) and measures it (needs the current GL context).
SweepFrame measureSweepFrame(Renderer& r, const std::shared_ptr<const Scene>& scene,
                             const Light& light, const SweepConfig& config, const Camera& camera,
                             int width, int height, bool first);

/// Where a sweep starts or goes on: configuration `config`, its frame `frame`.
struct SweepPosition {
  std::size_t config = 0, frame = 0;
};

/// Every configuration, every camera, in that order, on `r`, from `from` on (a sweep that was
/// stopped goes on where it stopped); `onFrame(config, frame, m)` after each. Stops after a
/// failed frame, before a frame when `stop` (may be null) is raised, or after `maxFrames`
/// frames (0: no limit); returns where it stopped, i.e. the next frame to measure
/// (configs.size() and 0 when it measured every frame; at the failed frame after a failure).
SweepPosition runSweep(
    Renderer& r, const std::shared_ptr<const Scene>& scene, const Light& light,
    const std::vector<SweepConfig>& configs, const std::vector<Camera>& cameras, int width,
    int height, SweepPosition from, const std::atomic<bool>* stop,
    const std::function<void(std::size_t, std::size_t, const SweepFrame&)>& onFrame,
    std::size_t maxFrames = 0);

/// The median of a configuration's frames; NaN when empty or when one value is not a number
/// (an unmeasured error makes the configuration's error n/a).
double sweepMedian(std::vector<double> values);

}  // namespace sl::measure
