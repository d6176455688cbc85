// The construction of the main window (see MainWindow.h): menus and their shortcuts, the
// main toolbar (scene, technique, camera), the docks (Parameters, Timing, the
// publication panels of panels/PanelRegistry.h, Lesson, Light, Charts), the status bar and
// the default layout. MainWindow.cpp has the window's behaviour.
#include <algorithm>

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QLayout>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QStatusBar>
#include <QToolBar>
#include <QToolButton>

#include "launch/LaunchOptions.h"
#include "teaching/LessonController.h"
#include "window/MainWindow.h"
#include "teaching/PassStepper.h"
#include "teaching/PresenterMode.h"
#include "window/SplitSideParams.h"
#include "window/StatusLine.h"
#include "window/WindowImages.h"
#include "window/SessionFiles.h"
#include "teaching/TeachingBar.h"
#include "window/Theme.h"
#include "view/ViewportWidget.h"
#include "window/WindowShortcuts.h"
#include "panels/common/ChartsPanel.h"
#include "panels/common/VariantMeasure.h"
#include "panels/common/LessonPanel.h"
#include "panels/common/ParamPanel.h"
#include "panels/common/TimingPanel.h"
#include "panels/light/LightPanel.h"
#include "scene/GltfLoader.h"
#include "service/RenderService.h"

