// Lessons: the Lessons menu, starting a lesson (its scene, technique, parameters, camera and
// light), the Lesson dock's previous / next / restart, the lesson banner over the view, and
// courses (scenes/courses.json): lessons in a course's order, Next going to its next one.
#pragma once

#include <vector>

#include <QObject>
#include <QString>

#include "panels/common/LessonPanel.h"

class QAction;
class QDockWidget;
class QMenu;

namespace sl::ui {

class MainWindow;
class ParamPanel;

class LessonController : public QObject {
  Q_OBJECT

 public:
  explicit LessonController(MainWindow& window);

  /// Fills the Lessons menu (one entry per lesson file, Alt+1..9, the banner toggle).
  void createMenu(QMenu* menu);
  /// Fills the Papers menu: one entry per preset in scenes/papers (each paper's method as
  /// written), opened like a lesson (its scene, technique and parameters; its text in the
  /// Lesson dock).
  void createPapersMenu(QMenu* menu);
  /// Connects the Lesson dock's buttons (after the dock exists), and creates the lesson's
  /// strip dock (after the Parameters panel exists: the strip follows its rebuilds).
  void connectPanel(LessonPanel* panel);
  /// The active lesson's strip ("layout": {"strip": [...]}: the parameters its steps change,
  /// the Parameters panel's editors for just those): its dock while it shows at least one
  /// row (a key the current technique lacks, after the user switched, is left out), else
  /// null. Shown with the lesson: under the Lesson dock, in presenter mode under the big
  /// panel (PresenterMode::arrangeDocks).
  QDockWidget* stripDock() const;
  ParamPanel* strip() const { return strip_; }
  /// A lesson by number, base name or preset path, and its case (0-based); false (reported)
  /// when none, or when the lesson has no such case.
  bool start(const QString& lesson, int caseIndex = 0);
  /// A preset file (a saved session), read again even when it was opened before; false
  /// (reported under `dialogTitle`, nothing changed) when it cannot be read or its scene
  /// cannot be loaded.
  bool startFile(const QString& path, const QString& dialogTitle);
  /// Starts lesson `index`; of a lesson told in cases, case `caseIndex` (0-based; the
  /// lesson's layout stays the lesson's).
  void apply(int index, int caseIndex = 0);
  /// Starts course `name` (scenes/courses.json) at its first lesson; false (reported) when
  /// there is no such course or the course file is bad.
  bool startCourse(const QString& name);
  /// In a course: its lesson `step` places on (1: the next, -1: the previous); otherwise the
  /// lesson folder's. Nothing past either end.
  void stepLesson(int step);
  const std::vector<sl::Course>& courses() const { return courses_; }
  /// The active course (nullptr: none; opening a lesson that is not in it ends it) and the
  /// active lesson's place in it (0-based).
  const sl::Course* activeCourse() const;
  int coursePosition() const { return coursePosition_; }
  /// "Course 45 min: 3 of 7 · ~8 min" (empty outside a course).
  QString courseLine() const;

  /// The active lesson's next case (after the last: the first); nothing without cases.
  void nextCase();

  /// Renders until the lesson's temporal state has settled (DA-RTW: a frame whose rotation
  /// estimate leaves R unchanged, at most kMaxSettleFrames), from a fresh temporal state once
  /// the layout has given the view its final size; the Lesson dock says what it waits for.
  /// Called by apply(), and when the renderer starts with a lesson already chosen.
  void settle();
  /// The window's layout changed the view's size after the lesson opened (presenter mode
  /// keeping the window on its screen): its temporal state settles again at the new size.
  void settleAgain();
  /// settle() is running or queued (a grab waits for it).
  bool settling() const { return settling_ || settleQueued_; }
  void queueSettle();
  /// Frames the last settle() rendered, and whether the state settled within them.
  int settleFrames() const { return settleFrames_; }
  bool settled() const { return settled_; }
  static constexpr int kMaxSettleFrames = 12;

  const std::vector<Lesson>& lessons() const { return lessons_; }
  int index() const { return index_; }
  /// The active case of a lesson told in cases (0 otherwise).
  int caseIndex() const { return caseIndex_; }
  /// The preset the active lesson's case applied (the lesson itself without cases).
  const sl::Preset* activePreset() const;
  /// Banner title and text of the active lesson (empty: none, or the banner is off).
  QString bannerTitle() const;
  QString bannerText() const;
  /// The texts shown now (the lesson's explanation, and its active case's).
  std::vector<const std::string*> shownTexts() const;
  /// A text shown now quotes a live number ("{error_pct}").
  bool quotesLiveNumbers() const;
  /// What the status line said when the lesson had settled at its size, if a panel the
  /// lesson names is on screen below a readable size (unreadableParts): "Too small to read
  /// at this window size: Warp functions (a plot 25 px tall, ...)", naming every such
  /// panel and what gives it room; empty when every one reads.
  const QString& fitNote() const { return fitNote_; }

 private:
  MainWindow& w_;
  std::vector<Lesson> lessons_;
  int index_ = -1;
  int caseIndex_ = 0;
  std::vector<sl::Course> courses_;
  QString courseError_;  ///< the course file's problem (no courses then)
  int course_ = -1;      ///< index into courses_, -1: no course
  int coursePosition_ = -1;
  QAction* bannerAction_ = nullptr;
  /// Settling, after the queued layout events: resets the temporal state and waits for
  /// frames (settleFrame) until the rotation holds.
  void startSettling();
  void settleFrame();
  void showSettlingNote();
  QMetaObject::Connection settleConnection_;
  QString settleNote_;  ///< the Lesson dock's note before settling
  ParamPanel* strip_ = nullptr;
  QDockWidget* stripDock_ = nullptr;
  int stripRows_ = 0;
  /// The strip's rows for the active lesson and the renderer's current parameters.
  void rebuildStrip();
  /// Outside presenter mode: the strip's dock shown under the right column (hidden without
  /// rows); presenter mode places it itself.
  void placeStrip();
  /// Measures the lesson's panels once it has settled and says, on the status line, which
  /// are too small to read (fitNote).
  void reportFit();
  void reportFitSoon();
  QString fitNote_;
  bool settling_ = false, settleQueued_ = false, settled_ = true;
  int settleFrames_ = 0;
};

}  // namespace sl::ui
