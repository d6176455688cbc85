// The list of the docks that show the renderer's Publication, one family per folder under
// ui/panels/ (rtw/ today; partition/, pages/, omni/ later). Adding a family: its folder
// with a function returning its entries, and one line in PanelRegistry.cpp.
#pragma once

#include <functional>
#include <vector>

#include <QKeySequence>
#include <QString>

#include "panels/common/PanelKit.h"

namespace sl::ui {

struct PanelEntry {
  QString id;     ///< dock object name and PassDecl::panel ("warp")
  QString title;  ///< dock title ("Warp functions")
  Qt::DockWidgetArea area = Qt::BottomDockWidgetArea;
  std::function<PublicationPanel*()> create;
  /// Its View > Panels shortcut; empty: the next free one of Ctrl+3...9 in registry order.
  QKeySequence shortcut = {};
};

/// Every publication panel of every family, in the order their docks are created.
const std::vector<PanelEntry>& publicationPanels();

}  // namespace sl::ui
