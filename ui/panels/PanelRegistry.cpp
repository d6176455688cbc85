// The one list of publication-panel families (see PanelRegistry.h).
#include "panels/PanelRegistry.h"

#include "panels/analysis/AnalysisPanels.h"
#include "panels/fvsm/FvsmPanels.h"
#include "panels/omni/OmniPanels.h"
#include "panels/pages/PagesPanels.h"
#include "panels/perspective/PerspectivePanels.h"
#include "panels/partition/PartitionPanels.h"
#include "panels/rtw/RtwPanels.h"

namespace sl::ui {

const std::vector<PanelEntry>& publicationPanels() {
  static const std::vector<PanelEntry> list = [] {
    std::vector<PanelEntry> all;
    for (std::vector<PanelEntry> family : {
             rtwPanels(),
             analysisPanels(),
             perspectivePanels(),
             partitionPanels(),
             omniPanels(),
             pagesPanels(),
             fvsmPanels(),
         })
      all.insert(all.end(), family.begin(), family.end());
    return all;
  }();
  return list;
}

}  // namespace sl::ui
