// The Qt-free parts of a labelled figure (renderer/figures/FigureKit.h draws it): what each cell
// shows and the optional zoom inset. shadowlab-cli fills them without Qt; only drawing needs Qt.
#pragma once

#include <string>

#include "metrics/Image.h"

namespace sl::ui {

struct FigureCell {
  std::string label;         ///< the configuration: "uniform resolution=1024"
  std::string facts;         ///< "1.05 M texels (4 MiB), error 0.42 %, 31.2 ms"
  ImageRGBA8 shaded, error;  ///< row 0 = top; the error image may be empty
};

/// A zoom inset: the region (fractions of the image, x right, y down) magnified `zoom`
/// times into the image's lower right corner, the region outlined where it is.
struct FigureInset {
  double x = 0.0, y = 0.0, w = 0.0, h = 0.0;
  int zoom = 3;
};

}  // namespace sl::ui
