// The session self-tests (see GuiTests.h): session-save=FILE sets a state far from the
// defaults, prints its metrics and saves it; session-check prints the metrics of the state the
// window started in (with --open-session FILE). tests/gui/session_roundtrip.sh compares them.
#include <cstdio>
#include <fstream>

#include <QApplication>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QKeyEvent>
#include <QLineEdit>
#include <QMessageBox>
#include <QStatusBar>
#include <QTimer>

#include "launch/LaunchOptions.h"
#include "teaching/LessonController.h"
#include "window/MainWindow.h"
#include "GuiTests.h"
#include "window/SessionFiles.h"
#include "teaching/TeachingBar.h"
#include "view/ViewportWidget.h"
#include "panels/common/ParamPanel.h"

namespace sl::ui {

namespace {
QString vec(const glm::vec3& v) {
  return QStringLiteral("%1 %2 %3").arg(v.x, 0, 'g', 9).arg(v.y, 0, 'g', 9).arg(v.z, 0, 'g', 9);
}
void metric(const QString& key, const QString& value) {
  std::printf("metric %s=%s\n", qPrintable(key), qPrintable(value));
}
}  // namespace

void GuiTests::printSessionMetrics() {
  // The same view size in both runs: the error is that of the same frame.
  w_.viewport()->setFixedSize(640, 400);
  QCoreApplication::processEvents();
  waitForFrames(6);  // cascades fit to last frame's depth range: settled after a few
  const auto error = w_.viewport()->measure()->computeErrorNow();
  const auto splitError = w_.viewport()->measure()->splitErrorPct();
  sl::ViewSide* r = w_.viewport()->mainSide();
  metric(QStringLiteral("scene"), auto_.sceneShown());
  metric(QStringLiteral("technique"), QString::fromStdString(w_.viewport()->techniqueId()));
  metric(QStringLiteral("split.technique"),
         QString::fromStdString(w_.viewport()->frames()->splitTechnique()));
  for (const sl::ParamSet* set : {&r->params(), &r->rendererParams()})
    for (const sl::ParamDecl& d : set->decls())
      metric(QStringLiteral("param.") + QString::fromStdString(d.key),
             QString::fromStdString(set->format(d.key)));
  for (const auto& [key, value] : w_.viewport()->frames()->splitParams())
    metric(QStringLiteral("split.param.") + QString::fromStdString(key),
           QString::fromStdString(value));
  const sl::Camera& c = w_.viewport()->camera()->camera();
  metric(QStringLiteral("camera.position"), vec(c.position));
  metric(QStringLiteral("camera.target"), vec(c.target));
  metric(QStringLiteral("camera.fov"), QString::number(c.fovYDeg, 'g', 9));
  const sl::Light& l = w_.viewport()->camera()->light();
  metric(QStringLiteral("light.type"),
         QString::fromStdString(std::string(sl::lightTypeName(l.type))));
  metric(QStringLiteral("light.angles"),
         QStringLiteral("%1 %2").arg(l.azimuthDeg, 0, 'g', 9).arg(l.elevationDeg, 0, 'g', 9));
  metric(QStringLiteral("light.position"), vec(l.positionM));
  QStringList docks;
  for (QDockWidget* dock : w_.findChildren<QDockWidget*>())
    if (dock->toggleViewAction()->isChecked()) docks << dock->objectName();
  docks.sort();
  metric(QStringLiteral("docks"), docks.join(QLatin1Char(',')));
  metric(QStringLiteral("error_pct"),
         error ? QString::number(*error, 'f', 4) : QStringLiteral("none"));
  metric(QStringLiteral("split.error_pct"),
         splitError ? QString::number(*splitError, 'f', 4) : QStringLiteral("none"));
  std::fflush(stdout);
  check(error && splitError, tr("both halves measured: %1 %, %2 %")
                                 .arg(error.value_or(-1), 0, 'f', 4)
                                 .arg(splitError.value_or(-1), 0, 'f', 4));
}

bool GuiTests::sessionSave(const QString& path) {
  if (path.isEmpty()) {
    check(false, tr("session-save needs a FILE"));
    return false;
  }
  check(auto_.openScene(QStringLiteral("corridor")), tr("scene corridor loaded"));
  if (auto e = auto_.setTechnique(QStringLiteral("cascades"))) check(false, *e);
  waitForFrames(1);
  sl::ViewSide* r = w_.viewport()->mainSide();
  for (const char* kv : {"partitions=3", "split=practical", "split.lambda=0.7",
                         "view.overlay=aliasing", "shading.ambient=0.3", "pcf=3"}) {
    const auto e = assignParameter(r->params(), r->rendererParams(), kv);
    check(!e, tr("set %1%2")
                  .arg(QLatin1String(kv),
                       e ? QStringLiteral(": ") + QString::fromStdString(*e) : QString()));
  }
  w_.paramPanel()->refreshValues();
  w_.teaching()->syncOverlayCombo();
  sl::Camera camera = w_.viewport()->camera()->camera();
  camera.position += glm::vec3(0.75f, 0.5f, -1.25f);
  camera.fovYDeg = 42.0f;
  w_.viewport()->camera()->setCamera(camera);
  w_.viewport()->camera()->setLight(sl::Light::directional(-35.0f, 38.5f));
  w_.syncLightControls();
  auto_.setSplit(QStringLiteral("uniform"), {{"resolution", "512"}});
  w_.timingDock()->hide();
  printSessionMetrics();

  // File > Save session…, the path typed into Qt's own file dialog as a user would.
  QFile::remove(path);
  bool sawDialog = false;
  QTimer driver;
  driver.setInterval(50);
  connect(&driver, &QTimer::timeout, this, [&sawDialog, &path] {
    if (auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget())) {
      sawDialog = true;
      if (auto* edit = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"))) {
        edit->setText(QFileInfo(path).absoluteFilePath());
        QKeyEvent enter(QEvent::KeyPress, Qt::Key_Return, Qt::NoModifier);
        QApplication::sendEvent(edit, &enter);
      }
    }
  });
  driver.start();
  w_.sessions()->saveAction()->trigger();  // returns once the dialog is closed
  driver.stop();
  check(sawDialog && QFileInfo(path).isFile(),
        tr("File > Save session… showed the file dialog and wrote %1").arg(path));
  const QString absolute = QFileInfo(path).absoluteFilePath();
  check(!auto_.recentSessions().isEmpty() && auto_.recentSessions().first() == absolute,
        tr("Recent sessions starts with it"));

