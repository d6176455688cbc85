// The main window (see MainWindow.h). Panels observe the renderer through the viewport;
// this class wires them together and owns none of the rendering.
#include "MainWindow.h"

#include "panels/light/LightPanel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QScreen>
#include <QSettings>
#include <QSlider>
#include <QStatusBar>
#include <QToolBar>
#include <QToolButton>
#include <QUrl>

#include <QJsonArray>
#include <QJsonDocument>

#include "CovariancePanel.h"
#include "ImportancePanel.h"
#include "LaunchOptions.h"
#include "LessonPanel.h"
#include "MessageText.h"
#include "MomentPanel.h"
#include "ParamPanel.h"
#include "ShadowMapPanel.h"
#include "ShortcutsDialog.h"
#include "TimingPanel.h"
#include "ViewportWidget.h"
#include "WarpPanel.h"
#include "scene/GltfLoader.h"

namespace sl::ui {

namespace {
const QString kOpenItem = QStringLiteral("\x01open");  ///< data of the "Open…" scene item
constexpr int kStatusMessageMs = 10000;
constexpr int kGrabTickMs = 30;
constexpr qint64 kGrabTimeoutMs = 120000;
constexpr int kSettingsVersion = 2;  ///< 2: the debug panels (older layouts are not restored)
constexpr QSize kDefaultWindowSize(1600, 1000);
constexpr int kDefaultParamDockWidth = 390;
constexpr int kDefaultLeftDockWidth = 440;
constexpr int kDefaultBottomDockHeight = 300;
const QString kOverlayKey = QStringLiteral("view.overlay");

bool isGltfFile(const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  return suffix == QLatin1String("gltf") || suffix == QLatin1String("glb");
}

QString gltfPathOf(const QMimeData* mime) {
  if (!mime || !mime->hasUrls()) return {};
  for (const QUrl& url : mime->urls())
    if (url.isLocalFile() && isGltfFile(url.toLocalFile())) return url.toLocalFile();
  return {};
}

void printErr(const QString& line) {
  std::fprintf(stderr, "shadowlab: %s\n", line.toLocal8Bit().constData());
  std::fflush(stderr);
}

/// "llvmpipe (LLVM 15.0.6, 256 bits)" out of Renderer::glDescription()'s
/// "RENDERER | VERSION".
QString shortGlName(const QString& description) {
  return description.section(QStringLiteral(" | "), 0, 0).trimmed();
}
}  // namespace

MainWindow::MainWindow(bool interactive, QWidget* parent)
    : QMainWindow(parent), interactive_(interactive), dialogs_(interactive) {
  setObjectName(QStringLiteral("mainWindow"));
  setWindowTitle(QStringLiteral("ShadowLab"));
  setAcceptDrops(true);
  setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
  setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
  setCorner(Qt::TopRightCorner, Qt::RightDockWidgetArea);
  setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
  setCorner(Qt::TopLeftCorner, Qt::LeftDockWidgetArea);

  viewport_ = new ViewportWidget(this);
  viewport_->setObjectName(QStringLiteral("viewport"));
  setCentralWidget(viewport_);
  connect(viewport_, &ViewportWidget::rendererReady, this, &MainWindow::onRendererReady);
  connect(viewport_, &ViewportWidget::rendererAboutToBeDestroyed, this,
          &MainWindow::onRendererAboutToBeDestroyed);
  connect(viewport_, &ViewportWidget::frameRendered, this, &MainWindow::onFrameRendered);
  connect(viewport_, &ViewportWidget::renderProblem, this, &MainWindow::onRenderProblem);
  connect(viewport_, &ViewportWidget::initializationFailed, this,
          &MainWindow::onInitializationFailed);
  connect(viewport_, &ViewportWidget::errorComputed, this, &MainWindow::onErrorComputed);
  connect(viewport_, &ViewportWidget::viewChanged, this, [this] {
    if (!viewport_->errorIsCurrent()) errorLabel_->setText(tr("error —"));
  });

  createActions();
  createToolBar();
  addToolBarBreak();
  createTeachingToolBar();
  createDocks();
  createStatusBar();
  applyDefaultLayout();
  if (interactive_) restoreSettings();

  grabTimer_.setInterval(kGrabTickMs);
  connect(&grabTimer_, &QTimer::timeout, this, &MainWindow::grabTick);
}

MainWindow::~MainWindow() {
  // Free the renderer (and let the panels drop their references) while this window is
  // still whole: the viewport's teardown signals arrive here.
  delete viewport_;
  viewport_ = nullptr;
}

// --- Construction ---------------------------------------------------------------------

void MainWindow::createActions() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QAction* open = file->addAction(tr("&Open glTF…"), this, &MainWindow::openSceneDialog);
  open->setShortcut(QKeySequence::Open);
  openAction_ = open;
  QAction* reload = file->addAction(tr("&Reload shaders"), this, [this] {
    if (auto error = viewport_->reloadShaders())
      report(tr("shader reload failed (the last good shaders stay in use): %1")
                 .arg(QString::fromStdString(*error)));
    else
      info(tr("Shaders reloaded."));
  });
  reload->setShortcut(Qt::Key_F5);
  QAction* screenshot =
      file->addAction(tr("Save &viewport image…"), this, &MainWindow::saveScreenshot);
  screenshot->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
  saveImageMenu_ = file->addMenu(tr("Save &panel image"));
  QAction* saveAll =
      file->addAction(tr("Save window and &all panels…"), this, &MainWindow::saveAllImages);
  saveAll->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_S));
  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  QAction* resetView = view->addAction(tr("&Reset view"), this, [this] { viewport_->resetView(); });
  resetView->setShortcut(Qt::Key_Home);
  QAction* error = view->addAction(tr("Compute &error now"), this, [this] {
    if (!viewport_->computeErrorNow()) showStatus(tr("No frame to measure yet."));
  });
  error->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
  continuousAction_ = view->addAction(tr("Render &continuously"));
  continuousAction_->setCheckable(true);
  continuousAction_->setShortcut(Qt::Key_F6);
  continuousAction_->setToolTip(
      tr("Redraw every frame (for techniques that converge over frames)"));
  connect(continuousAction_, &QAction::toggled, viewport_, &ViewportWidget::setContinuous);
  QAction* resetTemporal = view->addAction(tr("Reset &temporal state"), this, [this] {
    if (auto* r = viewport_->renderer()) r->resetTemporalState();
    viewport_->update();
  });
  resetTemporal->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_T));
  view->addSeparator();
  QAction* cycleOverlay = view->addAction(tr("Next &overlay (none, error, aliasing, warp grid)"),
                                          this, &MainWindow::cycleOverlay);
  cycleOverlay->setShortcut(Qt::Key_O);
  QAction* split =
      view->addAction(tr("&Split view (compare two techniques)"), this, &MainWindow::toggleSplit);
  split->setShortcut(Qt::Key_F7);
  view->addSeparator();
  QMenu* panels = view->addMenu(tr("&Panels"));
  panels->setObjectName(QStringLiteral("panelsMenu"));
  QAction* defaultLayout =
      view->addAction(tr("&Default layout"), this, [this] { applyDefaultLayout(); });

  QMenu* frame = menuBar()->addMenu(tr("F&rame"));
  pauseAction_ = frame->addAction(tr("&Pause"));
  pauseAction_->setCheckable(true);
  pauseAction_->setShortcut(Qt::Key_Space);
  pauseAction_->setShortcutContext(Qt::WindowShortcut);
  pauseAction_->setToolTip(tr("Freeze the frame: the panels keep showing its passes (Space)"));
  connect(pauseAction_, &QAction::toggled, this, &MainWindow::setPaused);
  QAction* step = frame->addAction(tr("&Step one frame"), this, &MainWindow::stepFrame);
  step->setShortcut(Qt::Key_Period);
  step->setToolTip(tr("Render exactly one frame and pause (.)"));
  frame->addSeparator();
  QAction* passNext =
      frame->addAction(tr("Step through the &passes: next"), this, [this] { stepPass(+1); });
  passNext->setShortcut(Qt::Key_BracketRight);
  passNext->setToolTip(
      tr("IM → collapse → blur → scan → warped map → lookup, one pass at a "
         "time, highlighting the panel that shows its output (])"));
  QAction* passPrev =
      frame->addAction(tr("Step through the passes: p&revious"), this, [this] { stepPass(-1); });
  passPrev->setShortcut(Qt::Key_BracketLeft);
  passStopAction_ =
      frame->addAction(tr("Stop stepping through the passes"), this, &MainWindow::stopPassStepping);
  passStopAction_->setShortcut(Qt::Key_Escape);
  passStopAction_->setShortcutContext(Qt::WindowShortcut);
  passStopAction_->setEnabled(false);

  QMenu* lessons = menuBar()->addMenu(tr("&Lessons"));
  createLessonsMenu(lessons);

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  QAction* shortcuts = help->addAction(tr("&Keyboard and mouse"), this, &MainWindow::showShortcuts);
  shortcuts->setShortcut(QKeySequence::HelpContents);
  help->addAction(tr("&About ShadowLab"), this, [this] {
    QMessageBox::about(this, tr("About ShadowLab"),
                       tr("<b>ShadowLab %1</b><p>An interactive visual debugger and teaching tool "
                          "for adaptive shadow maps.</p>")
                           .arg(QCoreApplication::applicationVersion()));
  });

  commandActions_ = {open,      reload,        screenshot,        saveAll,       quit,
                     resetView, error,         continuousAction_, resetTemporal, cycleOverlay,
                     split,     defaultLayout, shortcuts};
  // Shortcuts work wherever the focus is (also while the viewport has it).
  for (QAction* a : commandActions_) a->setShortcutContext(Qt::ApplicationShortcut);
  // Frame stepping keys: plain keys, so only while the main window has the focus (typing
  // in a field still works: editors take printable keys before shortcuts).
  for (QAction* a : {step, passNext, passPrev}) a->setShortcutContext(Qt::WindowShortcut);
  commandActions_ << pauseAction_ << step << passNext << passPrev << passStopAction_;
  for (QAction* a : lessons->actions())
    if (!a->shortcut().isEmpty()) commandActions_ << a;
}

