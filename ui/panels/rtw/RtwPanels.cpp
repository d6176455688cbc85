// The RTW panel family's entries for the registry (ui/panels/PanelRegistry.cpp).
#include "panels/rtw/RtwPanels.h"

#include <QCoreApplication>

#include "panels/rtw/CovariancePanel.h"
#include "panels/rtw/ImportancePanel.h"
#include "panels/rtw/MomentPanel.h"
#include "panels/rtw/ShadowMapPanel.h"
#include "panels/rtw/WarpPanel.h"

namespace sl::ui {

namespace {
template <typename T>
PanelEntry entry(const char* id, const char* title, Qt::DockWidgetArea area) {
  return {QString::fromLatin1(id), QCoreApplication::translate("sl::ui::MainWindow", title), area,
          [] { return new T; }};
}
}  // namespace

std::vector<PanelEntry> rtwPanels() {
  return {
      entry<ImportancePanel>("importance", "Importance map", Qt::LeftDockWidgetArea),
      entry<CovariancePanel>("covariance", "Covariance", Qt::LeftDockWidgetArea),
      entry<WarpPanel>("warp", "Warp functions", Qt::BottomDockWidgetArea),
      entry<ShadowMapPanel>("shadowmap", "Shadow map", Qt::BottomDockWidgetArea),
      entry<MomentPanel>("moments", "Moment mip chain", Qt::LeftDockWidgetArea),
  };
}

}  // namespace sl::ui
