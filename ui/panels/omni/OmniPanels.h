// The omni-directional family of publication panels (cube and dual-paraboloid shadow maps,
// seed 001): the Omni map panel.
#pragma once

#include <vector>

#include "panels/PanelRegistry.h"

namespace sl::ui {

std::vector<PanelEntry> omniPanels();

}  // namespace sl::ui
