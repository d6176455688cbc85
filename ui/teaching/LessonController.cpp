// Lessons (see LessonController.h): presets from scenes/lessons applied to the window.
#include "teaching/LessonController.h"

#include <algorithm>
#include <cstdio>
#include <optional>

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenu>
#include <QStatusBar>
#include <QTimer>

#include "launch/LaunchOptions.h"
#include "window/MainWindow.h"
#include "teaching/PassStepper.h"
#include "teaching/PresenterMode.h"
#include "window/SessionFiles.h"
#include "teaching/TeachingBar.h"
#include "view/ViewportWidget.h"
#include "panels/common/PanelKit.h"
#include "panels/common/ParamPanel.h"
#include "panels/rtw/RtwSettle.h"

namespace sl::ui {

namespace {
/// A title from a file as a menu shows it: its "&" literally (a single one marks a mnemonic).
QString menuText(const std::string& title) {
  return QString::fromStdString(title).replace(QLatin1Char('&'), QStringLiteral("&&"));
}

/// How much of a fit note identifies it on the status line (shownMessage may shorten the rest).
constexpr int kFitNoteLead = 24;

/// First paragraph of a lesson explanation (the banner's "what to look at").
QString firstParagraph(const std::string& text) {
  return QString::fromStdString(text).section(QStringLiteral("\n\n"), 0, 0).simplified();
}
}  // namespace

LessonController::LessonController(MainWindow& window) : QObject(&window), w_(window) {}

void LessonController::createMenu(QMenu* menu) {
  QStringList errors;
  lessons_ = loadLessons(&errors);
  for (const QString& e : errors) std::fprintf(stderr, "shadowlab: lesson %s\n", qPrintable(e));
  for (std::size_t i = 0; i < lessons_.size(); ++i) {
    QAction* a = menu->addAction(tr("&%1 %2").arg(i + 1).arg(menuText(lessons_[i].preset.title)),
                                 this, [this, i] { apply(static_cast<int>(i)); });
    if (i < 10) {  // Alt+1 … Alt+9, then Alt+0 for the tenth (as on the keyboard's row)
      const Qt::Key key = i < 9 ? static_cast<Qt::Key>(Qt::Key_1 + int(i)) : Qt::Key_0;
      a->setShortcut(QKeySequence(Qt::ALT | key));
      a->setShortcutContext(Qt::ApplicationShortcut);
    }
    a->setToolTip(firstParagraph(lessons_[i].preset.explanation));
  }
  if (lessons_.empty())
    menu->addAction(tr("(no lessons in %1)").arg(lessonDirectory()))->setEnabled(false);
  menu->addSeparator();
  // Courses: the lessons in a class's order, Alt+PgDown / Alt+PgUp (or the Lesson dock's
  // Next / Previous) stepping through them.
  if (std::optional<std::vector<sl::Course>> courses = loadCourseFile(&courseError_)) {
    courses_ = std::move(*courses);
  } else {
    std::fprintf(stderr, "shadowlab: course file %s\n", qPrintable(courseError_));
    menu->addAction(tr("(courses: %1)").arg(courseError_))->setEnabled(false);
  }
  for (const sl::Course& c : courses_) {
    const QString name = QString::fromStdString(c.name);
    QAction* a = menu->addAction(tr("Course: %1 minutes").arg(c.minutes), this,
                                 [this, name] { startCourse(name); });
    a->setToolTip(tr("%1 lessons in about %2 minutes, in the course's order (Alt+PgDown: the "
                     "course's next lesson)")
                      .arg(c.lessons.size())
                      .arg(c.plannedMinutes()));
  }
  if (!courses_.empty()) {
    QAction* next =
        menu->addAction(tr("Next lesson of the course"), this, [this] { stepLesson(1); });
    next->setShortcut(QKeySequence(Qt::ALT | Qt::Key_PageDown));
    next->setShortcutContext(Qt::ApplicationShortcut);
    QAction* previous =
        menu->addAction(tr("Previous lesson of the course"), this, [this] { stepLesson(-1); });
    previous->setShortcut(QKeySequence(Qt::ALT | Qt::Key_PageUp));
    previous->setShortcutContext(Qt::ApplicationShortcut);
    menu->addSeparator();
  }
  QAction* next =
      menu->addAction(tr("Next &case of the lesson"), this, &LessonController::nextCase);
  next->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_N));
  next->setShortcutContext(Qt::ApplicationShortcut);
  next->setToolTip(
      tr("A lesson told in cases (e.g. where a method wins and where it does not): "
         "the next one"));
  bannerAction_ = menu->addAction(tr("Show the lesson &banner over the view"));
  bannerAction_->setCheckable(true);
  bannerAction_->setChecked(true);
  bannerAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
  bannerAction_->setShortcutContext(Qt::ApplicationShortcut);
  connect(bannerAction_, &QAction::toggled, this, [this] { w_.updateBanner(); });
  menu->setToolTipsVisible(true);
}

