// The GUI's command line: `shadowlab [--scene NAME|FILE] [--technique ID]
// [--set KEY=VALUE]... [--lesson N|NAME|FILE] [--course NAME] [--open-session FILE] [--presenter]
// [--grab DIR --grab-after N]`, and the GL-free checks of the technique and parameter values
// against their declarations (before any window opens).
#pragma once

#include <optional>
#include <string>

#include <QString>
#include <QStringList>

#include "algo/Params.h"

namespace sl::ui {

struct LaunchOptions {
  QString scene;            ///< built-in name or .gltf/.glb path; empty: last used / default
  QString technique;        ///< technique id; empty: last used / the renderer's first
  QStringList assignments;  ///< KEY=VALUE, applied in order
  QString grabDir;          ///< non-empty: render, save the window and panels there, quit
  int grabAfterFrames = 5;
  QString
      lesson;  ///< non-empty: start this lesson (number, file base name or path; --open-session)
  QString course;      ///< non-empty: start this course (scenes/courses.json) at its first lesson
  int lessonCase = 1;  ///< --lesson-case: the lesson's case (1-based)
  bool presenter = false;  ///< start in presenter mode (PresenterMode.h)
  bool grab() const { return !grabDir.isEmpty(); }
};

/// Outcome of parsing: options, or an exit code with the text to print (help, version, or
/// an error for stderr).
struct ParsedLaunch {
  std::optional<LaunchOptions> options;
  int exitCode = 0;
  QString message;
  bool messageIsError = false;
};
ParsedLaunch parseLaunchOptions(const QStringList& arguments);

/// Applies "key=value" to whichever of the two sets declares the key (technique first).
/// Error: the ParamSet's message, or "unknown parameter" naming the keys of both sets.
std::optional<std::string> assignParameter(sl::ParamSet& technique, sl::ParamSet& shared,
                                           const std::string& keyEqualsValue);

/// Checks a technique id (empty: the first technique) and the assignments against the
/// declarations, without GL. Error: one line naming the culprit.
std::optional<std::string> validateLaunchSettings(const std::string& techniqueId,
                                                  const QStringList& assignments);

/// The id used when none is given: the technique declared TechniqueInfo::firstScreen, else (a
/// build without it) the first declared technique.
std::string defaultTechniqueId();

}  // namespace sl::ui
