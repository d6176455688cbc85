// The two storage-factor plots of `shadowlab-cli storage` (Lloyd et al., EGSR 2006, Figs. 6
// and 7): M_x, M_z and S over eta, and S over the hemisphere of light directions per scheme
// (log10 colour map). Qt draws them offscreen into PNGs; this header is Qt-free.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace sl::cli {

struct EtaCurve {
  std::vector<double> eta, mx, mz, s;  ///< same length, eta ascending
  std::string title, subtitle;
};

/// Fig. 6: the three curves normalised by their maxima (as the paper), with a legend naming
/// each maximum, the eta of uniform / LiSPSM / PSM marked on the axis title.
std::optional<std::string> writeEtaChart(const EtaCurve& curve, const std::string& pngPath);

struct HemispherePanel {
  std::string title;      ///< the scheme
  int grid = 0;           ///< cells per side
  std::vector<double> s;  ///< grid * grid, row-major (row 0 at the top); NaN outside the disk
};

struct HemisphereFigure {
  std::string title, subtitle;
  std::vector<HemispherePanel> panels;
  double markU = 0.0, markV = 0.0;  ///< the --light, in the panels' [-1, 1] coordinates
};

/// Fig. 7: one disk per scheme, log10 S on one shared colour scale with a colour bar.
std::optional<std::string> writeHemisphereChart(const HemisphereFigure& fig,
                                                const std::string& pngPath);

}  // namespace sl::cli
