// The perspective-warp family's entries for the registry (ui/panels/PanelRegistry.cpp).
#include "panels/perspective/PerspectivePanels.h"

#include <QCoreApplication>

#include "panels/perspective/PerspectiveWarpPanel.h"

namespace sl::ui {

std::vector<PanelEntry> perspectivePanels() {
  return {{QStringLiteral("perspective"),
           QCoreApplication::translate("sl::ui::MainWindow", "Perspective warp"),
           Qt::LeftDockWidgetArea, [] { return new PerspectiveWarpPanel; }}};
}

}  // namespace sl::ui
