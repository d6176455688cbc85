// The perspective-warp panel family (psm, lispsm, tsm): the warp's state and its fallback.
#pragma once

#include <vector>

#include "panels/PanelRegistry.h"

namespace sl::ui {

std::vector<PanelEntry> perspectivePanels();

}  // namespace sl::ui
