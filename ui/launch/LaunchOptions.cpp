// Command-line parsing and GL-free validation for the GUI (see LaunchOptions.h).
#include "launch/LaunchOptions.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include "core/Renderer.h"

namespace sl::ui {

ParsedLaunch parseLaunchOptions(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.setApplicationDescription(QStringLiteral(
      "ShadowLab: an interactive visual debugger and teaching tool for adaptive shadow maps."));
  const QCommandLineOption help = parser.addHelpOption();
  const QCommandLineOption version = parser.addVersionOption();
  const QCommandLineOption scene(QStringLiteral("scene"),
                                 QStringLiteral("Built-in scene name or .gltf/.glb file."),
                                 QStringLiteral("NAME|FILE"));
  const QCommandLineOption technique(
      QStringLiteral("technique"),
      QStringLiteral("Technique id (default: da-rtw, or the last one used)."),
      QStringLiteral("ID"));
  const QCommandLineOption set(
      QStringLiteral("set"),
      QStringLiteral("Set a parameter (repeatable), e.g. --set resolution=2048."),
      QStringLiteral("KEY=VALUE"));
  const QCommandLineOption grab(QStringLiteral("grab"),
                                QStringLiteral("Render, save window.png, viewport.png and "
                                               "panel-<name>.png into DIR, then quit."),
                                QStringLiteral("DIR"));
  const QCommandLineOption grabAfter(
      QStringLiteral("grab-after"), QStringLiteral("Frames to render before grabbing (default 5)."),
      QStringLiteral("N"), QStringLiteral("5"));
  const QCommandLineOption lesson(
      QStringLiteral("lesson"),
      QStringLiteral("Start a lesson: its number, its file name in scenes/lessons (e.g. "
                     "04-diagonal-pca) or a preset file. Its scene, technique and parameters "
                     "come first; --scene, --technique and --set then override them."),
      QStringLiteral("N|NAME|FILE"));
  const QCommandLineOption lessonCase(
      QStringLiteral("lesson-case"),
      QStringLiteral("With --lesson: start the lesson's case N (1-based) of a lesson told in "
                     "cases (Lessons > Next case)."),
      QStringLiteral("N"), QStringLiteral("1"));
  const QCommandLineOption course(
      QStringLiteral("course"),
      QStringLiteral("Start a course (scenes/courses.json: 90 or 45 minutes) at its first "
                     "lesson; Next in the Lesson dock (Alt+PgDown) opens the course's next "
                     "lesson."),
      QStringLiteral("NAME"));
  const QCommandLineOption session(
      QStringLiteral("open-session"),
      QStringLiteral("Open a session saved with File > Save session… (the same as --lesson "
                     "FILE: a session is a lesson)."),
      QStringLiteral("FILE"));
  const QCommandLineOption presenter(
      QStringLiteral("presenter"),
      QStringLiteral("Start in presenter mode (F11): fonts scaled to the screen, high contrast, "
                     "the window filling the screen, one big panel beside the view."));
  parser.addOptions(
      {scene, technique, set, lesson, lessonCase, course, session, presenter, grab, grabAfter});

  // A refusal: exit status 2 and the one-line reason, no options.
  const auto usageError = [](QString message) {
    return ParsedLaunch{.exitCode = 2, .message = std::move(message), .messageIsError = true};
  };
  ParsedLaunch out;
  if (!parser.parse(arguments)) return usageError(parser.errorText());
  if (parser.isSet(help)) {
    out.message = parser.helpText();
    return out;
  }
  if (parser.isSet(version)) {
    out.message = QCoreApplication::applicationName() + QLatin1Char(' ') +
                  QCoreApplication::applicationVersion();
    return out;
  }
  if (!parser.positionalArguments().isEmpty())
    return usageError(QStringLiteral("unexpected argument '%1' (use --scene FILE to open a scene)")
                          .arg(parser.positionalArguments().first()));
  LaunchOptions o;
  o.scene = parser.value(scene);
  o.technique = parser.value(technique);
  o.assignments = parser.values(set);
  o.grabDir = parser.value(grab);
  o.lesson = parser.value(lesson);
  o.presenter = parser.isSet(presenter);
  if (parser.isSet(session)) {
    if (parser.isSet(lesson))
      return usageError(QStringLiteral("--open-session and --lesson: give one of them"));
    o.lesson = parser.value(session);
  }
  if (parser.isSet(course)) {
    if (!o.lesson.isEmpty())
      return usageError(
          QStringLiteral("--course and --lesson (or --open-session): give one of them"));
    o.course = parser.value(course);
  }
  if (parser.isSet(lessonCase)) {
    bool caseOk = false;
    o.lessonCase = parser.value(lessonCase).toInt(&caseOk);
    if (!caseOk || o.lessonCase < 1 || o.lessonCase > 8 || o.lesson.isEmpty())
      return usageError(
          o.lesson.isEmpty()
              ? QStringLiteral("--lesson-case: needs --lesson (the lesson it is a case of)")
              : QStringLiteral("--lesson-case: expected a case number 1..8, got '%1'")
                    .arg(parser.value(lessonCase)));
  }
  bool ok = false;
  o.grabAfterFrames = parser.value(grabAfter).toInt(&ok);
  if (!ok || o.grabAfterFrames < 1 || o.grabAfterFrames > 100000)
    return usageError(QStringLiteral("--grab-after takes a frame count 1..100000, got '%1'")
                          .arg(parser.value(grabAfter)));
  if (parser.isSet(grabAfter) && !o.grab())
    return usageError(QStringLiteral("--grab-after needs --grab DIR"));
  out.options = o;
  return out;
}

std::optional<std::string> assignParameter(sl::ParamSet& technique, sl::ParamSet& shared,
                                           const std::string& keyEqualsValue) {
  const auto eq = keyEqualsValue.find('=');
  if (eq == std::string::npos || eq == 0)
    return "--set expects KEY=VALUE, got '" + keyEqualsValue + "'";
  const std::string key = keyEqualsValue.substr(0, eq);
  if (technique.has(key)) return technique.assign(keyEqualsValue);
  if (shared.has(key)) return shared.assign(keyEqualsValue);
  std::string known;
  for (const sl::ParamSet* set : {&technique, &shared})
    for (const sl::ParamDecl& d : set->decls()) known += (known.empty() ? "" : ", ") + d.key;
  return "unknown parameter '" + key + "' (known: " + (known.empty() ? "none" : known) + ")";
}

std::string defaultTechniqueId() {
  return sl::Renderer::firstScreenTechniqueId();
}

std::optional<std::string> validateLaunchSettings(const std::string& techniqueId,
                                                  const QStringList& assignments) {
  const std::string id = techniqueId.empty() ? defaultTechniqueId() : techniqueId;
  const sl::TechniqueInfo* info = sl::Renderer::findTechnique(id);
  if (!info) {
    std::string known;
    for (const sl::TechniqueInfo& t : sl::Renderer::techniques())
      known += (known.empty() ? "" : ", ") + t.id;
    return "unknown technique '" + id + "' (known: " + known + ")";
  }
  sl::ParamSet technique(info->params);
  sl::ParamSet shared(sl::rendererParamDecls());
  for (const QString& kv : assignments)
    if (auto error = assignParameter(technique, shared, kv.toStdString())) return error;
  return std::nullopt;
}

}  // namespace sl::ui