void LessonController::createPapersMenu(QMenu* menu) {
  const QDir dir(QDir(lessonDirectory()).filePath(QStringLiteral("../papers")));
  const QStringList files = dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
  for (const QString& file : files) {
    const QString path = QDir::cleanPath(dir.filePath(file));
    std::string error;
    const std::optional<sl::Preset> p = sl::loadPreset(path.toStdString(), &error);
    if (!p) {
      std::fprintf(stderr, "shadowlab: paper preset %s\n", error.c_str());
      continue;
    }
    QAction* a =
        menu->addAction(menuText(p->title.empty() ? file.toStdString() : p->title), this,
                        [this, path] { startFile(path, tr("Cannot open the paper preset")); });
    a->setToolTip(firstParagraph(p->explanation));
  }
  if (menu->isEmpty()) menu->addAction(tr("(no presets in %1)").arg(dir.path()))->setEnabled(false);
  menu->setToolTipsVisible(true);
}

void LessonController::connectPanel(LessonPanel* panel) {
  connect(panel, &LessonPanel::previousRequested, this, [this] { stepLesson(-1); });
  connect(panel, &LessonPanel::nextRequested, this, [this] { stepLesson(1); });
  connect(panel, &LessonPanel::restartRequested, this, [this] { apply(index_); });
  connect(panel, &LessonPanel::lessonChosen, this, [this](int index) { apply(index); });
  connect(panel, &LessonPanel::caseChosen, this, [this](int k) { apply(index_, k); });
  // The strip: the Parameters panel's rows for the lesson's few keys. Both edit the same
  // ParamSets; each refreshes the other, and the strip is rebuilt whenever the panel is (a
  // new technique, a new renderer, presenter mode's font).
  strip_ = new ParamPanel;
  strip_->setObjectName(QStringLiteral("lessonStripPanel"));
  stripDock_ = new QDockWidget(tr("Lesson controls"), &w_);
  stripDock_->setObjectName(QStringLiteral("lessonStrip"));
  stripDock_->setWidget(strip_);
  stripDock_->setToolTip(
      tr("The parameters this lesson's steps change (the same editors as in Parameters)"));
  w_.addDockWidget(Qt::RightDockWidgetArea, stripDock_);
  stripDock_->hide();
  ParamPanel* params = w_.paramPanel();
  connect(params, &ParamPanel::rebuilt, this, &LessonController::rebuildStrip);
  connect(params, &ParamPanel::paramChanged, strip_, &ParamPanel::refreshValues);
  connect(strip_, &ParamPanel::paramChanged, this, [this, params](const QString& key) {
    params->refreshValues();
    if (key.isEmpty() || key == QLatin1String("view.overlay")) w_.teaching()->syncOverlayCombo();
    if (w_.viewport()->frames()->paused())
      w_.viewport()->frames()->stepFrame();  // shown even when paused
    w_.viewport()->frames()->requestFrame();
  });
  connect(strip_, &ParamPanel::editRefused, this,
          [this](const QString& message) { w_.report(message); });

  QStringList titles;
  for (const Lesson& l : lessons_) titles << QString::fromStdString(l.preset.title);
  panel->setLessonTitles(titles);
  panel->showLesson(nullptr, -1, static_cast<int>(lessons_.size()));
}