QToolBar* MainWindow::addFixedToolBar(const QString& title, const QString& objectName) {
  QToolBar* bar = addToolBar(title);
  bar->setObjectName(objectName);
  bar->setMovable(false);
  bar->setFloatable(false);
  return bar;
}

void MainWindow::addToolBarLabel(QToolBar* bar, const QString& text) {
  auto* label = new QLabel(text);
  label->setContentsMargins(8, 0, 4, 0);
  bar->addWidget(label);
}

void MainWindow::createToolBar() {
  QToolBar* bar = addFixedToolBar(tr("Main"), QStringLiteral("mainToolBar"));
  auto addLabel = [bar](const QString& text) { addToolBarLabel(bar, text); };

  addLabel(tr("Scene"));
  sceneCombo_ = new QComboBox;
  sceneCombo_->setObjectName(QStringLiteral("sceneCombo"));
  sceneCombo_->setMinimumContentsLength(14);
  sceneCombo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  sceneCombo_->setToolTip(tr("Built-in scenes, or open a .gltf/.glb file"));
  for (const std::string& name : sl::builtinSceneNames())
    sceneCombo_->addItem(QString::fromStdString(name), QString::fromStdString(name));
  sceneCombo_->insertSeparator(sceneCombo_->count());
  sceneCombo_->addItem(tr("Open…"), kOpenItem);
  connect(sceneCombo_, &QComboBox::activated, this, &MainWindow::onSceneComboActivated);
  bar->addWidget(sceneCombo_);

  addLabel(tr("Technique"));
  techniqueCombo_ = new QComboBox;
  techniqueCombo_->setObjectName(QStringLiteral("techniqueCombo"));
  techniqueCombo_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  for (const sl::TechniqueInfo& t : sl::Renderer::techniques()) {
    techniqueCombo_->addItem(QString::fromStdString(t.name), QString::fromStdString(t.id));
    techniqueCombo_->setItemData(
        techniqueCombo_->count() - 1,
        QStringLiteral("<b>%1</b> <code>%2</code><br>%3")
            .arg(QString::fromStdString(t.name).toHtmlEscaped(), QString::fromStdString(t.id),
                 QString::fromStdString(t.description).toHtmlEscaped()),
        Qt::ToolTipRole);
  }
  connect(techniqueCombo_, &QComboBox::activated, this, &MainWindow::onTechniqueComboActivated);
  bar->addWidget(techniqueCombo_);
  bar->addSeparator();

  addLabel(tr("View"));
  bookmarkCombo_ = new QComboBox;
  bookmarkCombo_->setObjectName(QStringLiteral("bookmarkCombo"));
  bookmarkCombo_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  bookmarkCombo_->setToolTip(tr("Camera bookmarks of the scene"));
  connect(bookmarkCombo_, &QComboBox::activated, this,
          [this](int index) { viewport_->goToBookmark(bookmarkCombo_->itemData(index).toInt()); });
  bar->addWidget(bookmarkCombo_);
  auto* reset = new QToolButton;
  reset->setText(tr("Reset view"));
  reset->setToolTip(tr("Back to the scene's first camera (Home)"));
  connect(reset, &QToolButton::clicked, this, [this] { viewport_->resetView(); });
  bar->addWidget(reset);
  syncLightControls();
}