namespace sl::ui {

namespace {
/// Some technique feeds `panel` and every panel of `row` (they belong side by side).
bool feedsTogether(const std::vector<const PublicationPanel*>& row, const PublicationPanel& panel) {
  for (const sl::TechniqueInfo& t : sl::Renderer::techniques())
    if (panel.describes(t) &&
        std::all_of(row.begin(), row.end(), [&](const auto* p) { return p->describes(t); }))
      return true;
  return false;
}

constexpr QSize kDefaultWindowSize(1600, 1000);
constexpr int kDefaultParamDockWidth = 390;
constexpr int kDefaultLeftDockWidth = 400;
constexpr int kDefaultBottomDockHeight = 300;
const QString kOverlayKey = QStringLiteral("view.overlay");
}  // namespace

void MainWindow::createActions() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QAction* open = file->addAction(tr("&Open glTF…"), this, &MainWindow::openSceneDialog);
  open->setShortcut(QKeySequence::Open);
  openAction_ = open;
  file->addSeparator();
  sessions_->createMenu(file);
  file->addSeparator();
  QAction* reload = file->addAction(tr("&Reload shaders"), this, [this] {
    if (auto error = viewport_->frames()->reloadShaders())
      report(tr("shader reload failed (the last good shaders stay in use): %1")
                 .arg(QString::fromStdString(*error)));
    else
      info(tr("Shaders reloaded."));
  });
  reload->setShortcut(Qt::Key_F5);
  QAction* screenshot =
      file->addAction(tr("Save &viewport image…"), images_, &WindowImages::saveViewImage);
  QAction* figure = file->addAction(tr("Export &figure… (view and split view, with errors)"),
                                    images_, &WindowImages::exportFigureDialog);
  figure->setToolTip(
      tr("A labelled PNG for handouts: each half of the view above its error "
         "image (wrong pixels drawn wider for print), with technique, texels, "
         "error and time, as shadowlab-cli compare --montage writes"));
  screenshot->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
  saveImageMenu_ = file->addMenu(tr("Save &panel image"));
  QAction* saveAll =
      file->addAction(tr("Save window and &all panels…"), images_, &WindowImages::saveAllImages);
  saveAll->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_S));
  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  QAction* resetView =
      view->addAction(tr("&Reset view"), this, [this] { viewport_->camera()->resetView(); });
  resetView->setShortcut(Qt::Key_Home);
  QAction* error = view->addAction(tr("Compute &error now"), this, [this] {
    if (!viewport_->measure()->computeErrorNow()) showStatus(tr("No frame to measure yet."));
  });
  error->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
  continuousAction_ = view->addAction(tr("Render &continuously"));
  continuousAction_->setCheckable(true);
  continuousAction_->setShortcut(Qt::Key_F6);
  continuousAction_->setToolTip(
      tr("Redraw every frame (for techniques that converge over frames)"));
  connect(continuousAction_, &QAction::toggled, viewport_->frames(), &FrameLoop::setContinuous);
  QAction* resetTemporal = view->addAction(tr("Reset &temporal state"), this, [this] {
    if (auto* r = viewport_->mainSide()) r->resetTemporalState();
    viewport_->frames()->requestFrame();
  });
  resetTemporal->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_T));
  view->addSeparator();
  QAction* cycleOverlay = view->addAction(tr("Next &overlay (none, error, aliasing, warp grid)"),
                                          this, [this] { teaching_->cycleOverlay(); });
  cycleOverlay->setShortcut(Qt::Key_O);
  QAction* split = view->addAction(tr("&Split view (compare two techniques)"), this,
                                   [this] { teaching_->toggleSplit(); });
  split->setShortcut(Qt::Key_F7);
  QAction* outside = view->addAction(tr("O&utside view (the frusta from a third camera)"));
  outside->setObjectName(QStringLiteral("outsideViewAction"));
  outside->setCheckable(true);
  outside->setShortcut(Qt::Key_V);
  outside->setToolTip(
      tr("A third camera shows the view frustum, split planes, light and warp "
         "frusta; drag orbits it, the wheel moves it (view.outside)"));
  connect(outside, &QAction::triggered, this, [this, outside] {
    const bool on =
        !viewport_->camera()->outsideView();  // the parameter may have changed (a lesson)
    if (!viewport_->camera()->setOutsideView(on))
      showStatus(tr("This renderer has no outside view."));
    outside->setChecked(viewport_->camera()->outsideView());
  });
  connect(view, &QMenu::aboutToShow, this,
          [this, outside] { outside->setChecked(viewport_->camera()->outsideView()); });
  view->addSeparator();
  presenter_->createActions(view);
  QMenu* panels = view->addMenu(tr("&Panels"));
  panels->setObjectName(QStringLiteral("panelsMenu"));
  QAction* defaultLayout = view->addAction(tr("&Default layout"), this, [this] {
    for (const PublicationDocks::Dock& d : docks_.docks())
      docks_.setOpenedByHand(d.entry.id, false);
    applyDefaultLayout();
  });

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
      frame->addAction(tr("Step through the &passes: next"), this, [this] { passes_->step(+1); });
  passNext->setShortcut(Qt::Key_BracketRight);
  passNext->setToolTip(
      tr("The passes of this frame as the technique declares them, one at a time, "
         "highlighting the panel that shows its output (])"));
  QAction* passPrev = frame->addAction(tr("Step through the passes: p&revious"), this,
                                       [this] { passes_->step(-1); });
  passPrev->setShortcut(Qt::Key_BracketLeft);
  // Esc: stops the action the window waits for (an error trace, an export, the equal-memory
  // search: RenderService::call), else the stepping through the passes.
  passStopAction_ = frame->addAction(tr("Stop stepping through the passes"), this, [this] {
    if (viewport_->service().callsWaiting() > 0)
      viewport_->service().cancelCall();
    else
      passes_->stop();
  });
  passStopAction_->setShortcut(Qt::Key_Escape);
  passStopAction_->setShortcutContext(Qt::WindowShortcut);
  passStopAction_->setEnabled(false);
  connect(&viewport_->service(), &RenderService::callStarted, this, [this] {
    passStopAction_->setEnabled(true);
    passStopAction_->setText(tr("Stop the action in progress"));
  });
  connect(&viewport_->service(), &RenderService::callEnded, this, [this](int stillWaiting) {
    if (stillWaiting > 0) return;
    passStopAction_->setText(tr("Stop stepping through the passes"));
    passStopAction_->setEnabled(passes_->active());
  });

  QMenu* lessons = menuBar()->addMenu(tr("&Lessons"));
  lessons_->createMenu(lessons);
  lessons_->createPapersMenu(menuBar()->addMenu(tr("&Papers")));

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  QAction* shortcuts = help->addAction(tr("&Keyboard and mouse"), this, &MainWindow::showShortcuts);
  shortcuts->setShortcut(QKeySequence::HelpContents);
  help->addAction(tr("&About ShadowLab"), this, [this] {
    QMessageBox::about(this, tr("About ShadowLab"),
                       tr("<b>ShadowLab %1</b><p>An interactive visual debugger and teaching tool "
                          "for adaptive shadow maps.</p>")
                           .arg(QCoreApplication::applicationVersion()));
  });

  commandActions_ = {open,
                     reload,
                     screenshot,
                     saveAll,
                     quit,
                     resetView,
                     error,
                     continuousAction_,
                     resetTemporal,
                     cycleOverlay,
                     split,
                     outside,
                     defaultLayout,
                     shortcuts,
                     presenter_->action(),
                     presenter_->fullPanelAction()};
  // Shortcuts work wherever the focus is (also while the viewport has it).
  for (QAction* a : commandActions_) a->setShortcutContext(Qt::ApplicationShortcut);
  // Frame stepping keys: plain keys, so only while the main window has the focus (typing
  // in a field still works: editors take printable keys before shortcuts).
  for (QAction* a : {step, passNext, passPrev}) a->setShortcutContext(Qt::WindowShortcut);
  commandActions_ << pauseAction_ << step << passNext << passPrev << passStopAction_;
  for (QAction* a : lessons->actions())
    if (!a->shortcut().isEmpty()) commandActions_ << a;
  new WindowShortcuts(*this, *viewport_);  // the fly keys from anywhere in the window
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
  sceneCombo_->addItem(tr("Open…"), openItemData());
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
  connect(bookmarkCombo_, &QComboBox::activated, this, [this](int index) {
    viewport_->camera()->goToBookmark(bookmarkCombo_->itemData(index).toInt());
  });
  bar->addWidget(bookmarkCombo_);
  auto* reset = new QToolButton;
  reset->setText(tr("Reset view"));
  reset->setToolTip(tr("Back to the scene's first camera (Home)"));
  connect(reset, &QToolButton::clicked, this, [this] { viewport_->camera()->resetView(); });
  bar->addWidget(reset);
}