  // Recent sessions: at most 8, and a deleted file is dropped with a message.
  const QString gone = path + QStringLiteral(".gone.json");
  for (int i = 0; i < SessionFiles::kMaxRecent + 2; ++i)
    auto_.saveSession(path + QStringLiteral(".%1.json").arg(i));
  check(auto_.recentSessions().size() == SessionFiles::kMaxRecent,
        tr("Recent sessions keeps %1 (%2)")
            .arg(SessionFiles::kMaxRecent)
            .arg(auto_.recentSessions().size()));
  auto_.saveSession(gone);
  auto_.saveSession(path);
  QFile::remove(gone);
  auto_.clearStatusMessage();
  const QStringList recent = auto_.recentSessions();
  check(!recent.contains(QFileInfo(gone).absoluteFilePath()) && recent.first() == absolute,
        tr("a deleted session is dropped from Recent sessions (%1 left)").arg(recent.size()));
  check(auto_.statusMessage().contains(QFileInfo(gone).fileName()),
        tr("with a message naming it: \"%1\"").arg(auto_.statusMessage()));
  for (int i = 0; i < SessionFiles::kMaxRecent + 2; ++i)
    QFile::remove(path + QStringLiteral(".%1.json").arg(i));

  // A malformed or hostile session: refused, named, and nothing of the state lost.
  const QString bad = path + QStringLiteral(".bad.json");
  const std::pair<const char*, const char*> cases[] = {
      {R"({"technique": "uniform", "params": {"resolution": 99999}})", "params.resolution"},
      {R"({"compare": {"technique": "uniform", "params": {"resolutoin": 512}}})",
       "compare.params.resolutoin"},
      {R"({"layout": {"state": "<script>"}})", "layout.state"},
      {R"({"scene": "corridor", "technique": )", "not valid JSON"},
      // Valid JSON whose scene is a broken glTF: refused before anything else is applied.
      {R"({"scene": "BROKEN", "technique": "uniform", "params": {"resolution": 512}})",
       "could not be loaded"}};
  const QString brokenScene = path + QStringLiteral(".broken.gltf");
  std::ofstream(brokenScene.toStdString(), std::ios::binary | std::ios::trunc)
      << R"({"asset": {"version": "2.0"}, "meshes": [{"primitives": [{"attributes": {"POSITION": 7}}]}]})";
  for (const auto& [text, what] : cases) {
    std::ofstream(bad.toStdString(), std::ios::binary | std::ios::trunc)
        << QString::fromUtf8(text).replace(QStringLiteral("BROKEN"), brokenScene).toStdString();
    badSessionOpen(bad);
    check(auto_.statusMessage().contains(QLatin1String(what)),
          tr("the message names the problem (%1): \"%2\"")
              .arg(QLatin1String(what), auto_.statusMessage()));
  }
  QFile::remove(bad);
  QFile::remove(brokenScene);
  return true;
}

void GuiTests::readAndCloseDialogs(QTimer& driver, QString& text) {
  driver.setInterval(50);
  connect(&driver, &QTimer::timeout, this, [&text] {
    if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
      text = box->text();
      box->accept();
    }
  });
  driver.start();
}

void GuiTests::badSessionOpen(const QString& path) {
  const ViewState before = viewState();
  QString messageText;
  QTimer driver;  // closes the error dialog as a user would, reading it first
  readAndCloseDialogs(driver, messageText);
  auto_.clearStatusMessage();
  const bool opened = auto_.openSession(path);
  driver.stop();
  check(!opened, tr("%1 is refused").arg(QFileInfo(path).fileName()));
  check(messageText.contains(QFileInfo(path).fileName()),
        tr("an error dialog names the file: \"%1\"").arg(messageText.left(160)));
  check(viewState() == before, tr("scene, technique, parameters and split view are unchanged"));
}

bool GuiTests::sessionCheck() {
  printSessionMetrics();
  return true;
}

}  // namespace sl::ui