void MainWindow::createDocks() {
  QMenu* panels = menuBar()->findChild<QMenu*>(QStringLiteral("panelsMenu"));

  paramPanel_ = new ParamPanel;
  connect(paramPanel_, &ParamPanel::paramChanged, this, [this](const QString& key) {
    if (key.isEmpty() || key == kOverlayKey) syncOverlayCombo();
    if (viewport_->paused()) viewport_->stepFrame();  // show the change even when paused
    viewport_->update();
  });
  connect(paramPanel_, &ParamPanel::editRefused, this,
          [this](const QString& message) { report(message); });
  paramDock_ = new QDockWidget(tr("Parameters"), this);
  paramDock_->setObjectName(QStringLiteral("parameters"));
  paramDock_->setWidget(paramPanel_);
  paramDock_->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
  addDockWidget(Qt::RightDockWidgetArea, paramDock_);

  timingPanel_ = new TimingPanel;
  timingDock_ = new QDockWidget(tr("Timing"), this);
  timingDock_->setObjectName(QStringLiteral("timing"));
  timingDock_->setWidget(timingPanel_);
  addDockWidget(Qt::BottomDockWidgetArea, timingDock_);

  for (QDockWidget* dock : {paramDock_, timingDock_}) {
    QAction* toggle = dock->toggleViewAction();
    panels->addAction(toggle);
  }
  paramDock_->toggleViewAction()->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_1));
  timingDock_->toggleViewAction()->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_2));
  commandActions_ << paramDock_->toggleViewAction() << timingDock_->toggleViewAction();
  createPanelDocks();
}

