// The spherical panel family's entries for the registry (ui/panels/PanelRegistry.cpp).
#include "panels/spherical/SphericalPanels.h"

#include <QCoreApplication>

#include "panels/spherical/SphericalMapPanel.h"

namespace sl::ui {

std::vector<PanelEntry> sphericalPanels() {
  return {
      {QStringLiteral("spherical"),
       QCoreApplication::translate("sl::ui::MainWindow", "Spherical map"), Qt::LeftDockWidgetArea,
       [] { return new SphericalMapPanel; }},
  };
}

}  // namespace sl::ui
