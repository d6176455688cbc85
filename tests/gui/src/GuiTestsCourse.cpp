// The `course` self-test (see GuiTests.h): a course started with --course, stepped through
// with the Lesson dock's Next as a lecturer would.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <QAction>
#include <QApplication>
#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QFontInfo>
#include <QLabel>
#include <QPushButton>
#include <QScreen>

#include "teaching/LessonController.h"
#include "teaching/PresenterMode.h"
#include "window/MainWindow.h"
#include "GuiTests.h"
#include "panels/common/PanelKit.h"
#include "view/ViewportWidget.h"

namespace sl::ui {

bool GuiTests::course(const QString& dir) {
  LessonController& lessons = *w_.lessons();
  const sl::Course* course = lessons.activeCourse();
  check(course != nullptr, tr("--course started a course"));
  if (!course) return false;
  auto* next = w_.lessonPanel()->findChild<QPushButton*>(QStringLiteral("lessonNext"));
  auto* previous = w_.lessonPanel()->findChild<QPushButton*>(QStringLiteral("lessonPrevious"));
  auto* thread = w_.lessonPanel()->findChild<QLabel*>(QStringLiteral("lessonCourseThread"));
  check(next && previous && thread, tr("the Lesson dock has Next, Previous and the course line"));
  if (!next || !previous || !thread) return false;
  if (!dir.isEmpty()) QDir().mkpath(dir);
  auto activeFile = [&lessons] {
    return lessons.index() < 0
               ? QString()
               : QFileInfo(lessons.lessons()[static_cast<std::size_t>(lessons.index())].path)
                     .fileName();
  };
  const int count = static_cast<int>(course->lessons.size());
  for (int k = 0; k < count; ++k) {
    const sl::CourseLesson& want = course->lessons[static_cast<std::size_t>(k)];
    if (k > 0) next->click();  // opens the lesson (it settles on the frames that follow)
    const QString file = QString::fromStdString(want.lesson);
    check(activeFile() == file,
          tr("lesson %1 of the course is %2 (opened: %3)").arg(k + 1).arg(file, activeFile()));
    const QString line = QStringLiteral("Course %1 min: %2 of %3 · ~%4 min")
                             .arg(course->minutes)
                             .arg(k + 1)
                             .arg(count)
                             .arg(want.minutes);
    check(w_.lessonPanel()->courseLine() == line && !w_.lessonDock()->isHidden(),
          tr("the Lesson dock shows \"%1\" (shown: \"%2\")")
              .arg(line, w_.lessonPanel()->courseLine()));
    check(thread->isVisibleTo(w_.lessonPanel()) &&
              thread->text() == QString::fromStdString(want.thread),
          tr("%1: the dock shows the course's sentence for it").arg(file));
    // The course file's words as plain text: markup (an <img> of a local file) is not run.
    check(thread->textFormat() == Qt::PlainText, tr("%1: the sentence is plain text").arg(file));
    check(next->isEnabled() == (k + 1 < count) && previous->isEnabled() == (k > 0),
          tr("%1: Next %2, Previous %3")
              .arg(file, next->isEnabled() ? tr("on") : tr("off"),
                   previous->isEnabled() ? tr("on") : tr("off")));
    if (!dir.isEmpty())
      w_.lessonDock()->grab().save(QDir(dir).filePath(QStringLiteral("course-%1.png").arg(k + 1)));
  }
  lessons.stepLesson(1);  // past the last: stays
  check(lessons.coursePosition() == count - 1,
        tr("the course's next lesson after the last: none, the last stays open"));
  previous->click();
  check(count < 2 ||
            (lessons.coursePosition() == count - 2 &&
             activeFile() == QString::fromStdString(
                                 course->lessons[static_cast<std::size_t>(count - 2)].lesson)),
        tr("Previous opens the course's lesson before the last"));
  // A lesson outside the course (chosen from the Lessons menu) ends the course.
  int outside = -1;
  for (std::size_t i = 0; i < lessons.lessons().size() && outside < 0; ++i) {
    const std::string name = QFileInfo(lessons.lessons()[i].path).fileName().toStdString();
    bool listed = false;
    for (const sl::CourseLesson& l : course->lessons) listed = listed || l.lesson == name;
    if (!listed) outside = static_cast<int>(i);
  }
  if (outside >= 0) {
    lessons.apply(outside);
    check(!lessons.activeCourse() && w_.lessonPanel()->courseLine().isEmpty() && thread->isHidden(),
          tr("a lesson outside the course ends it (the dock's course line is gone)"));
  }
  // Presenter mode turned on (F11) after a lesson laid out its docks: the lesson's telling
  // panel is the big one, not the technique's first panel (lesson 6: Covariance, where
  // DA-RTW's first panel is Importance).
  if (lessons.start(QStringLiteral("06-diagonal-pca"))) {
    auto_.waitForSettled();
    const std::string want =
        lessons.lessons()[static_cast<std::size_t>(lessons.index())].preset.layout->large;
    w_.presenter()->action()->trigger();  // what F11 does
    const QDockWidget* big = w_.presenter()->bigDock();
    check(big && big->objectName().toStdString() == want && !big->visibleRegion().isEmpty(),
          tr("F11 after the lesson opened: the big panel is the lesson's %1 (shown: %2)")
              .arg(QString::fromStdString(want), big ? big->objectName() : tr("none")));
    // The split view's own rows (the Parameters dock's second panel, built before F11) are
    // rebuilt at the presenter's font like the main panel's.
    const int body = QFontInfo(QApplication::font()).pixelSize();
    int smallest = body;
    const QWidget* side = w_.paramDock()->findChild<QWidget*>(QStringLiteral("splitParamPanel"));
    for (const QLabel* label : side ? side->findChildren<QLabel*>() : QList<QLabel*>())
      smallest = std::min(smallest, QFontInfo(label->font()).pixelSize());
    check(side && smallest >= body * 4 / 5,
          tr("F11 with the split view on: its parameter rows at %1 px (body %2 px)")
              .arg(smallest)
              .arg(body));
    w_.presenter()->action()->trigger();
  }
  return true;
}

bool GuiTests::courseClaims(const QString& dir) {
  LessonController& lessons = *w_.lessons();
  const sl::Course* course = lessons.activeCourse();
  check(course != nullptr, tr("--course started a course"));
  auto* next = w_.lessonPanel()->findChild<QPushButton*>(QStringLiteral("lessonNext"));
  check(next != nullptr, tr("the Lesson dock has Next"));
  if (!course || !next) return false;
  // The course's lessons by file name, kept: a lesson's checks may apply its other cases.
  std::vector<std::string> files;
  for (const sl::CourseLesson& l : course->lessons) files.push_back(l.lesson);
  const int minutes = course->minutes;
  for (std::size_t k = 0; k < files.size(); ++k) {
    if (k > 0) next->click();  // opens the lesson; it settles on the frames that follow
    check(auto_.waitForSettled() && auto_.waitForFrames(2),
          tr("lesson %1 of the course settled after Next").arg(k + 1));
    const int index = lessons.index();
    const QString open =
        index < 0 ? QString()
                  : QFileInfo(lessons.lessons()[static_cast<std::size_t>(index)].path).fileName();
    check(open == QString::fromStdString(files[k]),
          tr("Next: lesson %1 of the %2-minute course is %3 (open: %4)")
              .arg(k + 1)
              .arg(minutes)
              .arg(QString::fromStdString(files[k]), open));
    if (open != QString::fromStdString(files[k])) return false;
    checkOpenLesson(index, dir);
  }
  return true;
}

void GuiTests::printReadableNeed() {
  // How much room the big panel lacks: its least size with every plot and image readable
  // against the size it has (asked for a moment, then given up again as it was).
  QDockWidget* big = w_.presenter()->bigDock();
  if (!big) return;
  auto flush = [] {
    for (int level = 0; level < 8; ++level)
      QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
  };
  const bool was = big->property("slReadableMinimum").toBool();
  setReadableMinimums(*big, true);
  flush();
  const QSize need = big->minimumSizeHint();
  const int windowNeeds = w_.minimumSizeHint().height(), windowGot = w_.height();
  QStringList parts;
  for (const QWidget* part : big->findChildren<QWidget*>())
    if ((qobject_cast<const PlotWidget*>(part) || qobject_cast<const ImageView*>(part)) &&
        part->isVisible())
      parts << QStringLiteral("%1 %2x%3 of %4x%5")
                   .arg(part->objectName().isEmpty()
                            ? QString::fromLatin1(part->metaObject()->className())
                            : part->objectName())
                   .arg(part->width())
                   .arg(part->height())
                   .arg(part->minimumSizeHint().width())
                   .arg(part->minimumSizeHint().height());
  setReadableMinimums(*big, was);
  flush();
  std::printf(
      "     the big panel %s: %dx%d, readable at %dx%d; the window then at least %d px tall "
      "(it grew to %d) (%s)\n",
      qPrintable(big->objectName()), big->width(), big->height(), need.width(), need.height(),
      windowNeeds, windowGot, qPrintable(parts.join(QStringLiteral(", "))));
}

bool GuiTests::courseGrabs(const QString& dir) {
  LessonController& lessons = *w_.lessons();
  const sl::Course* course = lessons.activeCourse();
  check(course != nullptr, tr("--course started a course"));
  auto* next = w_.lessonPanel()->findChild<QPushButton*>(QStringLiteral("lessonNext"));
  check(next != nullptr, tr("the Lesson dock has Next"));
  check(!dir.isEmpty() && QDir().mkpath(dir), tr("course-grabs=DIR: a folder to save into"));
  if (!course || !next || dir.isEmpty()) return false;
  const std::size_t count = course->lessons.size();
  // The window as the class sees it: settled, the named panels filled, the view's error
  // measured (the banner's and the text's numbers).
  auto grabAs = [&](const QString& shot) {
    check(auto_.waitForSettled() && auto_.waitForFrames(2), tr("%1 settled").arg(shot));
    const int index = lessons.index();
    const auto& layout = lessons.lessons()[static_cast<std::size_t>(index)].preset.layout;
    for (int frame = 0; frame < 10 && layout; ++frame) {
      bool empty = false;
      for (const std::string& id : layout->docks)
        if (const auto* dock = w_.findChild<QDockWidget*>(QString::fromStdString(id)))
          if (const auto* panel = qobject_cast<const PublicationPanel*>(dock->widget()))
            empty = empty || (dock->isVisible() && !panel->placeholderShown().isEmpty());
      if (!empty) break;
      if (!auto_.waitForFrames(1)) break;
    }
    w_.viewport()->measure()->computeErrorNow();
    QCoreApplication::processEvents();
    const QString note = lessons.fitNote();
    std::printf("     %s: window %dx%d, %s\n", qPrintable(shot), w_.width(), w_.height(),
                note.isEmpty() ? "every panel it names reads" : qPrintable(note));
    std::fflush(stdout);
    const QString path = QDir(dir).filePath(shot + QStringLiteral(".png"));
    check(w_.grab().toImage().save(path), tr("%1 saved").arg(path));
    if (!note.isEmpty()) printReadableNeed();  // after the grab: it lays the window out again
  };
  for (std::size_t k = 0; k < count; ++k) {
    if (k > 0) next->click();  // opens the lesson; it settles on the frames that follow
    const QString name =
        QFileInfo(QString::fromStdString(course->lessons[k].lesson)).completeBaseName();
    const int index = lessons.index();
    check(
        index >= 0 &&
            QFileInfo(lessons.lessons()[static_cast<std::size_t>(index)].path).completeBaseName() ==
                name,
        tr("Next: lesson %1 of the course is %2").arg(k + 1).arg(name));
    if (index < 0) return false;
    grabAs(name);
    // A lesson told in cases: each further case as Ctrl+Shift+N applies it.
    const std::size_t cases =
        lessons.lessons()[static_cast<std::size_t>(index)].preset.cases.size();
    for (std::size_t c = 1; c < cases; ++c) {
      lessons.nextCase();
      grabAs(QStringLiteral("%1-case%2").arg(name).arg(c + 1));
    }
  }
  return true;
}

}  // namespace sl::ui