void MainWindow::createDocks() {
  QMenu* panels = menuBar()->findChild<QMenu*>(QStringLiteral("panelsMenu"));

  paramPanel_ = new ParamPanel;
  connect(paramPanel_, &ParamPanel::paramChanged, this, [this](const QString& key) {
    if (key.isEmpty() || key == kOverlayKey) teaching_->syncOverlayCombo();
    if (viewport_->frames()->paused())
      viewport_->frames()->stepFrame();  // show the change even when paused
    viewport_->frames()->requestFrame();
  });
  connect(paramPanel_, &ParamPanel::editRefused, this,
          [this](const QString& message) { report(message); });
  paramDock_ = new QDockWidget(tr("Parameters"), this);
  paramDock_->setObjectName(QStringLiteral("parameters"));
  paramDock_->setWidget(splitSide_->createDockWidget(paramPanel_));
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
  // Dock titles at the body size: Qt draws them in the platform's smaller title font unless
  // the dock has a font of its own, and presenter mode would not scale that one.
  for (QDockWidget* dock : findChildren<QDockWidget*>()) followBodyFont(dock, 1.0);
}

void MainWindow::createStatusBar() {
  status_ = new StatusLine(*statusBar(), *viewport_, this);
  connect(continuousAction_, &QAction::toggled, status_, &StatusLine::onContinuousChanged);
  statusBar()->showMessage(tr("Starting the renderer…"));
  connect(statusBar(), &QStatusBar::messageChanged, this, [this](const QString& shown) {
    if (shown.isEmpty()) statusBar()->setToolTip(QString());
  });
}