void MainWindow::createStatusBar() {
  QStatusBar* bar = statusBar();
  auto permanent = [bar](const QString& name, const QString& tip) {
    auto* label = new QLabel;
    label->setObjectName(name);
    label->setToolTip(tip);
    label->setContentsMargins(8, 0, 8, 0);
    bar->addPermanentWidget(label);
    return label;
  };
  sceneLabel_ = permanent(QStringLiteral("sceneStatus"), tr("Scene shown"));
  frameLabel_ = permanent(QStringLiteral("frameStatus"),
                          tr("Time of the last frame, and how it was measured"));
  errorLabel_ =
      permanent(QStringLiteral("errorStatus"),
                tr("Shadow error of the current view against the exact ray-traced reference "
                   "(percent of covered pixels; computed once the view is still, or Ctrl+E)"));
  glLabel_ = permanent(QStringLiteral("glStatus"), tr("OpenGL renderer"));
  frameLabel_->setMinimumWidth(frameLabel_->fontMetrics().horizontalAdvance(
                                   QStringLiteral("frame 999.9 ms (glFinish+wallclock)")) +
                               16);
  frameLabel_->setText(tr("frame —"));
  errorLabel_->setText(tr("error —"));
  glLabel_->setText(tr("GL —"));
  statusBar()->showMessage(tr("Starting the renderer…"));
  connect(statusBar(), &QStatusBar::messageChanged, this, [this](const QString& shown) {
    if (shown.isEmpty()) statusBar()->setToolTip(QString());
  });
}

