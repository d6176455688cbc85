// The partition panel family's entries for the registry (ui/panels/PanelRegistry.cpp).
#include "panels/partition/PartitionPanels.h"

#include <QCoreApplication>

#include "panels/partition/PartitionsPanel.h"

namespace sl::ui {

std::vector<PanelEntry> partitionPanels() {
  return {
      {QStringLiteral("partitions"),
       QCoreApplication::translate("sl::ui::MainWindow", "Partitions"), Qt::BottomDockWidgetArea,
       [] { return new PartitionsPanel; }},
  };
}

}  // namespace sl::ui
