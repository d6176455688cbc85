// The `panels` self-test (see GuiTests.h): which publication panels the window shows for
// each technique, and that a panel opened by hand stays.
#include <QAction>
#include <QDockWidget>
#include <QStringList>

#include "MainWindow.h"
#include "GuiTests.h"
#include "ViewportWidget.h"
#include "panels/rtw/RtwPanels.h"

namespace sl::ui {

namespace {
/// The panels of DA-RTW's design (the RTW family): importance, moments, covariance, warp
/// functions, warped map.
QStringList rtwPanelIds() {
  QStringList ids;
  for (const PanelEntry& entry : rtwPanels()) ids << entry.id;
  return ids;
}
}  // namespace

bool GuiTests::panelsFollowTechnique() {
  const QStringList kRtwPanels = rtwPanelIds();
  auto dockOf = [this](const QString& id) { return w_.docks().dock(id.toStdString()); };
  auto isOpen = [&](const QString& id) {
    QDockWidget* dock = dockOf(id);
    return dock && !dock->isHidden();
  };
  auto inView = [&](const QString& id) {
    QDockWidget* dock = dockOf(id);
    return dock && dock->isVisible() && !dock->visibleRegion().isEmpty();
  };
  auto switchTo = [this](const QString& technique) {
    w_.setTechnique(technique);
    auto_.waitForFrames(2);
  };
  // No panel in view says that it gets nothing.
  auto checkNoEmptyPanel = [this](const QString& when) {
    QStringList empty;
    for (const PublicationDocks::Dock& d : w_.docks().docks())
      if (d.dock->isVisible() && !d.dock->visibleRegion().isEmpty() &&
          !d.panel->placeholderShown().isEmpty())
        empty << d.entry.id;
    check(empty.isEmpty(),
          tr("%1: no panel in view shows a placeholder (%2)")
              .arg(when, empty.isEmpty() ? tr("none") : empty.join(QStringLiteral(", "))));
  };

  check(w_.viewport()->techniqueId() == "da-rtw",
        tr("the window opens on da-rtw (%1)")
            .arg(QString::fromStdString(w_.viewport()->techniqueId())));
  auto_.waitForFrames(2);
  for (const QString& id : kRtwPanels)
    check(inView(id), tr("da-rtw: the %1 panel is in view").arg(id));
  check(w_.paramDock()->isVisible() && !w_.paramDock()->visibleRegion().isEmpty(),
        tr("da-rtw: the Parameters are in view"));
  checkNoEmptyPanel(tr("da-rtw"));

  switchTo(QStringLiteral("uniform"));
  for (const QString& id : kRtwPanels)
    if (id != QLatin1String("shadowmap"))
      check(!isOpen(id), tr("uniform: the %1 panel is closed").arg(id));
  check(inView(QStringLiteral("shadowmap")), tr("uniform: its Shadow map panel is in view"));
  check(inView(QStringLiteral("storage")), tr("uniform: the Storage factor panel is in view"));
  checkNoEmptyPanel(tr("uniform"));

  // Opened by hand: it stays through a switch to a technique that does not feed it either.
  QAction* covariance = dockOf(QStringLiteral("covariance"))->toggleViewAction();
  covariance->trigger();  // what View > Panels > Covariance does
  check(isOpen(QStringLiteral("covariance")), tr("View > Panels opens the Covariance panel"));
  switchTo(QStringLiteral("cascades"));
  check(isOpen(QStringLiteral("covariance")),
        tr("cascades: the Covariance panel opened by hand stays open"));
  check(inView(QStringLiteral("partitions")), tr("cascades: its Partitions panel is in view"));
  check(!isOpen(QStringLiteral("moments")) && !isOpen(QStringLiteral("warp")),
        tr("cascades: the Moment and Warp panels stay closed"));

  // Closed by hand: the next technique that does not feed it leaves it closed.
  covariance->trigger();
  check(!isOpen(QStringLiteral("covariance")), tr("View > Panels closes the Covariance panel"));
  switchTo(QStringLiteral("da-rtw"));
  for (const QString& id : kRtwPanels)
    check(inView(id), tr("back on da-rtw: the %1 panel is in view").arg(id));
  check(!isOpen(QStringLiteral("partitions")),
        tr("back on da-rtw: the Partitions panel is closed"));
  checkNoEmptyPanel(tr("back on da-rtw"));
  switchTo(QStringLiteral("uniform"));
  check(!isOpen(QStringLiteral("covariance")),
        tr("uniform again: the Covariance panel, no longer opened by hand, is closed"));
  return true;
}

}  // namespace sl::ui