bool LessonController::start(const QString& lesson, int caseIndex) {
  int found = findLesson(lessons_, lesson);
  if (found < 0) {  // a preset outside the lesson folder
    QString error;
    std::optional<Lesson> other = resolveLesson(lesson, &error);
    if (!other) {
      w_.report(error, tr("Cannot open lesson"));
      return false;
    }
    lessons_.push_back(std::move(*other));
    found = static_cast<int>(lessons_.size()) - 1;
  }
  const auto cases =
      static_cast<int>(lessons_[static_cast<std::size_t>(found)].preset.cases.size());
  if (caseIndex < 0 || caseIndex >= std::max(cases, 1)) {
    w_.report(tr("lesson '%1' has %2; there is no case %3")
                  .arg(lesson)
                  .arg(cases ? tr("%1 cases").arg(cases) : tr("no cases"))
                  .arg(caseIndex + 1),
              tr("Cannot open lesson"));
    return false;
  }
  apply(found, caseIndex);
  return true;
}

bool LessonController::startFile(const QString& path, const QString& dialogTitle) {
  std::string message;
  std::optional<sl::Preset> preset = sl::loadPreset(path.toStdString(), &message);
  if (!preset) {
    w_.report(QString::fromStdString(message), dialogTitle);
    return false;
  }
  // The scene first: a session whose scene cannot be loaded changes nothing (loadScene keeps
  // the current scene and reports, naming the file); apply() then finds it loaded.
  const QString scene = QString::fromStdString(preset->scene);
  if (!scene.isEmpty() && scene != w_.sceneSpec() && !w_.loadScene(scene)) {
    w_.report(tr("%1: its scene '%2' could not be loaded; nothing was changed").arg(path, scene),
              dialogTitle);
    return false;
  }
  auto same = std::find_if(lessons_.begin(), lessons_.end(),
                           [&path](const Lesson& l) { return l.path == path; });
  if (same == lessons_.end()) {
    lessons_.push_back(Lesson{path, std::move(*preset)});
    same = lessons_.end() - 1;
  } else {
    same->preset = std::move(*preset);
  }
  apply(static_cast<int>(same - lessons_.begin()));
  return true;
}

bool LessonController::startCourse(const QString& name) {
  const sl::Course* course = sl::findCourse(courses_, name.toStdString());
  if (!course) {
    w_.report(courseError_.isEmpty()
                  ? QString::fromStdString(sl::unknownCourseMessage(courses_, name.toStdString()))
                  : courseError_,
              tr("Cannot start the course"));
    return false;
  }
  const int first = findLesson(lessons_, QString::fromStdString(course->lessons.front().lesson));
  if (first < 0) {  // listed, but refused when the lessons were read (reported then)
    w_.report(tr("course %1: its lesson '%2' could not be read")
                  .arg(name, QString::fromStdString(course->lessons.front().lesson)),
              tr("Cannot start the course"));
    return false;
  }
  course_ = static_cast<int>(course - courses_.data());
  coursePosition_ = 0;
  apply(first);
  return true;
}

const sl::Course* LessonController::activeCourse() const {
  return course_ >= 0 ? &courses_[static_cast<std::size_t>(course_)] : nullptr;
}