void MainWindow::applyDefaultLayout() {
  const QScreen* screen = this->screen() ? this->screen() : QGuiApplication::primaryScreen();
  QSize size = kDefaultWindowSize;
  if (screen) size = size.boundedTo(screen->availableGeometry().size());
  // Right: Parameters | Lesson | Charts, the Light under them. Left: the registry's left
  // panels, one over the other. Bottom, under the view and the right column: its first
  // bottom panel and those a technique feeds together with the panels beside it, side by
  // side (RTW's warp functions, shadow map, moment chain); the others tabbed behind the
  // first, Timing behind the last. A technique shows only the panels it feeds
  // (PublicationDocks::showOnlyFor), so no row or tab is empty.
  for (QDockWidget* dock : findChildren<QDockWidget*>()) {
    dock->setFloating(false);
    dock->show();
  }
  addDockWidget(Qt::RightDockWidgetArea, paramDock_);
  addDockWidget(Qt::RightDockWidgetArea, lightDock_);
  splitDockWidget(paramDock_, lightDock_, Qt::Vertical);  // before the tabs: a neighbour
  addDockWidget(Qt::RightDockWidgetArea, lessonDock_);
  tabifyDockWidget(paramDock_, lessonDock_);
  addDockWidget(Qt::RightDockWidgetArea, chartsDock_);
  tabifyDockWidget(lessonDock_, chartsDock_);
  QDockWidget *leftFirst = nullptr, *leftLast = nullptr, *bottomFirst = nullptr,
              *bottomLast = nullptr;
  std::vector<const PublicationPanel*> row;  ///< the bottom row's panels, left to right
  for (const PublicationDocks::Dock& d : docks_.docks()) {
    addDockWidget(d.entry.area, d.dock);
    if (d.entry.area == Qt::LeftDockWidgetArea) {
      if (leftLast) splitDockWidget(leftLast, d.dock, Qt::Vertical);
      if (!leftFirst) leftFirst = d.dock;
      leftLast = d.dock;
    } else if (d.entry.area == Qt::BottomDockWidgetArea) {
      if (!bottomFirst) {
        bottomFirst = bottomLast = d.dock;
        row.push_back(d.panel);
      } else if (feedsTogether(row, *d.panel)) {
        splitDockWidget(bottomLast, d.dock, Qt::Horizontal);
        bottomLast = d.dock;
        row.push_back(d.panel);
      } else {
        tabifyDockWidget(bottomFirst, d.dock);
      }
    }
  }
  addDockWidget(Qt::BottomDockWidgetArea, timingDock_);
  if (bottomLast) tabifyDockWidget(bottomLast, timingDock_);
  // The technique's own panels only (the first screen's while the window is being built:
  // the window's size then fits them).
  const std::string technique =
      viewport_->techniqueId().empty() ? defaultTechniqueId() : viewport_->techniqueId();
  if (const sl::TechniqueInfo* info = sl::Renderer::findTechnique(technique)) {
    docks_.showOnlyFor(*info);
    docks_.raiseFor(*info);
  }
  paramDock_->raise();
  // Last: while the docks moved, a stale minimum may have widened the window; settle the
  // layout first, or the pending activation would undo the resize.
  layout()->invalidate();
  layout()->activate();
  resize(size);
  if (leftFirst)
    resizeDocks({paramDock_, leftFirst}, {kDefaultParamDockWidth, kDefaultLeftDockWidth},
                Qt::Horizontal);
  if (bottomFirst) resizeDocks({bottomFirst}, {kDefaultBottomDockHeight}, Qt::Vertical);
  // The bottom row's panels share its width.
  QList<QDockWidget*> shown;
  for (const PublicationDocks::Dock& d : docks_.docks())
    if (std::find(row.begin(), row.end(), d.panel) != row.end() && !d.dock->isHidden())
      shown << d.dock;
  if (shown.size() > 1)
    resizeDocks(shown, QList<int>(shown.size(), width() / int(shown.size())), Qt::Horizontal);
}

QDockWidget* MainWindow::addPanelDock(QWidget* panel, const QString& title, const QString& name,
                                      Qt::DockWidgetArea area) {
  auto* dock = new QDockWidget(title, this);
  dock->setObjectName(name);
  dock->setWidget(panel);
  addDockWidget(area, dock);
  // Right-click anywhere in a panel: save it as a PNG.
  auto* save = new QAction(tr("Save image of this panel…"), dock);
  connect(save, &QAction::triggered, this, [this, dock] { images_->savePanelImage(dock); });
  dock->addAction(save);
  dock->setContextMenuPolicy(Qt::ActionsContextMenu);
  return dock;
}

