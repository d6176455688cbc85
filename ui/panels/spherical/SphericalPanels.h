// The spherical (latitude-longitude) family of publication panels (the `spherical` omni
// shadow map): the Spherical map panel.
#pragma once

#include <vector>

#include "panels/PanelRegistry.h"

namespace sl::ui {

std::vector<PanelEntry> sphericalPanels();

}  // namespace sl::ui