void LessonController::stepLesson(int step) {
  const sl::Course* course = activeCourse();
  if (!course) {
    apply(std::clamp(index_ + step, 0, static_cast<int>(lessons_.size()) - 1));
    return;
  }
  const int to = coursePosition_ + step;
  if (to < 0 || to >= static_cast<int>(course->lessons.size())) return;
  const QString file = QString::fromStdString(course->lessons[static_cast<std::size_t>(to)].lesson);
  const int index = findLesson(lessons_, file);
  if (index < 0) {
    w_.report(tr("the course's lesson '%1' could not be read").arg(file));
    return;
  }
  coursePosition_ = to;
  apply(index);
}

QString LessonController::courseLine() const {
  const sl::Course* course = activeCourse();
  if (!course || coursePosition_ < 0) return {};
  return tr("Course %1 min: %2 of %3 · ~%4 min")
      .arg(course->minutes)
      .arg(coursePosition_ + 1)
      .arg(course->lessons.size())
      .arg(course->lessons[static_cast<std::size_t>(coursePosition_)].minutes);
}

const sl::Preset* LessonController::activePreset() const {
  if (index_ < 0 || index_ >= static_cast<int>(lessons_.size())) return nullptr;
  const sl::Preset& lesson = lessons_[static_cast<std::size_t>(index_)].preset;
  if (lesson.cases.empty()) return &lesson;
  return &lesson.cases[static_cast<std::size_t>(
      std::clamp(caseIndex_, 0, static_cast<int>(lesson.cases.size()) - 1))];
}

void LessonController::nextCase() {
  if (index_ < 0) return;
  const auto n = static_cast<int>(lessons_[static_cast<std::size_t>(index_)].preset.cases.size());
  if (n > 0) apply(index_, (caseIndex_ + 1) % n);
}