void MainWindow::applyDefaultLayout() {
  const QScreen* screen = this->screen() ? this->screen() : QGuiApplication::primaryScreen();
  QSize size = kDefaultWindowSize;
  if (screen) size = size.boundedTo(screen->availableGeometry().size());
  // Right: Parameters | Lesson | Charts. Left: Importance map over Covariance. Bottom: Warp
  // functions | Shadow map | Moment mip chain | Timing.
  for (QDockWidget* dock : findChildren<QDockWidget*>()) {
    dock->setFloating(false);
    dock->show();
  }
  addDockWidget(Qt::RightDockWidgetArea, paramDock_);
  addDockWidget(Qt::RightDockWidgetArea, lessonDock_);
  tabifyDockWidget(paramDock_, lessonDock_);
  addDockWidget(Qt::RightDockWidgetArea, chartsDock_);
  tabifyDockWidget(lessonDock_, chartsDock_);
  addDockWidget(Qt::LeftDockWidgetArea, importanceDock_);
  addDockWidget(Qt::LeftDockWidgetArea, covarianceDock_);
  splitDockWidget(importanceDock_, covarianceDock_, Qt::Vertical);
  addDockWidget(Qt::BottomDockWidgetArea, warpDock_);
  for (QDockWidget* dock : {shadowMapDock_, momentDock_, timingDock_}) {
    addDockWidget(Qt::BottomDockWidgetArea, dock);
    tabifyDockWidget(warpDock_, dock);
  }
  paramDock_->raise();
  warpDock_->raise();
  // Last: while the docks moved, a stale minimum may have widened the window; settle the
  // layout first, or the pending activation would undo the resize.
  layout()->invalidate();
  layout()->activate();
  resize(size);
  resizeDocks({paramDock_, importanceDock_}, {kDefaultParamDockWidth, kDefaultLeftDockWidth},
              Qt::Horizontal);
  resizeDocks({warpDock_}, {kDefaultBottomDockHeight}, Qt::Vertical);
}

void MainWindow::restoreSettings() {
  QSettings settings;
  if (settings.value(QStringLiteral("window/version")).toInt() != kSettingsVersion) return;
  restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
  restoreState(settings.value(QStringLiteral("window/state")).toByteArray(), kSettingsVersion);
}

void MainWindow::saveSettings() {
  if (!interactive_) return;
  QSettings settings;
  settings.setValue(QStringLiteral("window/version"), kSettingsVersion);
  settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
  settings.setValue(QStringLiteral("window/state"), saveState(kSettingsVersion));
  if (!sceneSpec_.isEmpty()) settings.setValue(QStringLiteral("scene/last"), sceneSpec_);
  if (!viewport_->techniqueId().empty())
    settings.setValue(QStringLiteral("technique/last"),
                      QString::fromStdString(viewport_->techniqueId()));
}

