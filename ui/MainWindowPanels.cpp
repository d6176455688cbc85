// The main window's debugging and teaching side (see MainWindow.h): the panels that observe
// the renderer's Publication, lessons, pause / frame / pass stepping, the overlay and
// split-view controls, and screenshots. MainWindow.cpp has construction, scenes and the
// renderer events.
#include <algorithm>
#include <cstdio>

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QJsonArray>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>
#include <QStyle>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>

#include "ChartsPanel.h"
#include "CovariancePanel.h"
#include "ImportancePanel.h"
#include "LaunchOptions.h"
#include "LessonPanel.h"
#include "MainWindow.h"

#include "panels/light/LightPanel.h"
#include "MomentPanel.h"
#include "ParamPanel.h"
#include "ShadowMapPanel.h"
#include "TimingPanel.h"
#include "ViewportWidget.h"
#include "WarpPanel.h"

namespace sl::ui {

namespace {
const QString kOverlayParam = QStringLiteral("view.overlay");
const QString kPassPrefix = QStringLiteral("\u25b6 ");  ///< dock title prefix while stepping
constexpr int kStatusMs = 10000;

/// First paragraph of a lesson explanation (the banner's "what to look at").
QString firstParagraph(const std::string& text) {
  return QString::fromStdString(text).section(QStringLiteral("\n\n"), 0, 0).simplified();
}
}  // namespace

// --- Construction --------------------------------------------------------------------------

void MainWindow::createTeachingToolBar() {
  QToolBar* bar = addFixedToolBar(tr("Teaching"), QStringLiteral("teachingToolBar"));
  auto addLabel = [bar](const QString& text) { addToolBarLabel(bar, text); };

  // Overlay: the choices come from the declaration of the shared `view.overlay` parameter.
  addLabel(tr("Overlay"));
  overlayCombo_ = new QComboBox;
  overlayCombo_->setObjectName(QStringLiteral("overlayCombo"));
  overlayCombo_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  const std::vector<sl::ParamDecl> shared = sl::rendererParamDecls();
  for (const sl::ParamDecl& d : shared) {
    if (QString::fromStdString(d.key) != kOverlayParam) continue;
    for (std::size_t i = 0; i < d.enumNames.size(); ++i)
      overlayCombo_->addItem(QString::fromStdString(d.enumNames[i]), static_cast<int>(i));
    overlayCombo_->setToolTip(QStringLiteral("<b>%1</b> (O cycles)<br>%2")
                                  .arg(QString::fromStdString(d.label).toHtmlEscaped(),
                                       QString::fromStdString(d.help).toHtmlEscaped()));
  }
  overlayCombo_->setEnabled(false);  // until the renderer exists
  connect(overlayCombo_, &QComboBox::activated, this,
          [this](int index) { setOverlay(overlayCombo_->itemData(index).toInt()); });
  bar->addWidget(overlayCombo_);
  if (overlayCombo_->count() == 0) overlayCombo_->hide();
  bar->addSeparator();

  addLabel(tr("Compare with"));
  splitCombo_ = new QComboBox;
  splitCombo_->setObjectName(QStringLiteral("splitCombo"));
  splitCombo_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  splitCombo_->setToolTip(
      tr("Split view (F7): this technique on the right half, same camera and light, with the "
         "time and error of both halves"));
  splitCombo_->addItem(tr("— (no split)"), QString());
  for (const sl::TechniqueInfo& t : sl::Renderer::techniques())
    splitCombo_->addItem(QString::fromStdString(t.name), QString::fromStdString(t.id));
  connect(splitCombo_, &QComboBox::activated, this,
          [this](int index) { setSplitTechnique(splitCombo_->itemData(index).toString()); });
  bar->addWidget(splitCombo_);
  bar->addSeparator();

  pauseAction_->setIcon(style()->standardIcon(QStyle::SP_MediaPause));
  bar->addAction(pauseAction_);
  auto addButton = [this, bar](const QString& text, const QString& tip, auto slot) {
    auto* b = new QToolButton;
    b->setText(text);
    b->setToolTip(tip);
    connect(b, &QToolButton::clicked, this, slot);
    bar->addWidget(b);
  };
  addButton(tr("Step frame"), tr("Render one frame and pause (.)"), [this] { stepFrame(); });
  addButton(tr("Step passes ▶"),
            tr("Walk through the passes of this frame: IM → collapse → blur → scan → warped "
               "map → lookup (] next, [ back, Esc stop)"),
            [this] { stepPass(+1); });
}

QDockWidget* MainWindow::addPanelDock(QWidget* panel, const QString& title, const QString& name,
                                      Qt::DockWidgetArea area) {
  auto* dock = new QDockWidget(title, this);
  dock->setObjectName(name);
  dock->setWidget(panel);
  addDockWidget(area, dock);
  // Right-click anywhere in a panel: save it as a PNG.
  auto* save = new QAction(tr("Save image of this panel…"), dock);
  connect(save, &QAction::triggered, this, [this, dock] { savePanelImage(dock); });
  dock->addAction(save);
  dock->setContextMenuPolicy(Qt::ActionsContextMenu);
  return dock;
}

void MainWindow::createPanelDocks() {
  QMenu* panels = menuBar()->findChild<QMenu*>(QStringLiteral("panelsMenu"));
  importancePanel_ = new ImportancePanel;
  momentPanel_ = new MomentPanel;
  covariancePanel_ = new CovariancePanel;
  warpPanel_ = new WarpPanel;
  shadowMapPanel_ = new ShadowMapPanel;
  lessonPanel_ = new LessonPanel;
  importanceDock_ = addPanelDock(importancePanel_, tr("Importance map"),
                                 QStringLiteral("importance"), Qt::LeftDockWidgetArea);
  covarianceDock_ = addPanelDock(covariancePanel_, tr("Covariance"), QStringLiteral("covariance"),
                                 Qt::LeftDockWidgetArea);
  warpDock_ = addPanelDock(warpPanel_, tr("Warp functions"), QStringLiteral("warp"),
                           Qt::BottomDockWidgetArea);
  shadowMapDock_ = addPanelDock(shadowMapPanel_, tr("Shadow map"), QStringLiteral("shadowmap"),
                                Qt::BottomDockWidgetArea);
  momentDock_ = addPanelDock(momentPanel_, tr("Moment mip chain"), QStringLiteral("moments"),
                             Qt::BottomDockWidgetArea);
  lessonDock_ =
      addPanelDock(lessonPanel_, tr("Lesson"), QStringLiteral("lesson"), Qt::RightDockWidgetArea);
  lightPanel_ = new LightPanel;
  addPanelDock(lightPanel_, tr("Light"), QStringLiteral("light"), Qt::RightDockWidgetArea);
  connect(lightPanel_, &LightPanel::lightEdited, viewport_, &ViewportWidget::setLight);
  connect(viewport_, &ViewportWidget::lightChanged, this, &MainWindow::syncLightControls);
  syncLightControls();
  chartsPanel_ = new ChartsPanel(viewport_);
  chartsDock_ =
      addPanelDock(chartsPanel_, tr("Charts"), QStringLiteral("charts"), Qt::RightDockWidgetArea);
  connect(chartsPanel_, &ChartsPanel::configurationChosen, this,
          [this](const QString& id, const QStringList& assignments) {
            if (id.toStdString() != viewport_->techniqueId()) setTechnique(id);
            sl::Renderer* r = viewport_->renderer();
            if (!r || id.toStdString() != r->techniqueId()) return;
            for (const QString& a : assignments) {
              const std::string key = a.section(QLatin1Char('='), 0, 0).toStdString();
              sl::ParamSet& set = r->params().has(key) ? r->params() : r->rendererParams();
              if (auto e = set.setFromString(key, a.section(QLatin1Char('='), 1).toStdString()))
                report(QString::fromStdString(*e));
            }
            rebuildParamPanel();
            viewport_->update();
            info(tr("Charts: showing %1 %2").arg(id, assignments.join(QLatin1Char(' '))));
          });
  for (QDockWidget* dock : {paramDock_, timingDock_}) {
    auto* save = new QAction(tr("Save image of this panel…"), dock);
    connect(save, &QAction::triggered, this, [this, dock] { savePanelImage(dock); });
    dock->addAction(save);
    dock->setContextMenuPolicy(Qt::ActionsContextMenu);
  }

  publicationDocks_ = {{importanceDock_, importancePanel_},
                       {covarianceDock_, covariancePanel_},
                       {warpDock_, warpPanel_},
                       {shadowMapDock_, shadowMapPanel_},
                       {momentDock_, momentPanel_}};
  int key = Qt::Key_3;
  for (QDockWidget* dock : {importanceDock_, covarianceDock_, warpDock_, shadowMapDock_,
                            momentDock_, lessonDock_, chartsDock_}) {
    QAction* toggle = dock->toggleViewAction();
    toggle->setShortcut(QKeySequence(Qt::CTRL | static_cast<Qt::Key>(key++)));
    toggle->setShortcutContext(Qt::ApplicationShortcut);
    panels->addAction(toggle);
    commandActions_ << toggle;
  }
  for (auto& [dock, panel] : publicationDocks_) {
    connect(dock, &QDockWidget::visibilityChanged, this, [this, p = panel](bool visible) {
      updatePublishing();
      if (!visible || !viewport_) return;  // (no viewport: the window is being destroyed)
      if (publicationIsCurrent())
        p->showPublication(viewport_->renderer()->publication());
      else if (viewport_->renderer())
        viewport_->stepFrame();  // publishing was off for the last frame: draw one
    });
  }
  for (QDockWidget* dock : findChildren<QDockWidget*>()) {
    QAction* a = saveImageMenu_->addAction(dock->windowTitle() + QStringLiteral("…"));
    connect(a, &QAction::triggered, this, [this, dock] { savePanelImage(dock); });
  }

  connect(lessonPanel_, &LessonPanel::previousRequested, this,
          [this] { applyLesson(std::max(0, lessonIndex_ - 1)); });
  connect(lessonPanel_, &LessonPanel::nextRequested, this, [this] {
    applyLesson(std::min(static_cast<int>(lessons_.size()) - 1, lessonIndex_ + 1));
  });
  connect(lessonPanel_, &LessonPanel::restartRequested, this,
          [this] { applyLesson(lessonIndex_); });
  connect(lessonPanel_, &LessonPanel::lessonChosen, this, &MainWindow::applyLesson);
  QStringList titles;
  for (const Lesson& l : lessons_) titles << QString::fromStdString(l.preset.title);
  lessonPanel_->setLessonTitles(titles);
  lessonPanel_->showLesson(nullptr, -1, static_cast<int>(lessons_.size()));
}

void MainWindow::createLessonsMenu(QMenu* menu) {
  QStringList errors;
  lessons_ = loadLessons(&errors);
  for (const QString& e : errors) std::fprintf(stderr, "shadowlab: lesson %s\n", qPrintable(e));
  for (std::size_t i = 0; i < lessons_.size(); ++i) {
    QAction* a = menu->addAction(
        tr("&%1 %2").arg(i + 1).arg(QString::fromStdString(lessons_[i].preset.title)), this,
        [this, i] { applyLesson(static_cast<int>(i)); });
    if (i < 9) {
      a->setShortcut(QKeySequence(Qt::ALT | static_cast<Qt::Key>(Qt::Key_1 + int(i))));
      a->setShortcutContext(Qt::ApplicationShortcut);
    }
    a->setToolTip(firstParagraph(lessons_[i].preset.explanation));
  }
  if (lessons_.empty())
    menu->addAction(tr("(no lessons in %1)").arg(lessonDirectory()))->setEnabled(false);
  menu->addSeparator();
  bannerAction_ = menu->addAction(tr("Show the lesson &banner over the view"));
  bannerAction_->setCheckable(true);
  bannerAction_->setChecked(true);
  bannerAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
  bannerAction_->setShortcutContext(Qt::ApplicationShortcut);
  connect(bannerAction_, &QAction::toggled, this, &MainWindow::updateBanner);
  menu->setToolTipsVisible(true);
}

// --- Lessons -------------------------------------------------------------------------------

bool MainWindow::startLesson(const QString& lesson) {
  int index = findLesson(lessons_, lesson);
  if (index < 0) {  // a preset outside the lesson folder
    QString error;
    std::optional<Lesson> found = resolveLesson(lesson, &error);
    if (!found) {
      report(error, tr("Cannot open lesson"));
      return false;
    }
    lessons_.push_back(std::move(*found));
    index = static_cast<int>(lessons_.size()) - 1;
  }
  applyLesson(index);
  return true;
}

void MainWindow::applyLesson(int index) {
  if (index < 0 || index >= static_cast<int>(lessons_.size())) return;
  if (passIndex_ >= 0) stopPassStepping();
  lessonIndex_ = index;
  const sl::Preset& p = lessons_[static_cast<std::size_t>(index)].preset;
  QStringList problems;

  const QString scene = QString::fromStdString(p.scene);
  if (!scene.isEmpty() && scene != sceneSpec_) {
    if (!loadScene(scene)) problems << tr("scene '%1' could not be loaded").arg(scene);
  } else if (viewport_->scene()) {
    viewport_->setScene(viewport_->scene());  // back to the scene's sun and first camera
    refreshBookmarks();
  }
  if (!p.technique.empty()) {
    if (!sl::Renderer::findTechnique(p.technique))
      problems << tr("this lesson needs the technique '%1', which this build does not have")
                      .arg(QString::fromStdString(p.technique));
    else
      setTechnique(QString::fromStdString(p.technique));
  }
  QStringList assignments;
  for (const auto& [key, value] : p.params)
    assignments << QString::fromStdString(key + "=" + value);
  if (sl::Renderer* r = viewport_->renderer()) {
    r->params().resetToDefaults();
    r->rendererParams().resetToDefaults();
    for (const QString& kv : assignments)
      if (auto error = assignParameter(r->params(), r->rendererParams(), kv.toStdString()))
        problems << QString::fromStdString(*error);
    r->resetTemporalState();
    paramPanel_->refreshValues();
    syncOverlayCombo();
  } else {
    // Applied when the renderer starts, before those of the command line (which win).
    pendingAssignments_ = assignments + pendingAssignments_;
  }
  if (p.camera) viewport_->setCamera(*p.camera);
  if (p.light) {
    viewport_->setLight(*p.light);
    syncLightControls();
  }
  for (auto& [dock, panel] : publicationDocks_) panel->resetHistory();

  lessonPanel_->showLesson(&lessons_[static_cast<std::size_t>(index)], index,
                           static_cast<int>(lessons_.size()));
  lessonPanel_->setNote(problems.join(QLatin1Char('\n')));
  for (const QString& problem : problems) report(tr("lesson: %1").arg(problem));
  lessonDock_->show();
  lessonDock_->raise();
  updateBanner();
  if (viewport_->paused()) viewport_->stepFrame();
  viewport_->update();
}

void MainWindow::updateBanner() {
  if (passIndex_ >= 0 && passIndex_ < static_cast<int>(passSteps_.size())) {
    const PassStep& step = passSteps_[static_cast<std::size_t>(passIndex_)];
    viewport_->setBanner(tr("Pass %1 of %2: %3   ( ] next · [ back · Esc stop )")
                             .arg(passIndex_ + 1)
                             .arg(passSteps_.size())
                             .arg(step.title),
                         step.text);
    return;
  }
  if (lessonIndex_ >= 0 && bannerAction_ && bannerAction_->isChecked()) {
    const sl::Preset& p = lessons_[static_cast<std::size_t>(lessonIndex_)].preset;
    viewport_->setBanner(
        tr("Lesson %1: %2").arg(lessonIndex_ + 1).arg(QString::fromStdString(p.title)),
        firstParagraph(p.explanation));
    return;
  }
  viewport_->setBanner(QString(), QString());
}

// --- Publication panels --------------------------------------------------------------------

bool MainWindow::publicationIsCurrent() const {
  const sl::Renderer* r = viewport_->renderer();
  return r && r->publication().frameIndex != 0 &&
         r->publication().frameIndex == r->stats().frameIndex;
}

void MainWindow::updatePublishing() {
  sl::Renderer* r = viewport_ ? viewport_->renderer() : nullptr;
  if (!r) return;
  bool wanted = !grabDir_.isEmpty() || passIndex_ >= 0 || passWaitingForFrame_;
  for (auto& [dock, panel] : publicationDocks_) wanted = wanted || dock->isVisible();
  r->setPublishing(wanted);
}

void MainWindow::feedPanels(bool all) {
  const sl::Renderer* r = viewport_->renderer();
  if (!r || r->publication().frameIndex == 0) return;
  for (auto& [dock, panel] : publicationDocks_)
    if (all || dock->isVisible()) panel->showPublication(r->publication());
}

// --- Pause, frame and pass stepping --------------------------------------------------------

void MainWindow::setPaused(bool paused) {
  if (pauseAction_->isChecked() != paused) {
    pauseAction_->setChecked(paused);  // re-enters through toggled
    return;
  }
  viewport_->setPaused(paused);
  if (!paused && passIndex_ >= 0) stopPassStepping();
  info(paused ? tr("Paused: . renders one frame, ] steps through its passes, Space resumes.")
              : tr("Running."));
}

void MainWindow::stepFrame() {
  if (!viewport_->paused()) setPaused(true);
  viewport_->stepFrame();
  if (passIndex_ >= 0) {  // stepping passes: start again at the new frame's first pass
    passWaitingForFrame_ = true;
    updatePublishing();
  }
}

void MainWindow::stepPass(int delta) {
  if (!viewport_->renderer()) return;
  if (passIndex_ < 0 && !passWaitingForFrame_) {
    pausedBeforePasses_ = viewport_->paused();
    if (!viewport_->paused()) setPaused(true);
    passStopAction_->setEnabled(true);
    if (publicationIsCurrent()) {
      passIndex_ = 0;
      showPass();
    } else {  // the last frame was not published: render one that is
      passWaitingForFrame_ = true;
      updatePublishing();
      viewport_->stepFrame();
    }
    return;
  }
  if (passWaitingForFrame_) return;
  const int next = passIndex_ + delta;
  if (next >= static_cast<int>(passSteps_.size())) {
    // Past the last pass: the frame is done; render the next one and start over.
    passWaitingForFrame_ = true;
    viewport_->stepFrame();
    return;
  }
  passIndex_ = std::max(0, next);
  showPass();
}

void MainWindow::showPass() {
  const sl::Renderer* r = viewport_->renderer();
  if (!r) return;
  const sl::Publication& pub = r->publication();
  feedPanels(true);
  // The passes this technique has, in frame order, each with the panel showing its output.
  passSteps_.clear();
  auto hasImage = [&pub](const char* key) { return pub.images.count(key) > 0; };
  auto hasCurve = [&pub](const char* key) { return pub.curves.count(key) > 0; };
  if (hasImage("importance"))
    passSteps_.push_back(
        {QStringLiteral("im"), tr("Importance map"),
         tr("The camera's needs in light space: every light texel gets the shadow-map "
            "density the camera wants there (eye distance; forward, backward or hybrid "
            "analysis). Bright = needs many texels. Shown in the Importance map panel (raw)."),
         importanceDock_});
  if (hasImage("moment.I.0") || pub.numbers.count("moment.I"))
    passSteps_.push_back(
        {QStringLiteral("moments"), tr("Moment mip chain"),
         tr("DA-RTW: six textures I, xI, yI, x²I, y²I, xyI, summed 2×2 per level down to 1×1: "
            "the top holds the sums that give the mean and covariance of the importance."),
         momentDock_});
  if (pub.numbers.count("e_x"))
    passSteps_.push_back(
        {QStringLiteral("pca"), tr("PCA and rotation"),
         tr("DA-RTW: the covariance's principal axis (orange) gives the rotation R' that turns "
            "the light's image plane so the axis lies on the shadow map's x axis — unless e_x "
            "is above the vibration threshold, then R is held."),
         covarianceDock_});
  if (hasCurve("importance.x"))
    passSteps_.push_back(
        {QStringLiteral("collapse"), tr("Collapse to 1D"),
         tr("The max over every column (x map) and row (y map) — backward analysis scatters "
            "straight into these two maps, the same maxima without the 2D IM. A rectilinear "
            "warp can only give the separable density Ix·Iy: compare it with the raw IM."),
         importanceDock_});
  if (hasCurve("importance.x.blurred"))
    passSteps_.push_back(
        {QStringLiteral("blur"), tr("Blur and floor"),
         tr("A Gaussian blur of each 1D map (no abrupt steps in the warp) and a floor so that "
            "no region collapses to zero texels: orange curves in Warp functions."),
         warpDock_});
  if (hasCurve("warp.x"))
    passSteps_.push_back(
        {QStringLiteral("scan"), tr("Prefix sum → warp maps"),
         tr("The normalised cumulative sum of importance is the warp: u' = u + warp(u). Its "
            "slope is the magnification; the dashed line is the uniform map."),
         warpDock_});
  if (hasImage("shadow map"))
    passSteps_.push_back(
        {QStringLiteral("warped"), hasCurve("warp.x") ? tr("Warped shadow map") : tr("Shadow map"),
         hasCurve("warp.x")
             ? tr("Depth from the light, warped: important regions get more texels (large grid "
                  "cells), beside the unwarped map for contrast. Each texel stores its "
                  "triangle's depth plane at the texel's unwarped centre (exact whatever the "
                  "tessellation); tessellation bends the silhouettes with the warp.")
             : tr("Depth from the light, uniform over the focused light frustum."),
         shadowMapDock_});
  passSteps_.push_back(
      {QStringLiteral("lookup"), tr("Lookup (resolve and shade)"),
       tr("Every pixel finds its light-space position, applies the same warp and compares "
          "its own plane, carried to the sampled texel's centre, with the depth stored "
          "there. Try the overlays (O): error against the exact reference, texels per pixel, "
          "the shadow-map grid on the scene."),
       nullptr});
  passIndex_ = std::clamp(passIndex_, 0, static_cast<int>(passSteps_.size()) - 1);
  const PassStep& step = passSteps_[static_cast<std::size_t>(passIndex_)];
  for (auto& [dock, panel] : publicationDocks_) panel->highlightPass(step.id);
  for (QDockWidget* dock : findChildren<QDockWidget*>()) {
    QString title = dock->windowTitle();
    if (title.startsWith(kPassPrefix)) title.remove(0, kPassPrefix.size());
    dock->setWindowTitle(dock == step.dock ? kPassPrefix + title : title);
  }
  if (step.dock) {
    step.dock->show();
    step.dock->raise();
  }
  updateBanner();
  showStatus(tr("Frame %1, pass %2 of %3: %4")
                 .arg(pub.frameIndex)
                 .arg(passIndex_ + 1)
                 .arg(passSteps_.size())
                 .arg(step.title),
             kStatusMs);
}

void MainWindow::stopPassStepping() {
  if (passIndex_ < 0 && !passWaitingForFrame_) return;
  passIndex_ = -1;
  passWaitingForFrame_ = false;
  passStopAction_->setEnabled(false);
  for (auto& [dock, panel] : publicationDocks_) panel->highlightPass(QString());
  for (QDockWidget* dock : findChildren<QDockWidget*>()) {
    QString title = dock->windowTitle();
    if (title.startsWith(kPassPrefix)) dock->setWindowTitle(title.mid(kPassPrefix.size()));
  }
  updateBanner();
  updatePublishing();
  if (!pausedBeforePasses_) setPaused(false);
}

// --- Overlays and split view ----------------------------------------------------------------

void MainWindow::syncOverlayCombo() {
  sl::Renderer* r = viewport_->renderer();
  const bool has = r && r->rendererParams().has(kOverlayParam.toStdString());
  overlayCombo_->setEnabled(has);
  if (!has) return;
  const int value = r->rendererParams().getInt(kOverlayParam.toStdString());
  const QSignalBlocker block(overlayCombo_);
  overlayCombo_->setCurrentIndex(overlayCombo_->findData(value));
}

void MainWindow::setOverlay(int value) {
  sl::Renderer* r = viewport_->renderer();
  if (!r) return;
  if (auto error = r->rendererParams().set(kOverlayParam.toStdString(), value)) {
    report(QString::fromStdString(*error));
    syncOverlayCombo();
    return;
  }
  paramPanel_->refreshValues();
  syncOverlayCombo();
  const sl::ParamDecl* d = r->rendererParams().find(kOverlayParam.toStdString());
  const bool error = d && value >= 0 && value < static_cast<int>(d->enumNames.size()) &&
                     d->enumNames[static_cast<std::size_t>(value)] == "error";
  if (viewport_->paused()) viewport_->stepFrame();
  viewport_->update();
  // The error overlay needs the exact reference of this view: compute it now.
  if (error && !viewport_->errorIsCurrent())
    QTimer::singleShot(0, this, [this] { viewport_->computeErrorNow(); });
}

void MainWindow::cycleOverlay() {
  const sl::Renderer* r = viewport_->renderer();
  if (!r || overlayCombo_->count() == 0) return;
  const int next = (overlayCombo_->currentIndex() + 1) % overlayCombo_->count();
  setOverlay(overlayCombo_->itemData(next).toInt());
  info(tr("Overlay: %1").arg(overlayCombo_->currentText()));
}

void MainWindow::setSplitTechnique(const QString& id) {
  if (auto error = viewport_->setSplitTechnique(id.toStdString())) {
    report(QString::fromStdString(*error));
    return;
  }
  if (!id.isEmpty()) lastSplitTechnique_ = id;
  const QSignalBlocker block(splitCombo_);
  splitCombo_->setCurrentIndex(std::max(0, splitCombo_->findData(id)));
  info(id.isEmpty() ? tr("Split view off.")
                    : tr("Split view: %1 (left) against %2 (right).")
                          .arg(QString::fromStdString(viewport_->techniqueId()), id));
}

void MainWindow::toggleSplit() {
  if (!viewport_->splitTechnique().empty()) return setSplitTechnique(QString());
  QString id = lastSplitTechnique_;
  if (id.isEmpty()) {  // uniform against anything else, else the first other technique
    const QString current = QString::fromStdString(viewport_->techniqueId());
    for (const sl::TechniqueInfo& t : sl::Renderer::techniques()) {
      const QString candidate = QString::fromStdString(t.id);
      if (candidate == current) continue;
      if (id.isEmpty() || candidate == QLatin1String("uniform")) id = candidate;
    }
  }
  if (id.isEmpty()) {
    report(tr("split view: there is only one technique to compare"));
    return;
  }
  setSplitTechnique(id);
}

// --- Screenshots -----------------------------------------------------------------------------

void MainWindow::savePanelImage(QDockWidget* dock) {
  const QString name = QStringLiteral("shadowlab-%1.png").arg(dock->objectName());
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Save panel image"), QDir::home().filePath(name), tr("PNG images (*.png)"));
  if (path.isEmpty()) return;
  if (dock->grab().toImage().save(path))
    showStatus(tr("Saved %1").arg(path), kStatusMs);
  else
    report(tr("cannot write %1").arg(path), tr("Save panel image"));
}

void MainWindow::saveAllImages() {
  const QString dir = QFileDialog::getExistingDirectory(this, tr("Save window and all panels into"),
                                                        QDir::homePath());
  if (dir.isEmpty()) return;
  const QStringList failures = writeImages(dir, false);
  if (failures.isEmpty())
    showStatus(tr("Saved the window and every panel in %1").arg(dir), kStatusMs);
  else
    report(failures.join(QLatin1Char('\n')), tr("Save images"));
}

QStringList MainWindow::writeImages(const QString& dirPath, bool printPaths) {
  QStringList failures;
  const QDir dir(dirPath);
  auto save = [&](const QImage& image, const QString& name) {
    const QString path = dir.absoluteFilePath(name);
    if (image.isNull() || !image.save(path)) {
      failures << tr("cannot write %1").arg(path);
      return;
    }
    if (printPaths) std::printf("%s\n", path.toLocal8Bit().constData());
  };
  save(grab().toImage(), QStringLiteral("window.png"));
  save(viewport_->grabView(), QStringLiteral("viewport.png"));
  // Tabbed docks: bring each to the front so that it is laid out and painted.
  std::vector<QDockWidget*> front;
  for (QDockWidget* dock : findChildren<QDockWidget*>())
    if (dock->isVisible()) front.push_back(dock);
  for (QDockWidget* dock : findChildren<QDockWidget*>()) {
    if (dock->isHidden() && !dock->toggleViewAction()->isChecked()) continue;  // closed
    dock->raise();
    QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
    save(dock->grab().toImage(), QStringLiteral("panel-%1.png").arg(dock->objectName()));
  }
  for (QDockWidget* dock : front) dock->raise();
  QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
  return failures;
}

QJsonObject MainWindow::publicationJson() const {
  QJsonObject o;
  const sl::Renderer* r = viewport_->renderer();
  if (!r) return o;
  const sl::Publication& pub = r->publication();
  o[QStringLiteral("frame")] = static_cast<qint64>(pub.frameIndex);
  o[QStringLiteral("technique")] = QString::fromStdString(r->techniqueId());
  o[QStringLiteral("published_technique")] = QString::fromStdString(pub.techniqueId);
  o[QStringLiteral("scene")] = sceneSpec_;
  QJsonObject numbers;
  for (const auto& [key, value] : pub.numbers) numbers[QString::fromStdString(key)] = value;
  o[QStringLiteral("numbers")] = numbers;
  QJsonObject images;
  for (const auto& [key, image] : pub.images)
    images[QString::fromStdString(key)] = QJsonArray{image.width, image.height, image.channels};
  o[QStringLiteral("images")] = images;
  QJsonObject curves;
  for (const auto& [key, curve] : pub.curves)
    curves[QString::fromStdString(key)] = static_cast<qint64>(curve.size());
  o[QStringLiteral("curves")] = curves;
  QJsonObject panels;
  for (const auto& [dock, panel] : publicationDocks_)
    panels[dock->objectName()] = panel->drawnValues();
  o[QStringLiteral("panels")] = panels;
  o[QStringLiteral("frame_ms")] = r->stats().totalMs;
  if (auto error = viewport_->errorPct()) o[QStringLiteral("error_pct")] = *error;
  if (!viewport_->splitTechnique().empty()) {
    o[QStringLiteral("split_technique")] = QString::fromStdString(viewport_->splitTechnique());
    if (auto error = viewport_->splitErrorPct()) o[QStringLiteral("split_error_pct")] = *error;
  }
  return o;
}

}  // namespace sl::ui