void LessonController::apply(int index, int caseIndex) {
  if (index < 0 || index >= static_cast<int>(lessons_.size())) return;
  MainWindow& w = w_;
  w.passes()->stop();
  index_ = index;
  caseIndex_ = caseIndex;
  // A lesson's pictures and numbers are full-size frames: from now on this window never
  // reduces its resolution (view.adaptive), whatever the frame time.
  w.viewport()->frames()->setAdaptiveAllowed(false);
  if (const sl::Course* course = activeCourse()) {  // still in the course: where in it
    const std::string file =
        QFileInfo(lessons_[static_cast<std::size_t>(index)].path).fileName().toStdString();
    const auto at = std::find_if(course->lessons.begin(), course->lessons.end(),
                                 [&file](const sl::CourseLesson& l) { return l.lesson == file; });
    if (at == course->lessons.end()) {
      course_ = -1;  // a lesson outside the course ends it
      coursePosition_ = -1;
    } else {
      coursePosition_ = static_cast<int>(at - course->lessons.begin());
    }
  }
  const sl::Preset& lesson = lessons_[static_cast<std::size_t>(index)].preset;
  const sl::Preset& p = *activePreset();  // the case's (the lesson's layout below)
  QStringList problems;

  const QString scene = QString::fromStdString(p.scene);
  if (!scene.isEmpty() && scene != w.sceneSpec()) {
    if (!w.loadScene(scene)) problems << tr("scene '%1' could not be loaded").arg(scene);
  } else if (w.viewport()->scene()) {
    w.viewport()->setScene(w.viewport()->scene());  // back to the scene's sun and first camera
    w.refreshBookmarks();
  }
  if (!p.technique.empty()) {
    if (!sl::Renderer::findTechnique(p.technique))
      problems << tr("this lesson needs the technique '%1', which this build does not have")
                      .arg(QString::fromStdString(p.technique));
    else
      w.setTechnique(QString::fromStdString(p.technique));
  }
  QStringList assignments;
  for (const auto& [key, value] : p.params)
    assignments << QString::fromStdString(key + "=" + value);
  if (sl::ViewSide* r = w.viewport()->mainSide()) {
    r->params().resetToDefaults();
    r->rendererParams().resetToDefaults();
    for (const QString& kv : assignments)
      if (auto error = assignParameter(r->params(), r->rendererParams(), kv.toStdString()))
        problems << QString::fromStdString(*error);
    r->resetTemporalState();
    w.paramPanel()->refreshValues();
    w.teaching()->syncOverlayCombo();
  } else {
    // Applied when the renderer starts, before those of the command line (which win).
    w.setPendingAssignments(assignments + w.pendingAssignments());
  }
  if (p.camera) w.viewport()->camera()->setCamera(*p.camera);
  if (p.light) {
    w.viewport()->camera()->setLight(*p.light);
    w.syncLightControls();
  }
  // A session's or a lesson's comparison: the split view ("" = off). None named: off, so a
  // lesson never shows the split of the lesson before it.
  const sl::PresetCompare compare = p.compare.value_or(sl::PresetCompare{});
  if (auto e = w.viewport()->frames()->setSplitTechnique(compare.technique, compare.params))
    problems << QString::fromStdString(*e);
  else
    w.teaching()->setSplitTechnique(QString::fromStdString(compare.technique), compare.params);
  rebuildStrip();  // before the layout: presenter mode places the strip with the docks
  if (lesson.layout) w.sessions()->applyLayout(*lesson.layout, &problems);  // a session: its docks
  placeStrip();
  w.docks().resetHistory();

  w.lessonPanel()->showLesson(&lessons_[static_cast<std::size_t>(index)], index,
                              static_cast<int>(lessons_.size()), caseIndex_);
  if (const sl::Course* course = activeCourse())
    w.lessonPanel()->setCourse(
        courseLine(),
        QString::fromStdString(course->lessons[static_cast<std::size_t>(coursePosition_)].thread),
        coursePosition_ > 0, coursePosition_ + 1 < static_cast<int>(course->lessons.size()));
  else
    w.lessonPanel()->setCourse({}, {}, false, false);
  w.lessonPanel()->setNote(problems.join(QLatin1Char('\n')));
  for (const QString& problem : problems) w.report(tr("lesson: %1").arg(problem));
  if (!lesson.layout) {
    w.lessonDock()->show();
    w.lessonDock()->raise();
  }
  w.updateBanner();
  if (w.viewport()->mainSide())
    settle();
  else  // settled when the renderer starts (MainWindow::onRendererReady)
    w.viewport()->frames()->requestFrame();
}

void LessonController::queueSettle() {
  if (index_ < 0 || settleQueued_) return;
  settleQueued_ = true;
  QTimer::singleShot(0, this, [this] {
    // Started before the window and its renderer were up: the window's own start-up (its
    // default layout, the technique's panels raised) came after the lesson's layout.
    if (index_ >= 0)
      if (const auto& layout = lessons_[static_cast<std::size_t>(index_)].preset.layout) {
        QStringList problems;
        rebuildStrip();
        w_.sessions()->applyLayout(*layout, &problems);
        placeStrip();
      }
    settle();
    settleQueued_ = false;  // only now: a script or grab must not start inside settle()
  });
}

void LessonController::settle() {
  if (!w_.viewport()->mainSide() || settling_) return;
  settling_ = true;  // from here: what waits for the lesson waits
  // The layout's resizes first (they are queued): the rotation depends on the view's aspect
  // (the importance follows the view frustum), so it must start from the size the lesson is
  // shown at.
  QTimer::singleShot(0, this, &LessonController::startSettling);
}

void LessonController::settleAgain() {
  if (index_ < 0) return;
  // Every technique's state across frames starts again at the view's new size, not only a
  // rotation's: cascades hold their split range while it still fits, so frames at a
  // transient size (a panel re-sized in a lesson's first frames) chose the range the lesson
  // was then measured with (lesson 10 after lesson 9: uniform split 22.8 % against 18.1 %).
  if (sl::ViewSide* r = w_.viewport()->mainSide()) r->resetTemporalState();
  if (settling_ && settleConnection_) {  // started at the old size: over again at the new one
    settleFrames_ = 0;
    settled_ = false;
    return;
  }
  if (!settling_) settle();
}

