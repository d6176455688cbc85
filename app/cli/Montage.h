// `compare --montage`: the compared configurations side by side for handouts, drawn by
// ui/FigureKit.h (the GUI's File > Export figure draws the same figure).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "FigureTypes.h"

namespace sl::cli {

/// Writes the montage PNG (`columns` cells per row; 0 = all in one row). An error when it
/// cannot (no Qt in this build, no cells, the file cannot be written).
std::optional<std::string> writeMontage(const std::vector<sl::ui::FigureCell>& cells,
                                        const std::string& title, int columns,
                                        const std::optional<sl::ui::FigureInset>& inset,
                                        const std::string& pngPath);

}  // namespace sl::cli
