// The analysis family of publication panels: the Storage factor panel (Lloyd, Tuft, Yoon,
// Manocha, EGSR 2006): the metric every warping and partitioning technique is judged by.
#pragma once

#include <vector>

#include "panels/PanelRegistry.h"

namespace sl::ui {

std::vector<PanelEntry> analysisPanels();

}  // namespace sl::ui
