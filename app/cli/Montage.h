// `compare --montage`: the compared configurations side by side for handouts, drawn by
// ui/FigureKit.h (the GUI's File > Export figure draws the same figure).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "metrics/Image.h"

namespace sl::cli {

struct MontageCell {
  std::string label;  ///< the configuration: "uniform resolution=1024"
  std::string facts;  ///< "1.05 M texels (4 MiB), error 0.42 %, 31.2 ms"
  ImageRGBA8 shaded, error;
};

/// A zoom inset: the region (fractions of the image, x right, y down) magnified `zoom`
/// times into the image's lower right corner.
struct MontageInset {
  double x = 0.0, y = 0.0, w = 0.0, h = 0.0;
  int zoom = 3;
};

/// Writes the montage PNG (`columns` cells per row; 0 = all in one row). An error when it
/// cannot (no Qt in this build, no cells, the file cannot be written).
std::optional<std::string> writeMontage(const std::vector<MontageCell>& cells,
                                        const std::string& title, int columns,
                                        const std::optional<MontageInset>& inset,
                                        const std::string& pngPath);

}  // namespace sl::cli
