// The `panels` self-test (see GuiTests.h): which publication panels the window shows for
// each technique, and that a panel opened by hand stays; the `turn-prediction` test: the
// Covariance panel's predicted turn against the measured one.
#include <algorithm>
#include <cmath>

#include <QAction>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QTest>
#include <QCoreApplication>
#include <QDir>
#include <QJsonArray>
#include <QPushButton>
#include <QTimer>
#include <QElapsedTimer>
#include <QStringList>

#include "window/MainWindow.h"
#include "GuiTests.h"
#include "view/ViewportWidget.h"
#include "panels/common/ParamPanel.h"
#include "panels/rtw/CovariancePanel.h"
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
    if (auto e = auto_.setTechnique(technique)) check(false, *e);
    waitForFrames(2);
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
  waitForFrames(2);
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

bool GuiTests::turnPrediction(const QString& dir) {
  check(auto_.openScene(QStringLiteral("band-diagonal")), tr("scene band-diagonal"));
  check(!auto_.setTechnique(QStringLiteral("da-rtw")), tr("technique da-rtw"));
  check(!auto_.setParameter(QStringLiteral("resolution=512")), tr("resolution 512"));
  PublicationPanel* panel = nullptr;
  for (const PublicationDocks::Dock& d : w_.docks().docks())
    if (d.entry.id == QLatin1String("covariance")) panel = d.panel;
  check(panel != nullptr, tr("a Covariance panel"));
  if (!panel) return false;
  w_.docks().dock("covariance")->raise();
  // The first prediction weighs the shadow edges of the frame before the last: frame 3.
  QJsonObject drawn;
  for (int k = 0; k < 12; ++k) {
    waitForFrames(1);
    drawn = panel->drawnValues();
    if (drawn.value(QStringLiteral("state")).toString() == QLatin1String("held_best")) break;
  }
  const QJsonArray ratios = drawn.value(QStringLiteral("prediction.ratios")).toArray();
  check(ratios.size() == 37, tr("the Turn prediction draws 37 turns (%1)").arg(ratios.size()));
  int lowest = 0;
  for (int i = 1; i < ratios.size(); ++i)
    if (ratios[i].toDouble(1e9) < ratios[lowest].toDouble(1e9)) lowest = i;
  const double lowestDeg = -90.0 + 5.0 * lowest;
  const double chosen = drawn.value(QStringLiteral("prediction.chosen_deg")).toDouble(std::nan(""));
  check(std::abs(std::abs(lowestDeg) - 45.0) <= 5.0 && std::abs(std::abs(chosen) - 45.0) <= 3.75,
        tr("the turn is chosen at the curve's lowest point: curve lowest at %1°, R at %2°")
            .arg(lowestDeg)
            .arg(chosen, 0, 'f', 2));
  check(drawn.value(QStringLiteral("prediction.markers")).toInt() >= 3,
        tr("the plot marks now, was and PCA's axis (%1 markers with their copies)")
            .arg(drawn.value(QStringLiteral("prediction.markers")).toInt()));
  const QString stateText = drawn.value(QStringLiteral("state_text")).toString();
  check(stateText.contains(QStringLiteral("HELD")) || stateText.contains(QStringLiteral("TURNED")),
        tr("the state says what the rotation did and why: \"%1\"").arg(stateText));

  // The measured sweep, on the render thread: the window keeps answering meanwhile.
  auto* button = panel->findChild<QPushButton*>(QStringLiteral("covarianceMeasure"));
  check(button && button->isEnabled(), tr("the Measure button is there and enabled"));
  if (!button) return false;
  QElapsedTimer clock;
  qint64 last = 0, worstGapMs = 0;
  QTimer beat;
  clock.start();
  connect(&beat, &QTimer::timeout, this, [&] {
    worstGapMs = std::max(worstGapMs, clock.elapsed() - last);
    last = clock.elapsed();
  });
  beat.start(10);
  button->click();
  const int total = panel->drawnValues().value(QStringLiteral("measured.total")).toInt();
  QElapsedTimer wait;
  wait.start();
  while (panel->drawnValues().value(QStringLiteral("measured.done")).toInt() < total &&
         wait.elapsed() < 240000)
    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
  beat.stop();
  drawn = panel->drawnValues();
  const int done = drawn.value(QStringLiteral("measured.done")).toInt();
  check(total == 14 && done == total, tr("every turn measured: %1 of %2 in %3 s")
                                          .arg(done)
                                          .arg(total)
                                          .arg(wait.elapsed() / 1000.0));
  // A 1-second bound: the jobs run on the render thread; the window only plots answers.
  check(worstGapMs < 1000,
        tr("the window kept answering while they ran (longest stall %1 ms)").arg(worstGapMs));
  const QJsonArray measured = drawn.value(QStringLiteral("measured.ratios")).toArray();
  int best = 0;
  for (int i = 1; i < measured.size(); ++i)
    if (measured[i].toDouble(1e9) < measured[best].toDouble(1e9)) best = i;
  const double bestDeg = -90.0 + 15.0 * best;
  // The measured ratios are against the current angle (±45°, the turned frame): the unturned
  // frame (0°) measures many times its error, as predicted.
  const double atZero = measured.size() == 13 ? measured[6].toDouble(std::nan("")) : std::nan("");
  const double predictedAtZero =
      ratios.size() == 37 ? ratios[18].toDouble(std::nan("")) : std::nan("");
  check(std::abs(std::abs(bestDeg) - 45.0) < 1e-9 && atZero > 1.5 && predictedAtZero > 1.0,
        tr("truth and prediction agree: the measured error is lowest at %1°, the unturned frame "
           "measures %2x the turned one's (predicted %3x)")
            .arg(bestDeg)
            .arg(atZero, 0, 'f', 2)
            .arg(predictedAtZero, 0, 'f', 2));
  // The threshold on its own scale: a click on the gauge at 1 - threshold = 1e-6 sets it
  // finer than the Parameters panel's step (0.0001), and the Parameters panel shows it whole.
  if (auto* covariance = qobject_cast<CovariancePanel*>(panel)) {
    QWidget* gauge = covariance->thresholdGauge();
    QTest::mouseClick(gauge, Qt::LeftButton, {}, covariance->thresholdGaugePoint(1e-6));
    QCoreApplication::processEvents();
    const double threshold = w_.viewport()->mainSide()->params().get("pca.threshold");
    auto* spin = w_.paramPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("param:pca.threshold"));
    const QString shown = spin ? spin->text() : QString();
    check(std::abs(std::log10(1.0 - threshold) + 6.0) < 0.05 &&
              std::abs(shown.toDouble() - threshold) < 1e-9,
          tr("a click on the gauge at 1e-6 sets the threshold %1 (1 - threshold = %2), the "
             "Parameters panel shows \"%3\"")
              .arg(threshold, 0, 'f', 9)
              .arg(1.0 - threshold, 0, 'e', 2)
              .arg(shown));
    waitForFrames(2);
    const QJsonObject band = panel->drawnValues();
    check(band.value(QStringLiteral("gauge.band_frames")).toInt() >= 2 &&
              band.value(QStringLiteral("gauge.band_lo")).toDouble() <=
                  band.value(QStringLiteral("gauge.band_hi")).toDouble(),
          tr("the gauge shows 1 - e_x of the last %1 frames as a band")
              .arg(band.value(QStringLiteral("gauge.band_frames")).toInt()));
    w_.paramPanel()->edit("pca.threshold",
                          w_.viewport()->mainSide()->params().find("pca.threshold")->defaultValue);
  }
  if (!dir.isEmpty() && QDir().mkpath(dir)) {
    // The panel as a user gives it the left column (the docks beside it closed from their
    // title bars), after a frame that predicted again: a picture of prediction against truth.
    QDockWidget* dock = w_.docks().dock("covariance");
    for (const PublicationDocks::Dock& d : w_.docks().docks())
      if (d.dock != dock && w_.dockWidgetArea(d.dock) == w_.dockWidgetArea(dock)) d.dock->hide();
    for (int k = 0; k < 6; ++k) {
      waitForFrames(1);
      if (panel->drawnValues().value(QStringLiteral("prediction.valid")).toBool()) break;
    }
    dock->grab().save(QDir(dir).filePath(QStringLiteral("covariance-turn-prediction.png")));
    w_.grab().save(QDir(dir).filePath(QStringLiteral("window.png")));
  }
  return true;
}

}  // namespace sl::ui