QString MainWindow::initialSceneName() const {
  if (interactive_) {
    const QString last = QSettings().value(QStringLiteral("scene/last")).toString();
    if (!last.isEmpty()) return last;
  }
  return defaultSceneName();
}

QString MainWindow::defaultSceneName() {
  const auto names = sl::builtinSceneNames();
  if (names.empty() || std::find(names.begin(), names.end(), "default") != names.end())
    return QStringLiteral("default");
  return QString::fromStdString(names.front());
}

QString MainWindow::lastTechnique() const {
  return interactive_ ? QSettings().value(QStringLiteral("technique/last")).toString() : QString();
}

void MainWindow::closeEvent(QCloseEvent* event) {
  saveSettings();
  if (shortcuts_) shortcuts_->close();
  QMainWindow::closeEvent(event);
}

// --- Scenes -------------------------------------------------------------------------------

bool MainWindow::loadScene(const QString& nameOrPath) {
  QApplication::setOverrideCursor(Qt::WaitCursor);
  sl::SceneLoadResult result = sl::loadSceneByNameOrPath(nameOrPath.toStdString());
  QApplication::restoreOverrideCursor();
  if (!result) {
    report(tr("cannot load scene '%1': %2").arg(nameOrPath, QString::fromStdString(result.error)),
           tr("Cannot open scene"));
    syncSceneCombo();  // back to the scene still shown
    return false;
  }
  for (const std::string& warning : result.scene->warnings)
    printErr(tr("scene '%1': %2").arg(nameOrPath, QString::fromStdString(warning)));
  sceneSpec_ = nameOrPath;
  viewport_->setScene(result.scene);
  timingPanel_->resetHistory();
  for (auto& [dock, panel] : publicationDocks_) panel->resetHistory();
  const sl::Scene& scene = *viewport_->scene();
  sceneLabel_->setText(
      tr("%1 · %2 triangles")
          .arg(shownMessage(QString::fromStdString(scene.name)))
          .arg(QLocale::c().toString(static_cast<qulonglong>(scene.triangleCount()))));
  sceneLabel_->setToolTip(shownMessage(QString::fromStdString(scene.sourcePath)));
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
  if (data == kOpenItem) {
    syncSceneCombo();
    openSceneDialog();
  } else if (!data.isEmpty() && data != sceneSpec_) {
    loadScene(data);
  }
}

