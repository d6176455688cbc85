// The storage-click self-test (see GuiTests.h): a click on the Storage factor panel's
// hemisphere moves the light to the direction under the cursor (issue 10).
#include <cmath>
#include <cstdio>

#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QImage>
#include <QMouseEvent>
#include <QStatusBar>

#include "window/MainWindow.h"
#include "GuiTests.h"
#include "view/ViewportWidget.h"
#include "algo/partition/StoragePlots.h"
#include "panels/analysis/StoragePanel.h"

namespace sl::ui {

namespace {
constexpr qint64 kAnalysisTimeoutMs = 60000;  ///< llvmpipe under Xvfb on a busy 2-core machine

void click(QWidget* widget, const QPointF& at) {
  const QPointF global = widget->mapToGlobal(at);
  QMouseEvent press(QEvent::MouseButtonPress, at, global, Qt::LeftButton, Qt::LeftButton,
                    Qt::NoModifier);
  QCoreApplication::sendEvent(widget, &press);
  QMouseEvent release(QEvent::MouseButtonRelease, at, global, Qt::LeftButton, Qt::NoButton,
                      Qt::NoModifier);
  QCoreApplication::sendEvent(widget, &release);
  QCoreApplication::processEvents();
}

/// Degrees between two directions given as azimuth and elevation.
double angleDeg(const sl::Light& a, const sl::Light& b) {
  // atan2 of sine and cosine: acos loses the small angles (float directions: 0.03°).
  const glm::dvec3 x(a.directionalTowards()), y(b.directionalTowards());
  return glm::degrees(std::atan2(glm::length(glm::cross(x, y)), glm::dot(x, y)));
}
}  // namespace

bool GuiTests::storageClick(const QString& dir) {
  StoragePanel* panel = nullptr;
  for (const PublicationDocks::Dock& d : w_.docks().docks())
    if (d.entry.id == QLatin1String("storage")) panel = qobject_cast<StoragePanel*>(d.panel);
  QDockWidget* dock = w_.docks().dock("storage");
  check(panel && dock, tr("the Storage factor dock exists"));
  if (!panel || !dock) return false;
  dock->show();
  dock->raise();
  QCoreApplication::processEvents();
  ViewportWidget* view = w_.viewport();
  check(view->camera()->light().type == sl::LightType::Directional,
        tr("the scene's light is directional"));

  // The analysis runs off the UI thread: wait until the panel drew the frame's light.
  auto analysedLight = [&](const sl::Light& light) {
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < kAnalysisTimeoutMs) {
      waitForFrames(1);
      const QJsonObject drawn = panel->drawnValues();
      if (drawn.contains(QStringLiteral("mark_u"))) {
        const sl::Light shown = sl::Light::directional(
            float(drawn.value(QStringLiteral("light_azimuth_deg")).toDouble()),
            float(drawn.value(QStringLiteral("light_elevation_deg")).toDouble()));
        if (angleDeg(shown, light) < 0.01) return true;
      }
    }
    return false;
  };
  check(analysedLight(view->camera()->light()), tr("the panel analysed the frame's light"));

  // The direction a click at disk coordinates (u, v) must pick: the paper's Fig. 7 frame of
  // this camera (algo/partition, as the CLI's plot), independent of the panel.
  const sl::partition::HemisphereFrame frame = sl::partition::HemisphereFrame::forView(
      sl::warp::ViewFrustum::fromCamera(view->camera()->camera(),
                                        double(view->width()) / std::max(1, view->height())),
      glm::dvec3(0.0, 1.0, 0.0));
  const QJsonObject before = panel->drawnValues();
  const glm::dvec2 mark(before.value(QStringLiteral("mark_u")).toDouble(),
                        before.value(QStringLiteral("mark_v")).toDouble());
  const glm::dvec2 markExpected =
      frame.disk(glm::dvec3(view->camera()->light().directionalTowards()));
  check(glm::length(mark - markExpected) < 1e-3,
        tr("the light's mark is at (%1, %2); its direction in this camera's frame: (%3, %4)")
            .arg(mark.x, 0, 'f', 4)
            .arg(mark.y, 0, 'f', 4)
            .arg(markExpected.x, 0, 'f', 4)
            .arg(markExpected.y, 0, 'f', 4));

  // Two clicks far from the mark and from each other: behind the viewer to its right, then
  // in front to its left.
  int step = 0;
  for (const glm::dvec2 uv : {glm::dvec2(-0.45, 0.35), glm::dvec2(0.55, -0.3)}) {
    ++step;
    const std::optional<glm::dvec3> towards = frame.direction(uv.x, uv.y);
    check(bool(towards), tr("(%1, %2) is inside the disk").arg(uv.x).arg(uv.y));
    if (!towards) continue;
    const sl::Light expected = sl::Light::directionalFromTowards(glm::vec3(*towards));
    click(panel->hemisphereWidget(), panel->hemispherePoint(uv.x, uv.y));
    const sl::Light& now = view->camera()->light();
    check(now.type == sl::LightType::Directional && angleDeg(now, expected) < 0.05,
          tr("click %1 at disk (%2, %3): light azimuth %4°, elevation %5°; expected %6°, %7° "
             "(%8° apart)")
              .arg(step)
              .arg(uv.x)
              .arg(uv.y)
              .arg(now.azimuthDeg, 0, 'f', 2)
              .arg(now.elevationDeg, 0, 'f', 2)
              .arg(expected.azimuthDeg, 0, 'f', 2)
              .arg(expected.elevationDeg, 0, 'f', 2)
              .arg(angleDeg(now, expected), 0, 'f', 3));
    check(auto_.statusMessage().contains(QStringLiteral("Light moved to azimuth")),
          tr("the status bar says: %1").arg(auto_.statusMessage()));
    // The next frames render with it, and the panel re-analyses with the mark under the click.
    check(analysedLight(now), tr("the panel re-analysed the moved light"));
    const QJsonObject after = panel->drawnValues();
    const glm::dvec2 moved(after.value(QStringLiteral("mark_u")).toDouble(),
                           after.value(QStringLiteral("mark_v")).toDouble());
    check(glm::length(moved - uv) < 2e-3, tr("the mark moved to (%1, %2), under the click")
                                              .arg(moved.x, 0, 'f', 4)
                                              .arg(moved.y, 0, 'f', 4));
    if (!dir.isEmpty() && QDir().mkpath(dir))
      w_.grab().toImage().save(
          QDir(dir).filePath(QStringLiteral("storage-click-%1.png").arg(step)));
  }

  // Outside the disk nothing is picked: the light stays.
  const sl::Light kept = view->camera()->light();
  click(panel->hemisphereWidget(), panel->hemispherePoint(0.95, 0.95));
  check(angleDeg(view->camera()->light(), kept) == 0.0,
        tr("a click outside the disk keeps the light"));
  return true;
}

}  // namespace sl::ui