void LessonController::startSettling() {
  MainWindow& w = w_;
  sl::ViewSide* r = w.viewport()->mainSide();
  if (!r) {
    settling_ = false;
    return;
  }
  const sl::TechniqueInfo* info = sl::Renderer::findTechnique(r->techniqueId());
  const bool temporal = info && rtwsettle::settlesRotation(*info);
  settled_ = true;
  settleFrames_ = 0;
  if (!temporal || w.viewport()->frames()->paused()) {
    settling_ = false;
    // The panels show the lesson's frame once it is drawn: measured after it.
    connect(w.viewport()->frames(), &FrameLoop::frameRendered, this,
            &LessonController::reportFitSoon, Qt::SingleShotConnection);
    if (w.viewport()->frames()->paused()) w.viewport()->frames()->stepFrame();
    w.viewport()->frames()->requestFrame();
    return;
  }
  settled_ = false;
  w.updatePublishing();  // the rotation's numbers, while settling
  r->resetTemporalState();
  settleNote_ = w.lessonPanel()->note();
  showSettlingNote();
  // Frame by frame, driven by the view's frames (no nested event loop): settleFrame() looks
  // at each and asks for the next until an estimate leaves R unchanged.
  settleConnection_ = connect(w.viewport()->frames(), &FrameLoop::frameRendered, this,
                              &LessonController::settleFrame);
  w.viewport()->frames()->requestFrame();
}

void LessonController::showSettlingNote() {
  w_.lessonPanel()->setNote(
      tr("Settling: frame %1 of at most %2 — the rotation is estimated from the last frame's "
         "importance; the lesson's state is complete once an estimate leaves it unchanged.")
          .arg(settleFrames_ + 1)
          .arg(kMaxSettleFrames));
}

void LessonController::settleFrame() {
  MainWindow& w = w_;
  const sl::ViewSide* r = w.viewport()->mainSide();
  ++settleFrames_;
  const sl::TechniqueInfo* info = r ? sl::Renderer::findTechnique(r->techniqueId()) : nullptr;
  if (r && info)
    if (const std::optional<bool> done = rtwsettle::settled(*info, r->publication()))
      settled_ = *done;  // nothing yet on the first frame (it has no last frame)
  if (r && !settled_ && settleFrames_ < kMaxSettleFrames) {
    showSettlingNote();
    w.viewport()->frames()->requestFrame();
    return;
  }
  disconnect(settleConnection_);
  settling_ = false;
  reportFitSoon();
  // The plots start at the settled state: what the lesson is about (lesson 7's vibration of a
  // tenth of a degree) is not squeezed under the settling turn's tens of degrees.
  w.docks().resetHistory();
  w.updatePublishing();
  w.lessonPanel()->setNote(
      settled_ ? settleNote_
               : (settleNote_.isEmpty() ? QString() : settleNote_ + QLatin1Char('\n')) +
                     tr("The rotation still turns after %1 frames: it never holds with these "
                        "parameters.")
                         .arg(settleFrames_));
  w.viewport()->frames()->requestFrame();
}

void LessonController::reportFitSoon() {
  // After the events this frame queued (the panels' new data, their layouts).
  QTimer::singleShot(0, this, &LessonController::reportFit);
}

