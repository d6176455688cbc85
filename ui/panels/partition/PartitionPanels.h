// The partition family of publication panels (z-partitioning / cascades, face partitions):
// every partition's map side by side with its split distances and texel density.
#pragma once

#include <vector>

#include "panels/PanelRegistry.h"

namespace sl::ui {

std::vector<PanelEntry> partitionPanels();

}  // namespace sl::ui
