// The GUI's start: command line (LaunchOptions.h), GL-free checks, the OpenGL probe, the
// window, the lesson or course, then the event loop: an interactive window, a `--grab` run, or
// a window driven by a script (ui/Automation.h; tests/gui's shadowlab-gui-tests).
// Exit codes: 0 ok, 1 runtime failure (no GL 4.5, scene not loadable, grab failed),
// 2 bad command line (unknown option, technique or parameter, value out of range).
#include <cstdio>
#include <optional>
#include <vector>

#include <QApplication>
#include <QMessageBox>

#include "launch/Launch.h"

#include "service/GlSupport.h"
#include "launch/LaunchOptions.h"
#include "teaching/LessonController.h"
#include "panels/common/LessonPanel.h"
#include "window/MainWindow.h"
#include "window/Theme.h"
#include "core/Course.h"
#include "core/Renderer.h"
#include "window/MessageText.h"

namespace sl::ui {

namespace {

/// Qt aborts without a display; say what is missing instead (unless a platform is forced).
bool haveDisplay() {
  return qEnvironmentVariableIsSet("QT_QPA_PLATFORM") || !qEnvironmentVariableIsEmpty("DISPLAY") ||
         !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY");
}

/// Prints help, version or a usage error; returns the exit code, or nothing to go on.
std::optional<int> handleNonRunOutcome(const ParsedLaunch& parsed) {
  if (parsed.options) return std::nullopt;
  if (parsed.messageIsError)
    printErr(parsed.message);
  else
    std::printf("%s\n", parsed.message.toLocal8Bit().constData());
  return parsed.exitCode;
}

void setApplicationNames() {
  QCoreApplication::setOrganizationName(QStringLiteral("ShadowLab"));
  QCoreApplication::setApplicationName(QStringLiteral("shadowlab"));
  QCoreApplication::setApplicationVersion(QStringLiteral("0.1"));
}

}  // namespace

int runGui(int& argc, char** argv, const WindowScript& script) {
  if (!haveDisplay()) {
    // Qt would abort without a display: still answer --help / --version / usage errors.
    QCoreApplication core(argc, argv);
    setApplicationNames();
    if (auto code = handleNonRunOutcome(parseLaunchOptions(QCoreApplication::arguments())))
      return *code;
    printErr(
        QStringLiteral("no display: DISPLAY and WAYLAND_DISPLAY are not set; the GUI needs an "
                       "X server (e.g. Xvfb) or Wayland (shadowlab-cli works headless)"));
    return 1;
  }
  // The GL context format must be the default before the application exists.
  QApplication app(argc, argv);
  setApplicationNames();
  QApplication::setApplicationDisplayName(QStringLiteral("ShadowLab"));

  const ParsedLaunch parsed = parseLaunchOptions(QApplication::arguments());
  if (auto code = handleNonRunOutcome(parsed)) return *code;
  const LaunchOptions& options = *parsed.options;
  const bool scripted = static_cast<bool>(script);
  const bool interactive = !options.grab() && !scripted;

  // GL-free checks first: a typo must not cost a window (grab runs stop here; interactive
  // runs report the same problems in the status bar once the window is up).
  // A lesson brings its technique (the one --set is checked against when none is given).
  // A course starts at its first lesson (its file, course file and name checked here).
  QString firstLesson = options.lesson;
  if (!options.course.isEmpty()) {
    QString error;
    const std::optional<std::vector<sl::Course>> courses = loadCourseFile(&error);
    if (!courses) {
      printErr(error);
      return 2;
    }
    const sl::Course* course = sl::findCourse(*courses, options.course.toStdString());
    if (!course) {
      printErr(
          QString::fromStdString(sl::unknownCourseMessage(*courses, options.course.toStdString())));
      return 2;
    }
    firstLesson = QString::fromStdString(course->lessons.front().lesson);
  }
  const bool startsLesson = !firstLesson.isEmpty();
  // A course: through the window's LessonController (a child of the window).
  auto startLesson = [&options](MainWindow& w) {
    return options.course.isEmpty() ? w.startLesson(options.lesson, options.lessonCase - 1)
                                    : w.findChild<LessonController*>()->startCourse(options.course);
  };
  std::string lessonTechnique;
  if (startsLesson) {
    QString error;
    const std::optional<Lesson> lesson = resolveLesson(firstLesson, &error);
    if (!lesson) {
      printErr(error);
      return 2;
    }
    lessonTechnique = lesson->preset.technique;
  }
  const std::string technique = !options.technique.isEmpty() ? options.technique.toStdString()
                                : !lessonTechnique.empty()   ? lessonTechnique
                                                             : defaultTechniqueId();
  if (!interactive) {
    if (auto error = validateLaunchSettings(technique, options.assignments)) {
      printErr(QString::fromStdString(*error));
      return 2;
    }
  }

  QString glName;
  if (auto problem = probeOpenGL(&glName)) {
    printErr(*problem);
    if (interactive)
      QMessageBox::critical(nullptr, QStringLiteral("ShadowLab: OpenGL problem"), *problem);
    return 1;
  }

  applyTheme(app);
  MainWindow window(interactive);
  window.setPendingAssignments(options.assignments);

  if (!interactive) {
    // A lesson sets scene, technique and parameters; explicit options then override them.
    if (startsLesson && !startLesson(window)) return 2;
    if (!startsLesson || !options.technique.isEmpty())
      window.setTechnique(QString::fromStdString(technique));
    if ((!startsLesson || !options.scene.isEmpty()) &&
        !window.loadScene(options.scene.isEmpty() ? window.initialSceneName() : options.scene))
      return 1;
    window.show();
    if (options.presenter) window.setPresenterMode(true);
    if (scripted)
      script(window);
    else
      window.startGrab(options.grabDir, options.grabAfterFrames);
    return QApplication::exec();
  }

  if (!options.technique.isEmpty())
    window.setTechnique(options.technique);
  else if (const QString last = window.lastTechnique();
           !last.isEmpty() && sl::Renderer::findTechnique(last.toStdString()))
    window.setTechnique(last);
  else
    window.setTechnique(QString::fromStdString(technique));
  // The scene before the window: its first frame then already has something to show.
  const QString scene = options.scene.isEmpty() ? window.initialSceneName() : options.scene;
  if (!window.loadScene(scene) && scene != MainWindow::defaultSceneName())
    window.loadScene(MainWindow::defaultSceneName());
  if (startsLesson) startLesson(window);
  window.show();
  if (options.presenter) window.setPresenterMode(true);
  return QApplication::exec();
}

}  // namespace sl::ui