void LessonController::reportFit() {
  if (!fitNote_.isEmpty() &&
      w_.statusBar()->currentMessage().startsWith(fitNote_.left(kFitNoteLead)))
    w_.statusBar()->clearMessage();  // the last lesson's, or this one's at another size
  fitNote_.clear();
  if (index_ < 0) return;
  w_.presenter()->askReadableSettled();
  const auto& layout = lessons_[static_cast<std::size_t>(index_)].preset.layout;
  if (!layout) return;
  QStringList panels;
  for (const std::string& id : layout->docks) {
    // A hidden dock's, or one behind another tab, are not counted (unreadableParts).
    const QDockWidget* dock = w_.findChild<QDockWidget*>(QString::fromStdString(id));
    if (!dock) continue;
    const QStringList parts = unreadableParts(*dock);
    if (!parts.isEmpty())
      panels << (parts.size() == 1 ? tr("%1 (%2)").arg(dock->windowTitle(), parts.front())
                                   : tr("%1 (%2 parts, the first %3)")
                                         .arg(dock->windowTitle())
                                         .arg(parts.size())
                                         .arg(parts.front()));
  }
  if (panels.isEmpty()) return;
  fitNote_ = tr("Too small to read at this window size: %1. F12 shows the big panel full "
                "screen; closing other panels gives these room.")
                 .arg(panels.join(QStringLiteral("; ")));
  w_.showStatus(fitNote_, 0);
}

QDockWidget* LessonController::stripDock() const {
  return stripRows_ > 0 ? stripDock_ : nullptr;
}

void LessonController::rebuildStrip() {
  if (!strip_) return;
  std::vector<ParamPanel::StripRow> rows;
  // Only while the Parameters panel edits the renderer's ParamSets: it is cleared before
  // they are destroyed, and so is the strip then.
  sl::ViewSide* r = w_.viewport()->mainSide();
  if (r && w_.paramPanel()->bound() && index_ >= 0 && index_ < static_cast<int>(lessons_.size()))
    if (const auto& layout = lessons_[static_cast<std::size_t>(index_)].preset.layout)
      for (const std::string& key : layout->strip)
        rows.push_back({r->params().has(key) ? &r->params() : &r->rendererParams(), key});
  stripRows_ = rows.empty() ? 0 : strip_->setStrip(rows);
  if (stripRows_ == 0) {
    strip_->clear();
    stripDock_->hide();
  }
}

void LessonController::placeStrip() {
  if (!stripDock_ || w_.presenter()->active()) return;  // presenter mode: arrangeDocks
  if (!stripDock()) {
    stripDock_->hide();
    return;
  }
  // Under the right column (the Lesson dock's side), as tall as its rows.
  stripDock_->setFloating(false);
  w_.addDockWidget(Qt::RightDockWidgetArea, stripDock_, Qt::Vertical);
  stripDock_->show();
  w_.resizeDocks({stripDock_}, {stripDock_->sizeHint().height()}, Qt::Vertical);
}

QString LessonController::bannerTitle() const {
  if (index_ < 0 || !bannerAction_ || !bannerAction_->isChecked()) return {};
  const sl::Preset& p = lessons_[static_cast<std::size_t>(index_)].preset;
  const QString title = tr("Lesson %1: %2").arg(index_ + 1).arg(QString::fromStdString(p.title));
  if (p.cases.empty()) return title;
  return tr("Lesson %1 · %2").arg(index_ + 1).arg(QString::fromStdString(activePreset()->title));
}

QString LessonController::bannerText() const {
  if (index_ < 0 || !bannerAction_ || !bannerAction_->isChecked()) return {};
  // A case's: what this case shows; its live numbers filled.
  return firstParagraph(w_.fillLiveText(activePreset()->explanation));
}

std::vector<const std::string*> LessonController::shownTexts() const {
  std::vector<const std::string*> texts;
  if (index_ < 0) return texts;
  const sl::Preset& lesson = lessons_[static_cast<std::size_t>(index_)].preset;
  texts.push_back(&lesson.explanation);
  if (const sl::Preset* shown = activePreset(); shown && shown != &lesson)
    texts.push_back(&shown->explanation);
  return texts;
}

bool LessonController::quotesLiveNumbers() const {
  for (const std::string* text : shownTexts())
    if (text->find('{') != std::string::npos) return true;
  return false;
}

}  // namespace sl::ui
