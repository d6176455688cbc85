// The analysis panel family's entries for the registry (ui/panels/PanelRegistry.cpp).
#include "panels/analysis/AnalysisPanels.h"

#include <QCoreApplication>

#include "panels/analysis/StoragePanel.h"

namespace sl::ui {

std::vector<PanelEntry> analysisPanels() {
  return {
      {QStringLiteral("storage"),
       QCoreApplication::translate("sl::ui::MainWindow", "Storage factor"), Qt::LeftDockWidgetArea,
       [] { return new StoragePanel; }, QKeySequence(Qt::CTRL | Qt::Key_0)},
  };
}

}  // namespace sl::ui
