// The omni panel family's entries for the registry (ui/panels/PanelRegistry.cpp).
#include "panels/omni/OmniPanels.h"

#include <QCoreApplication>

#include "panels/omni/OmniMapPanel.h"

namespace sl::ui {

std::vector<PanelEntry> omniPanels() {
  return {
      {QStringLiteral("omni"), QCoreApplication::translate("sl::ui::MainWindow", "Omni map"),
       Qt::BottomDockWidgetArea, [] { return new OmniMapPanel; }},
  };
}

}  // namespace sl::ui
