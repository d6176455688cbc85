// The speed- (or memory-) against-accuracy chart (issue 5): one point per configuration,
// x = time per frame or shadow memory, y = pixel error, one colour per technique, the
// Pareto front (lower-left) drawn as a line, each point labelled with its parameter
// values. Qt Charts rendered offscreen to a PNG; this header is Qt-free.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "algo/metrics/BenchStats.h"

class QImage;

namespace sl::cli {

struct ChartPoint {
  std::string technique;  ///< series (colour); series appear in first-seen order
  std::string label;      ///< drawn next to the point, e.g. "1024"
  double x = 0.0;         ///< ms or bytes (ChartSpec::x), as measured
  double y = 0.0;         ///< error_pct
};

struct ChartSpec {
  std::string title;
  std::string subtitle;  ///< second title line (conditions: size, frames, timing method)
  sl::ChartX x = sl::ChartX::TimeMs;  ///< what x is; its axis and title: sl::planCostAxis
  std::string yTitle = "pixel error against the exact reference (% of covered pixels)";
  std::vector<std::string> seriesNotes;  ///< optional legend suffix per technique, same order
  /// Error axis: "linear", "log" (needs every y > 0), or "auto": log when every y > 0 and
  /// they span more than a factor 20 (a few outliers would squash the rest), else linear.
  std::string yScale = "auto";
  int width = 1280, height = 800;  ///< pixels
};

#if SHADOWLAB_CLI_CHARTS
/// A QApplication on the offscreen platform (Qt Charts draws with widgets' fonts and
/// styles). Made once, on first use, after any GL work has its own EGL context.
void ensureOffscreenApplication();
/// `image` as a PNG at `path` through writeFile: QImage::save reports no failed write (a full
/// disk, /dev/full), writeFile checks every one. An error naming `path` or nothing.
std::optional<std::string> savePng(const QImage& image, const std::string& path);
#endif

/// Renders the chart to `pngPath`. Returns an error when it cannot (no Qt Charts in this
/// build, no points, the file cannot be written).
std::optional<std::string> writeSpeedAccuracyChart(const std::vector<ChartPoint>& points,
                                                   const ChartSpec& spec,
                                                   const std::string& pngPath);

}  // namespace sl::cli
