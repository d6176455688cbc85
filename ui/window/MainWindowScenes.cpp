// MainWindow's scenes (MainWindow.h): loading one by name or path (off the UI thread, the
// window live meanwhile), the Scene box and its "Open…" item, dropped files, the camera
// bookmarks of the scene shown.
#include <cstdio>

#include <QApplication>
#include <QComboBox>
#include <QDragEnterEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QMimeData>
#include <QSettings>
#include <QUrl>

#include "panels/common/TimingPanel.h"
#include "scene/GltfLoader.h"
#include "service/OffThread.h"
#include "view/ViewportWidget.h"
#include "window/MainWindow.h"
#include "window/SessionFiles.h"
#include "window/StatusLine.h"
#include "window/MessageText.h"

namespace sl::ui {

namespace {

bool isGltfFile(const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  return suffix == QLatin1String("gltf") || suffix == QLatin1String("glb");
}

bool isSessionFile(const QString& path) {
  return QFileInfo(path).suffix().toLower() == QLatin1String("json");
}

/// The first local file of a drag that is a glTF scene or (a .json) a session.
QString droppedPathOf(const QMimeData* mime) {
  if (!mime || !mime->hasUrls()) return {};
  for (const QUrl& url : mime->urls())
    if (url.isLocalFile() && (isGltfFile(url.toLocalFile()) || isSessionFile(url.toLocalFile())))
      return url.toLocalFile();
  return {};
}

}  // namespace

bool MainWindow::loadScene(const QString& nameOrPath) {
  if (sceneLoading_) {
    info(tr("Still loading a scene: try again when it is shown."));
    return false;
  }
  // A large file (its parse and BVH take seconds) loads off the UI thread: the window stays
  // live and keeps the scene shown until the new one is in.
  info(tr("Loading %1\u2026").arg(nameOrPath));
  QApplication::setOverrideCursor(Qt::WaitCursor);
  sceneLoading_ = true;
  viewport_->frames()->setSceneLoading(true);
  sl::SceneLoadResult result;
  runOffThread([&] { result = sl::loadSceneByNameOrPath(nameOrPath.toStdString()); });
  sceneLoading_ = false;
  QApplication::restoreOverrideCursor();
  if (!result) {
    viewport_->frames()->setSceneLoading(false);
    report(tr("cannot load scene '%1': %2").arg(nameOrPath, QString::fromStdString(result.error)),
           tr("Cannot open scene"));
    syncSceneCombo();  // back to the scene still shown
    return false;
  }
  for (const std::string& warning : result.scene->warnings)
    printErr(tr("scene '%1': %2").arg(nameOrPath, QString::fromStdString(warning)));
  sceneSpec_ = nameOrPath;
  viewport_->setScene(result.scene);
  viewport_->frames()->setSceneLoading(false);  // the next frame is of the new scene
  timingPanel_->resetHistory();
  docks_.resetHistory();
  const sl::Scene& scene = *viewport_->scene();
  status_->showScene(scene);
  if (!result.scene->warnings.empty())
    info(tr("Scene loaded with %1 warning(s) (see stderr): %2")
             .arg(result.scene->warnings.size())
             .arg(QString::fromStdString(result.scene->warnings.front())));
  else
    info(tr("Loaded %1").arg(QString::fromStdString(scene.sourcePath)));
  syncSceneCombo();
  refreshBookmarks();
  syncLightControls();
  updateTitle();
  return true;
}

void MainWindow::syncSceneCombo() {
  if (sceneSpec_.isEmpty()) return;
  int index = sceneCombo_->findData(sceneSpec_);
  if (index < 0) {  // a file: list it above the separator
    const int separator = sceneCombo_->count() - 2;
    sceneCombo_->insertItem(separator, QFileInfo(sceneSpec_).fileName(), sceneSpec_);
    sceneCombo_->setItemData(separator, sceneSpec_, Qt::ToolTipRole);
    index = separator;
  }
  sceneCombo_->setCurrentIndex(index);
}

void MainWindow::onSceneComboActivated(int index) {
  const QString data = sceneCombo_->itemData(index).toString();
  if (data == openItemData()) {
    syncSceneCombo();
    openSceneDialog();
  } else if (!data.isEmpty() && data != sceneSpec_) {
    loadScene(data);
  }
}

void MainWindow::openSceneDialog() {
  // A script drives Qt's own dialog (and never touches the user's settings).
  const bool test = scripted_;
  const QString dir =
      interactive_ ? QSettings().value(QStringLiteral("scene/openDir"), QDir::homePath()).toString()
                   : QDir::currentPath();
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Open glTF scene"), dir, tr("glTF scenes (*.gltf *.glb);;All files (*)"), nullptr,
      test ? QFileDialog::DontUseNativeDialog : QFileDialog::Options());
  if (path.isEmpty()) return;
  if (interactive_)
    QSettings().setValue(QStringLiteral("scene/openDir"), QFileInfo(path).absolutePath());
  loadScene(path);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  if (!droppedPathOf(event->mimeData()).isEmpty()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  // A glTF loads as the scene; a .json opens as a session (File > Open session…).
  const QString path = droppedPathOf(event->mimeData());
  if (path.isEmpty()) return;
  event->acceptProposedAction();
  if (isSessionFile(path))
    sessions_->open(path);
  else
    loadScene(path);
}

void MainWindow::refreshBookmarks() {
  bookmarkCombo_->clear();
  const auto& scene = viewport_->scene();
  if (scene) {
    for (std::size_t i = 0; i < scene->cameras.size(); ++i) {
      const std::string& name = scene->cameras[i].name;
      bookmarkCombo_->addItem(
          name.empty() ? tr("Camera %1").arg(i + 1) : shownMessage(QString::fromStdString(name)),
          static_cast<int>(i));
    }
  }
  bookmarkCombo_->addItem(tr("Overview"), -1);
  bookmarkCombo_->setCurrentIndex(0);
}

}  // namespace sl::ui
