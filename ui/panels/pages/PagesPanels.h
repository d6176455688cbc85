// The pages family of publication panels (resolution-matched shadow maps, Lefohn et al.
// 2007; techniques/rmsm): the Pages panel.
#pragma once

#include <vector>

#include "panels/PanelRegistry.h"

namespace sl::ui {

std::vector<PanelEntry> pagesPanels();

}  // namespace sl::ui
