// The main window (see MainWindow.h): scenes, techniques, renderer events, the light, the
// status line, publication requests, pause. Its construction is in MainWindowSetup.cpp;
// panels observe the renderer through the viewport and the window owns none of the rendering.
#include "window/MainWindow.h"

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
#include <QStatusBar>
#include <QToolBar>
#include <QToolButton>
#include <QUrl>

#include "launch/GrabRun.h"
#include "launch/LaunchOptions.h"
#include "service/OffThread.h"
#include "teaching/LessonController.h"
#include "window/MessageText.h"
#include "teaching/PassStepper.h"
#include "teaching/PresenterMode.h"
#include "window/SplitSideParams.h"
#include "window/SessionFiles.h"
#include "window/ShortcutsDialog.h"
#include "window/StatusLine.h"
#include "window/WindowImages.h"
#include "teaching/TeachingBar.h"
#include "view/ViewportWidget.h"
#include "panels/common/ChartsPanel.h"
#include "panels/common/LessonPanel.h"
#include "panels/common/ParamPanel.h"
#include "panels/rtw/RtwSettle.h"
#include "core/LiveText.h"
#include "panels/common/TimingPanel.h"
#include "panels/light/LightPanel.h"
#include "scene/GltfLoader.h"

namespace sl::ui {

namespace {
constexpr int kStatusMessageMs = 10000;
/// 2: the debug panels; 3: each technique's panels side by side (older layouts are not
/// restored).
constexpr int kSettingsVersion = 3;

}  // namespace

MainWindow::MainWindow(bool interactive, QWidget* parent)
    : QMainWindow(parent), interactive_(interactive), dialogs_(interactive) {
  setObjectName(QStringLiteral("mainWindow"));
  setWindowTitle(QStringLiteral("ShadowLab"));
  setAcceptDrops(true);
  setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
  // The bottom panels reach under the right column: a technique's panels side by side.
  setCorner(Qt::BottomRightCorner, Qt::BottomDockWidgetArea);
  setCorner(Qt::TopRightCorner, Qt::RightDockWidgetArea);
  setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
  setCorner(Qt::TopLeftCorner, Qt::LeftDockWidgetArea);

  viewport_ = new ViewportWidget(this);
  viewport_->setObjectName(QStringLiteral("viewport"));
  // Scripted runs (grabs, ui/Automation.h) measure full-size frames: no adaptive resolution.
  viewport_->frames()->setAdaptiveAllowed(interactive_);
  setCentralWidget(viewport_);
  connect(viewport_, &ViewportWidget::rendererReady, this, &MainWindow::onRendererReady);
  connect(viewport_, &ViewportWidget::rendererAboutToBeDestroyed, this,
          &MainWindow::onRendererAboutToBeDestroyed);
  connect(viewport_->frames(), &FrameLoop::frameRendered, this, &MainWindow::onFrameRendered);
  connect(viewport_, &ViewportWidget::renderProblem, this, &MainWindow::onRenderProblem);
  // A lesson's texts quote the error (the status line shows it: StatusLine).
  connect(viewport_->measure(), &MeasureService::errorUnmeasured, this,
          &MainWindow::refreshLiveTexts);
  connect(viewport_, &ViewportWidget::initializationFailed, this,
          &MainWindow::onInitializationFailed);
  connect(viewport_->measure(), &MeasureService::errorComputed, this,
          &MainWindow::refreshLiveTexts);
  connect(viewport_->measure(), &MeasureService::pixelProbed, this,
          [this](const std::optional<sl::PixelProbe>& probe) { docks_.showProbe(probe); });

  lessons_ = std::make_unique<LessonController>(*this);
  passes_ = std::make_unique<PassStepper>(*this);
  teaching_ = std::make_unique<TeachingBar>(*this);
  grab_ = std::make_unique<GrabRun>(*this);
  sessions_ = std::make_unique<SessionFiles>(*this);
  images_ = new WindowImages(*this, *grab_);
  presenter_ = new PresenterMode(*this);
  // A panel grows with its first data: in presenter mode the window is kept on its screen.
  docks_.setOnFed([this] { presenter_->keepOnScreen(); });
  splitSide_ = new SplitSideParams(*this);
  connect(viewport_->frames(), &FrameLoop::splitChanged, splitSide_, &SplitSideParams::rebuild);
  createActions();
  createToolBar();
  addToolBarBreak();
  teaching_->create();
  createDocks();
  createStatusBar();
  applyDefaultLayout();
  if (interactive_) restoreSettings();
}

MainWindow::~MainWindow() {
  // Free the renderer (and let the panels drop their references) while this window is
  // still whole: the viewport's teardown signals arrive here.
  delete viewport_;
  viewport_ = nullptr;
  // The parts hold a reference to this window: free them while it is still whole.
  grab_.reset();
  teaching_.reset();
  passes_.reset();
  lessons_.reset();
}

void MainWindow::startGrab(const QString& dir, int frames) {
  grab_->start(dir, frames);
}

bool MainWindow::startLesson(const QString& lesson, int caseIndex) {
  return lessons_->start(lesson, caseIndex);
}

void MainWindow::setScripted(bool scripted) {
  scripted_ = scripted;
  dialogs_ = interactive_ || scripted;
}

void MainWindow::setPresenterMode(bool on) {
  presenter_->setActive(on);
}

void MainWindow::restoreSettings() {
  QSettings settings;
  if (settings.value(QStringLiteral("window/version")).toInt() != kSettingsVersion) return;
  restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
  restoreState(settings.value(QStringLiteral("window/state")).toByteArray(), kSettingsVersion);
  for (const QString& id : settings.value(QStringLiteral("window/openedByHand")).toStringList())
    docks_.setOpenedByHand(id, true);
}

void MainWindow::saveSettings() {
  if (!interactive_) return;
  QSettings settings;
  settings.setValue(QStringLiteral("window/version"), kSettingsVersion);
  settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
  settings.setValue(QStringLiteral("window/state"), saveState(kSettingsVersion));
  QStringList byHand;
  for (const QString& id : docks_.openedByHand()) byHand << id;
  settings.setValue(QStringLiteral("window/openedByHand"), byHand);
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

// --- Technique and parameters -----------------------------------------------------------

void MainWindow::setTechnique(const QString& id) {
  if (auto error = viewport_->setTechnique(id.toStdString())) {
    report(QString::fromStdString(*error));
  } else {
    timingPanel_->resetHistory();
    docks_.resetHistory();
    if (rendererBound_) rebuildParamPanel();
    passes_->stop();
    if (const sl::TechniqueInfo* info = sl::Renderer::findTechnique(id.toStdString())) {
      // The technique's own panels; presenter mode keeps its one big panel.
      if (!presenter_->active()) docks_.showOnlyFor(*info);
      docks_.raiseFor(*info);
    }
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
  sl::ViewSide* renderer = viewport_->mainSide();
  if (!renderer) return paramPanel_->clear();
  const sl::TechniqueInfo* info = sl::Renderer::findTechnique(renderer->techniqueId());
  std::vector<ParamPanel::Section> sections;
  sections.push_back(
      {info ? QString::fromStdString(info->name) : QString::fromStdString(renderer->techniqueId()),
       info ? QString::fromStdString(info->description) : QString(), &renderer->params()});
  sections.push_back({tr("View and shading"), QString(), &renderer->rendererParams()});
  paramPanel_->setSections(std::move(sections));
  splitSide_->rebuildRows();  // the dock's second panel: built at the same font
}

// --- Renderer events ----------------------------------------------------------------------

void MainWindow::onRendererReady() {
  sl::ViewSide* renderer = viewport_->mainSide();
  if (!renderer) return;
  for (const QString& kv : pendingAssignments_)
    if (auto error =
            assignParameter(renderer->params(), renderer->rendererParams(), kv.toStdString()))
      report(QString::fromStdString(*error));
  pendingAssignments_.clear();
  rendererBound_ = true;
  grab_->resetFrameCount();
  rebuildParamPanel();
  splitSide_->rebuild();  // a split technique set before the renderer existed
  syncTechniqueCombo();
  if (const sl::TechniqueInfo* info = sl::Renderer::findTechnique(renderer->techniqueId()))
    docks_.raiseFor(*info);
  teaching_->syncOverlayCombo();
  updatePublishing();
  teaching_->restoreSplit();
  lessons_->queueSettle();  // a lesson chosen before the renderer started
  updateTitle();
  const QString gl = viewport_->glDescription();
  status_->showGl(gl);
  info(tr("Renderer ready: %1").arg(shortGlName(gl)));
  viewport_->frames()->requestFrame();
}

void MainWindow::onRendererAboutToBeDestroyed() {
  rendererBound_ = false;
  paramPanel_->clear();
  splitSide_->clear();
  if (teaching_) teaching_->setRendererAvailable(false);
}

void MainWindow::onFrameRendered() {
  const sl::ViewSide* renderer = viewport_->mainSide();
  if (!renderer) return;
  splitSide_->onFrameRendered();
  const sl::FrameStats& stats = renderer->stats();
  timingPanel_->setTechnique(sl::Renderer::findTechnique(renderer->techniqueId()));
  timingPanel_->showStats(stats, viewport_->frames()->frameFailure());
  if (rendererBound_) grab_->countFrame();
  if (docks_.isCurrent(*renderer, false)) docks_.feed(*renderer, false);
  passes_->onFrameRendered();
  refreshLiveTexts();
}

void MainWindow::refreshLiveTexts() {
  lessonPanel_->refreshLiveNumbers();
  if (lessons_->quotesLiveNumbers()) updateBanner();
}

void MainWindow::onRenderProblem(const QString& message) {
  report(message);  // a grab notes it
}

void MainWindow::onInitializationFailed(const QString& message) {
  if (failed_) return;
  failed_ = true;
  grab_->stop();
  report(message, tr("OpenGL problem"));
  QCoreApplication::exit(1);
}

// --- Light, camera, misc -------------------------------------------------------------------

void MainWindow::syncLightControls() {
  if (lightPanel_) lightPanel_->showLight(viewport_->camera()->light());
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
  // A scripted run fails on any problem, also one reported before its grab started (a
  // lesson's scene that does not load, a light the technique refuses).
  if (!interactive_ && grab_) grab_->noteProblem(message);
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

// --- Publications, pause and frame stepping, images ---------------------------------------

void MainWindow::onChartsConfigurationChosen(const QString& id, const QStringList& assignments) {
  if (id.toStdString() != viewport_->techniqueId()) setTechnique(id);
  sl::ViewSide* r = viewport_->mainSide();
  if (!r || id.toStdString() != r->techniqueId()) return;
  for (const QString& a : assignments) {
    const std::string key = a.section(QLatin1Char('='), 0, 0).toStdString();
    sl::ParamSet& set = r->params().has(key) ? r->params() : r->rendererParams();
    if (auto e = set.setFromString(key, a.section(QLatin1Char('='), 1).toStdString()))
      report(QString::fromStdString(*e));
  }
  rebuildParamPanel();
  viewport_->frames()->requestFrame();
  info(tr("Charts: showing %1 %2").arg(id, assignments.join(QLatin1Char(' '))));
}

std::string MainWindow::fillLiveText(const std::string& text) const {
  auto side = [this](const sl::ViewSide* r, std::optional<double> errorPct, bool failed) {
    sl::LiveSide s;
    if (!r) return s;
    s.errorPct = errorPct;
    if (!failed) s.frameMs = r->stats().totalMs;
    s.memoryMB = static_cast<double>(r->stats().memory.bytes()) / (1024.0 * 1024.0);
    s.publication = &r->publication();
    return s;
  };
  // The error the caption shows: the current view's, or in continuous rendering the latest
  // reference's (never a number that was not measured).
  auto live = [](std::optional<double> current,
                 const std::optional<MeasureService::LiveError>& latest) -> std::optional<double> {
    if (current) return current;
    if (latest && latest->unmeasured.isEmpty()) return latest->errorPct;
    return std::nullopt;
  };
  if (!viewport_) return sl::fillLiveText(text, {}, nullptr);
  const bool failed = !viewport_->frames()->frameFailure().isEmpty();
  const sl::LiveSide left =
      side(viewport_->mainSide(),
           failed ? std::nullopt
                  : live(viewport_->measure()->errorPct(), viewport_->measure()->liveError()),
           failed);
  const sl::ViewSide* split = viewport_->splitSide();
  const sl::LiveSide right = side(
      split,
      failed ? std::nullopt
             : live(viewport_->measure()->splitErrorPct(), viewport_->measure()->splitLiveError()),
      failed);
  return sl::fillLiveText(text, left, split ? &right : nullptr);
}

void MainWindow::updatePublishing() {
  sl::ViewSide* r = viewport_ ? viewport_->mainSide() : nullptr;
  if (!r) return;
  viewport_->measure()->setProbeWanted(docks_.probeWanted());
  std::set<std::string> keys = docks_.keys(grab_->running() || passes_->active());
  if (lessons_ && lessons_->settling())  // what the lesson waits for
    if (const sl::TechniqueInfo* info = sl::Renderer::findTechnique(r->techniqueId()))
      for (const std::string& key : rtwsettle::keys(*info)) keys.insert(key);
  // A grab's published.json holds every number the technique declares (they cost no readback).
  if (grab_->running())
    if (const sl::TechniqueInfo* info = sl::Renderer::findTechnique(r->techniqueId()))
      for (const sl::PublicationDecl& d : info->publications)
        if (d.kind == sl::PublicationKind::Number) keys.insert(d.key);
  // What the lesson's text quotes, on either side of the split view.
  std::set<std::string> splitKeys;
  if (lessons_)
    for (const std::string* text : lessons_->shownTexts()) {
      keys.merge(sl::livePublicationKeys(*text, false));
      splitKeys.merge(sl::livePublicationKeys(*text, true));
    }
  r->requestPublications(std::move(keys));
  viewport_->frames()->setSplitPublications(std::move(splitKeys));
}

void MainWindow::updateBanner() {
  if (!passes_->bannerTitle().isEmpty())
    viewport_->painter()->setBanner(passes_->bannerTitle(), passes_->bannerText());
  else
    viewport_->painter()->setBanner(lessons_->bannerTitle(), lessons_->bannerText());
}

void MainWindow::setPaused(bool paused) {
  if (pauseAction_->isChecked() != paused) {
    pauseAction_->setChecked(paused);  // re-enters through toggled
    return;
  }
  viewport_->frames()->setPaused(paused);
  if (!paused) passes_->stop();
  info(paused ? tr("Paused: . renders one frame, ] steps through its passes, Space resumes.")
              : tr("Running."));
}

void MainWindow::stepFrame() {
  if (!viewport_->frames()->paused()) setPaused(true);
  viewport_->frames()->stepFrame();
  passes_->restartAtNextFrame();  // stepping passes: start again at the new frame's first
}

bool MainWindow::waitForFrames(int frames, int timeoutMs) {
  const std::uint64_t target =
      viewport_->frames()->framesRendered() + static_cast<std::uint64_t>(frames);
  QElapsedTimer clock;
  clock.start();
  while (viewport_->frames()->framesRendered() < target) {
    viewport_->frames()->requestFrame();
    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    if (clock.elapsed() > timeoutMs) return false;
  }
  // The panels get the frame one per turn of the event loop: done when all have it.
  while (docks_.feeding()) {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    if (clock.elapsed() > timeoutMs) return false;
  }
  return true;
}

}  // namespace sl::ui
