// The omni panel family's entries for the registry (ui/panels/PanelRegistry.cpp).
#include "panels/omni/OmniPanels.h"

#include <QCoreApplication>

#include "panels/omni/OmniMapPanel.h"
#include "panels/omni/SphericalMapPanel.h"

namespace sl::ui {

std::vector<PanelEntry> omniPanels() {
  return {
      {QStringLiteral("omni"), QCoreApplication::translate("sl::ui::MainWindow", "Omni map"),
       Qt::BottomDockWidgetArea, [] { return new OmniMapPanel; }},
      {QStringLiteral("spherical"),
       QCoreApplication::translate("sl::ui::MainWindow", "Spherical map"), Qt::LeftDockWidgetArea,
       [] { return new SphericalMapPanel; }},
  };
}

}  // namespace sl::ui
