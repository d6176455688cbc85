// The two storage-factor plots of `shadowlab-cli storage` (Lloyd et al., EGSR 2006, Figs. 6
// and 7) as PNGs: the data from algo/partition/StoragePlots.h, drawn offscreen with the
// pieces of renderer/figures/StorageChartKit.h (shared with the GUI's Storage factor panel).
// Qt-free header.
#pragma once

#include <optional>
#include <string>

#include "algo/partition/StoragePlots.h"

namespace sl::cli {

/// Fig. 6: the three curves normalised by their maxima (as the paper), with a legend naming
/// each maximum, the eta of uniform / LiSPSM / PSM marked on the axis title.
std::optional<std::string> writeEtaChart(const partition::EtaCurve& curve,
                                         const std::string& pngPath);

/// Fig. 7: one disk per scheme, log10 S on one shared colour scale with a colour bar.
std::optional<std::string> writeHemisphereChart(const partition::HemisphereFigure& fig,
                                                const std::string& pngPath);

}  // namespace sl::cli
