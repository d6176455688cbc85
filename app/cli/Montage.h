// `compare --montage`: the compared configurations side by side for handouts — each cell
// the shaded image above its error image (error pixels dilated for print), with the
// configuration, texels, error and time printed under it; a title line on top.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "metrics/Image.h"

namespace sl::cli {

struct MontageCell {
  std::string label;  ///< the configuration: "uniform resolution=1024"
  std::string facts;  ///< "1.05 M texels (4 MiB) · error 0.42 % · 31.2 ms"
  ImageRGBA8 shaded, error;
};

/// A zoom inset: the region (fractions of the image, x right, y down) magnified `zoom`
/// times into the image's lower right corner, the region outlined where it is.
struct MontageInset {
  double x = 0.0, y = 0.0, w = 0.0, h = 0.0;
  int zoom = 3;
};

/// Writes the montage PNG (`columns` cells per row; 0 = all in one row), with `inset` drawn
/// into every image and error image when given. An error when it cannot (no Qt in this
/// build, no cells, the file cannot be written).
std::optional<std::string> writeMontage(const std::vector<MontageCell>& cells,
                                        const std::string& title, int columns,
                                        const std::optional<MontageInset>& inset,
                                        const std::string& pngPath);

}  // namespace sl::cli
