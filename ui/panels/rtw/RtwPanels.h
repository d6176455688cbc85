// The RTW / DA-RTW family of publication panels (Rosen 2012; Tokuyoshi et al. 2014):
// importance map, covariance (PCA), warp functions, warped shadow map, moment mip chain.
#pragma once

#include <vector>

#include "panels/PanelRegistry.h"

namespace sl::ui {

std::vector<PanelEntry> rtwPanels();

}  // namespace sl::ui