void MainWindow::openSceneDialog() {
  // Self-tests drive Qt's own dialog (and never touch the user's settings).
  const bool test = !selfTest_.isEmpty();
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
  if (!gltfPathOf(event->mimeData()).isEmpty()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  const QString path = gltfPathOf(event->mimeData());
  if (path.isEmpty()) return;
  event->acceptProposedAction();
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

// --- Technique and parameters -----------------------------------------------------------

void MainWindow::setTechnique(const QString& id) {
  if (auto error = viewport_->setTechnique(id.toStdString())) {
    report(QString::fromStdString(*error));
  } else {
    timingPanel_->resetHistory();
    for (auto& [dock, panel] : publicationDocks_) panel->resetHistory();
    if (rendererBound_) rebuildParamPanel();
    if (passIndex_ >= 0) stopPassStepping();
  }
  syncTechniqueCombo();
  updateTitle();
}

void MainWindow::onTechniqueComboActivated(int index) {
  const QString id = techniqueCombo_->itemData(index).toString();
  if (id.toStdString() != viewport_->techniqueId()) setTechnique(id);
}

void MainWindow::syncTechniqueCombo() {
  const int index = techniqueCombo_->findData(QString::fromStdString(viewport_->techniqueId()));
  if (index >= 0) techniqueCombo_->setCurrentIndex(index);
}

void MainWindow::setPendingAssignments(const QStringList& assignments) {
  pendingAssignments_ = assignments;
}

void MainWindow::rebuildParamPanel() {
  sl::Renderer* renderer = viewport_->renderer();
  if (!renderer) return paramPanel_->clear();
  const sl::TechniqueInfo* info = sl::Renderer::findTechnique(renderer->techniqueId());
  std::vector<ParamPanel::Section> sections;
  sections.push_back(
      {info ? QString::fromStdString(info->name) : QString::fromStdString(renderer->techniqueId()),
       info ? QString::fromStdString(info->description) : QString(), &renderer->params()});
  sections.push_back({tr("View and shading"), QString(), &renderer->rendererParams()});
  paramPanel_->setSections(std::move(sections));
}

// --- Renderer events ----------------------------------------------------------------------

void MainWindow::onRendererReady() {
  sl::Renderer* renderer = viewport_->renderer();
  if (!renderer) return;
  for (const QString& kv : pendingAssignments_)
    if (auto error =
            assignParameter(renderer->params(), renderer->rendererParams(), kv.toStdString()))
      report(QString::fromStdString(*error));
  pendingAssignments_.clear();
  rendererBound_ = true;
  grabFramesRendered_ = 0;
  rebuildParamPanel();
  syncTechniqueCombo();
  syncOverlayCombo();
  updatePublishing();
  if (!lastSplitTechnique_.isEmpty() && splitCombo_->currentIndex() > 0)
    setSplitTechnique(lastSplitTechnique_);
  updateTitle();
  const QString gl = QString::fromStdString(renderer->glDescription());
  glLabel_->setText(shortGlName(gl));
  glLabel_->setToolTip(gl);
  info(tr("Renderer ready: %1").arg(shortGlName(gl)));
  viewport_->update();
}

void MainWindow::onRendererAboutToBeDestroyed() {
  rendererBound_ = false;
  paramPanel_->clear();
  if (overlayCombo_) overlayCombo_->setEnabled(false);
}

void MainWindow::onFrameRendered() {
  const sl::Renderer* renderer = viewport_->renderer();
  if (!renderer) return;
  const sl::FrameStats& stats = renderer->stats();
  frameLabel_->setText(tr("frame %1 ms (%2)")
                           .arg(stats.totalMs, 0, 'f', stats.totalMs < 10 ? 2 : 1)
                           .arg(stats.timingMethod.empty()
                                    ? tr("untimed")
                                    : QString::fromStdString(stats.timingMethod)));
  timingPanel_->showStats(stats);
  if (rendererBound_) ++grabFramesRendered_;
  if (publicationIsCurrent()) {
    feedPanels(false);
    if (passWaitingForFrame_) {
      passWaitingForFrame_ = false;
      passIndex_ = 0;
      showPass();
    }
  }
}

void MainWindow::onRenderProblem(const QString& message) {
  if (grabTimer_.isActive()) grabProblems_ << message;
  report(message);
}

void MainWindow::onInitializationFailed(const QString& message) {
  if (failed_) return;
  failed_ = true;
  grabTimer_.stop();
  report(message, tr("OpenGL problem"));
  QCoreApplication::exit(1);
}

void MainWindow::onErrorComputed(double errorPct) {
  errorLabel_->setText(tr("error %1 %").arg(errorPct, 0, 'f', errorPct < 1 ? 3 : 2));
}

// --- Light, camera, misc -------------------------------------------------------------------

void MainWindow::syncLightControls() {
  if (lightPanel_) lightPanel_->showLight(viewport_->light());
}

void MainWindow::updateTitle() {
  QString title = QStringLiteral("ShadowLab");
  if (const auto& scene = viewport_->scene())
    title += QStringLiteral(" — ") + shownMessage(QString::fromStdString(scene->name));
  if (const sl::TechniqueInfo* t = sl::Renderer::findTechnique(viewport_->techniqueId()))
    title += QStringLiteral(" — ") + QString::fromStdString(t->name);
  setWindowTitle(title);
}

void MainWindow::showShortcuts() {
  if (!shortcuts_) shortcuts_ = new ShortcutsDialog(commandActions_, this);
  shortcuts_->show();
  shortcuts_->raise();
  shortcuts_->activateWindow();
}

void MainWindow::saveScreenshot() {
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Save viewport image"), QDir::home().filePath(QStringLiteral("shadowlab.png")),
      tr("PNG images (*.png)"));
  if (path.isEmpty()) return;
  if (viewport_->grabView().save(path))
    showStatus(tr("Saved %1").arg(path));
  else
    report(tr("cannot write %1").arg(path), tr("Save viewport image"));
}

void MainWindow::info(const QString& message) {
  if (lastProblemClock_.isValid() && lastProblemClock_.elapsed() < kStatusMessageMs) return;
  showStatus(message);
}

void MainWindow::showStatus(const QString& message, int timeoutMs) {
  statusBar()->showMessage(shownMessage(message), timeoutMs);
  statusBar()->setToolTip(messageDetails(message));  // cleared with the message (createStatusBar)
}

void MainWindow::report(const QString& message, const QString& dialogTitle) {
  printErr(message);
  showStatus(message);
  lastProblemClock_.start();
  if (!dialogs_ || dialogTitle.isEmpty()) return;
  QMessageBox box(QMessageBox::Warning, dialogTitle, shownMessage(message), QMessageBox::Ok, this);
  box.setTextFormat(Qt::PlainText);  // a file's text is never markup
  if (box.text() != message) {
    const QString details = messageDetails(message);
    box.setDetailedText(
        details.isEmpty()
            ? tr("The message is %1 characters long; the whole of it is on the standard error "
                 "output.")
                  .arg(message.size())
            : details);
  }
  box.exec();
}

// --- --grab ------------------------------------------------------------------------------

void MainWindow::startGrab(const QString& dir, int frames) {
  grabDir_ = dir;
  grabFrames_ = frames;
  grabProblems_.clear();
  grabClock_.start();
  grabTimer_.start();
}

void MainWindow::grabTick() {
  if (failed_) return grabTimer_.stop();
  if (!rendererBound_) {
    if (grabClock_.elapsed() > kGrabTimeoutMs) {
      grabTimer_.stop();
      report(tr("--grab: the renderer did not start within %1 s (no OpenGL context?)")
                 .arg(kGrabTimeoutMs / 1000));
      QCoreApplication::exit(1);
    }
    return;
  }
  if (grabFramesRendered_ < grabFrames_) {
    viewport_->update();
    return;
  }
  grabTimer_.stop();
  finishGrab();
}

void MainWindow::finishGrab() {
  // The status line shows the error of the grabbed view. Then freeze the frame, so that
  // the window, the viewport, every panel and published.json show the same frame.
  viewport_->computeErrorNow();
  waitForFrames(1);  // the error overlay, when on, needs a frame drawn with the reference
  viewport_->setPaused(true, false);
  QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
  feedPanels(true);

  QStringList failures;
  if (!QDir().mkpath(grabDir_)) failures << tr("cannot create directory %1").arg(grabDir_);
  if (failures.isEmpty()) failures << writeImages(grabDir_, true);
  if (failures.isEmpty()) {
    const QString path = QDir(grabDir_).absoluteFilePath(QStringLiteral("published.json"));
    QFile file(path);
    if (file.open(QIODevice::WriteOnly | QIODevice::Truncate) &&
        file.write(QJsonDocument(publicationJson()).toJson()) > 0) {
      std::printf("%s\n", path.toLocal8Bit().constData());
    } else {
      failures << tr("cannot write %1").arg(path);
    }
  }
  std::fflush(stdout);
  for (const QString& problem : grabProblems_) failures << tr("while rendering: %1").arg(problem);
  for (const QString& f : failures) printErr(f);
  QCoreApplication::exit(failures.isEmpty() ? 0 : 1);
}

}  // namespace sl::ui
