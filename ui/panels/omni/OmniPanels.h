// The omni-directional family of publication panels: the Omni map panel (the cube and
// dual-paraboloid shadow maps, seed 001) and the Spherical map panel (the `spherical`
// latitude-longitude map), both on OmniPanelBase.
#pragma once

#include <vector>

#include "panels/PanelRegistry.h"

namespace sl::ui {

std::vector<PanelEntry> omniPanels();

}  // namespace sl::ui
