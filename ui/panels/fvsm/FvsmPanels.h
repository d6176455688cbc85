// The fitted-virtual-shadow-map family of publication panels (Giegl & Wimmer 2007): the FVSM
// panel.
#pragma once

#include <vector>

#include "panels/PanelRegistry.h"

namespace sl::ui {

std::vector<PanelEntry> fvsmPanels();

}  // namespace sl::ui
