// The pages panel family's entries for the registry (ui/panels/PanelRegistry.cpp).
#include "panels/pages/PagesPanels.h"

#include <QCoreApplication>

#include "panels/pages/PagesPanel.h"

namespace sl::ui {

std::vector<PanelEntry> pagesPanels() {
  return {
      {QStringLiteral("pages"), QCoreApplication::translate("sl::ui::MainWindow", "Pages"),
       Qt::BottomDockWidgetArea, [] { return new PagesPanel; }},
  };
}

}  // namespace sl::ui
