// Lessons: presets in scenes/lessons/*.json (sl::loadPreset: title, explanation, scene,
// technique, params, camera, light; a saved session adds compare and layout), listed in the Lessons
// menu in file-name order, and the Lesson dock that shows the current one's explanation with
// previous / next / restart.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <QString>
#include <QStringList>
#include <QWidget>

#include "core/Course.h"
#include "core/Preset.h"

class QLabel;
class QPushButton;
class QTextBrowser;

namespace sl::ui {

struct Lesson {
  QString path;
  sl::Preset preset;
};

/// The folder the lessons live in: <built-in scene dir>/lessons.
QString lessonDirectory();
/// Every readable lesson, sorted by file name; problems (one line each) go to `errors`.
std::vector<Lesson> loadLessons(QStringList* errors);

/// Index into `lessons` of `spec`: a 1-based number, a file's base name
/// ("04-diagonal-pca"), a file name or a path of one of them; -1 when none matches.
int findLesson(const std::vector<Lesson>& lessons, const QString& spec);

/// The course file: <built-in scene dir>/courses.json.
QString courseFilePath();
/// The courses of courseFilePath(), checked against lessonDirectory(); nothing (and `error`
/// set to one line naming the file, the entry and what is wrong) when the file is bad. No
/// file: no courses.
std::optional<std::vector<sl::Course>> loadCourseFile(QString* error);

/// A lesson given on the command line: one of loadLessons() or a preset file elsewhere.
/// Nothing (and `error` set, naming the known lessons) when it cannot be found or read.
std::optional<Lesson> resolveLesson(const QString& spec, QString* error);

class LessonPanel : public QWidget {
  Q_OBJECT

 public:
  explicit LessonPanel(QWidget* parent = nullptr);

  /// Shows lesson `index` of `count` (null: the list of lessons to choose from), and of a
  /// lesson told in cases, case `caseIndex` (its buttons above the text).
  void showLesson(const Lesson* lesson, int index, int count, int caseIndex = 0);
  /// The list shown when no lesson is active.
  void setLessonTitles(const QStringList& titles);
  /// A line under the explanation (e.g. a parameter the lesson could not apply).
  void setNote(const QString& note);
  /// The course line above the title ("Course 45 min: 3 of 7 · ~8 min") and the sentence
  /// that connects the lesson to the course; an empty `position` hides both. `hasPrevious`
  /// and `hasNext` then enable Previous and Next (the course's, not the lesson folder's).
  void setCourse(const QString& position, const QString& thread, bool hasPrevious, bool hasNext);
  /// The course line as shown (empty: no course).
  QString courseLine() const;
  /// The note as set (unelided).
  QString note() const { return noteText_; }

  /// Where a text's live numbers ("{error_pct}", algo/TextTemplate.h) come from: the text
  /// with its placeholders filled from the last frame. Unset: texts are shown as written.
  using LiveFill = std::function<std::string(const std::string& text)>;
  void setLiveFill(LiveFill fill) { liveFill_ = std::move(fill); }
  /// A new frame (or a new error): the shown texts are filled again when they quote a live
  /// number (nothing is laid out again otherwise; the scroll position is kept).
  void refreshLiveNumbers();
  /// The explanation as shown now (the case's under the lesson's; placeholders filled), as
  /// plain text.
  QString shownText() const;

 Q_SIGNALS:
  void previousRequested();
  void nextRequested();
  void restartRequested();
  void lessonChosen(int index);
  void caseChosen(int caseIndex);

 private:
  QLabel* course_ = nullptr;  ///< the course position (hidden outside a course)
  QLabel* thread_ = nullptr;  ///< why this lesson comes here in the course
  QLabel* title_ = nullptr;
  QWidget* cases_ = nullptr;  ///< one checkable button per case (hidden without cases)
  QTextBrowser* text_ = nullptr;
  QLabel* note_ = nullptr;
  QPushButton* previous_ = nullptr;
  QPushButton* next_ = nullptr;
  QPushButton* restart_ = nullptr;
  QStringList titles_;
  QString noteText_;
  LiveFill liveFill_;
  /// A copy of the lesson shown (showLesson's arguments) and whether its texts quote live
  /// numbers.
  std::optional<Lesson> shownLesson_;
  int shownIndex_ = 0, shownCount_ = 0, shownCase_ = 0;
  bool live_ = false;
  QString shownHtml_;
  void showText();
};

}  // namespace sl::ui