void MainWindow::createPanelDocks() {
  QMenu* panels = menuBar()->findChild<QMenu*>(QStringLiteral("panelsMenu"));
  // Panels' "measure" requests (variants of the shown view) run on the render thread.
  auto* variants = new VariantMeasure(viewport_, this);
  for (const PanelEntry& entry : publicationPanels()) {
    PublicationPanel* panel = entry.create();
    docks_.add(entry, addPanelDock(panel, entry.title, entry.id, entry.area), panel);
    connect(panel, &PublicationPanel::variantErrorsRequested, this,
            [variants, panel](const QString& tag, const QList<QStringList>& list) {
              variants->start(panel, tag, list);
            });
    connect(panel, &PublicationPanel::parameterChosen, this,
            [this](const QString& key, double value) {
              if (!paramPanel()->edit(key.toStdString(), value))
                report(tr("no parameter '%1' to set").arg(key));
            });
    connect(panel, &PublicationPanel::lightChosen, this, [this](double azimuth, double elevation) {
      // The storage analysis is for a directional light: a click makes the light one.
      viewport_->camera()->setLight(
          sl::Light::directional(static_cast<float>(azimuth), static_cast<float>(elevation)));
      syncLightControls();
      info(tr("Light moved to azimuth %1°, elevation %2°")
               .arg(azimuth, 0, 'f', 1)
               .arg(elevation, 0, 'f', 1));
    });
  }
  lessonPanel_ = new LessonPanel;
  lessonPanel_->setLiveFill([this](const std::string& text) { return fillLiveText(text); });
  lessonDock_ =
      addPanelDock(lessonPanel_, tr("Lesson"), QStringLiteral("lesson"), Qt::RightDockWidgetArea);
  // The light is edited, not published: its dock is not a registry entry
  // (panels/PanelRegistry.h lists PublicationPanels).
  lightPanel_ = new LightPanel;
  lightDock_ =
      addPanelDock(lightPanel_, tr("Light"), QStringLiteral("light"), Qt::RightDockWidgetArea);
  connect(lightPanel_, &LightPanel::lightEdited, viewport_->camera(), &CameraController::setLight);
  connect(viewport_->camera(), &CameraController::lightChanged, this,
          &MainWindow::syncLightControls);
  syncLightControls();
  chartsPanel_ = new ChartsPanel(viewport_);
  chartsDock_ =
      addPanelDock(chartsPanel_, tr("Charts"), QStringLiteral("charts"), Qt::RightDockWidgetArea);
  connect(chartsPanel_, &ChartsPanel::configurationChosen, this,
          &MainWindow::onChartsConfigurationChosen);
  for (QDockWidget* dock : {paramDock_, timingDock_}) {
    auto* save = new QAction(tr("Save image of this panel…"), dock);
    connect(save, &QAction::triggered, this, [this, dock] { images_->savePanelImage(dock); });
    dock->addAction(save);
    dock->setContextMenuPolicy(Qt::ActionsContextMenu);
  }
  std::vector<std::pair<QDockWidget*, QKeySequence>> toggled;
  for (const PublicationDocks::Dock& d : docks_.docks())
    toggled.push_back({d.dock, d.entry.shortcut});
  toggled.push_back({lessonDock_, {}});
  toggled.push_back({chartsDock_, {}});
  toggled.push_back({lightDock_, {}});  // past Ctrl+9: View > Panels only
  int key = Qt::Key_3;
  for (const auto& [dock, shortcut] : toggled) {
    QAction* toggle = dock->toggleViewAction();
    if (!shortcut.isEmpty() || key <= Qt::Key_9) {
      toggle->setShortcut(shortcut.isEmpty() ? QKeySequence(Qt::CTRL | static_cast<Qt::Key>(key++))
                                             : shortcut);
      toggle->setShortcutContext(Qt::ApplicationShortcut);
    }
    panels->addAction(toggle);
    commandActions_ << toggle;
  }
  for (const PublicationDocks::Dock& d : docks_.docks()) {
    // Opened by hand (View > Panels, its shortcut): it stays through technique switches.
    connect(d.dock->toggleViewAction(), &QAction::triggered, this,
            [this, id = d.entry.id](bool open) { docks_.setOpenedByHand(id, open); });
    connect(d.dock, &QDockWidget::visibilityChanged, this, [this, p = d.panel](bool visible) {
      updatePublishing();
      if (!visible || !viewport_ || !viewport_->mainSide()) return;  // (window being destroyed)
      if (docks_.isCurrent(*viewport_->mainSide(), false))
        p->showPublication(viewport_->mainSide()->publication());
      else
        viewport_->frames()->stepFrame();  // the last frame did not publish its keys: draw one
    });
  }
  for (QDockWidget* dock : findChildren<QDockWidget*>()) {
    QAction* a = saveImageMenu_->addAction(dock->windowTitle() + QStringLiteral("…"));
    connect(a, &QAction::triggered, this, [this, dock] { images_->savePanelImage(dock); });
  }
  lessons_->connectPanel(lessonPanel_);
}

}  // namespace sl::ui
