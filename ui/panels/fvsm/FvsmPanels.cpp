// The fvsm family's entries for the registry (ui/panels/PanelRegistry.cpp).
#include "panels/fvsm/FvsmPanels.h"

#include <QCoreApplication>

#include "panels/fvsm/FvsmPanel.h"

namespace sl::ui {

std::vector<PanelEntry> fvsmPanels() {
  return {{QStringLiteral("fvsm"), QCoreApplication::translate("sl::ui::MainWindow", "FVSM"),
           Qt::BottomDockWidgetArea, [] { return new FvsmPanel; }}};
}

}  // namespace sl::ui
