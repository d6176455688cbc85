// `compare --montage`: the compared configurations side by side for handouts, drawn by
// renderer/figures/FigureKit.h (the GUI's File > Export figure draws the same figure).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "figures/FigureTypes.h"

namespace sl::cli {

/// Why this build cannot draw a montage (built without Qt), or nothing; checked before any work.
std::optional<std::string> montageUnavailable();

/// Writes the montage PNG (`columns` cells per row; 0 = all in one row) as every output is
/// written: into a temporary file in the same folder, then renamed, so a failure leaves nothing
/// half-written. Throws std::runtime_error naming `pngPath` when it cannot be written; `cells`
/// must not be empty.
void writeMontage(const std::vector<sl::ui::FigureCell>& cells, const std::string& title,
                  int columns, const std::optional<sl::ui::FigureInset>& inset,
                  const std::string& pngPath);

}  // namespace sl::cli
