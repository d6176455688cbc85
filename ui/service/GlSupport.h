// OpenGL requirement of the GUI, checked before any window opens: the render service's
// context (surfaceless EGL, OpenGL 4.5 core, as the CLI's) is created once on a thread of its
// own and its problem named. The UI thread itself never makes a context current.
#pragma once

#include <optional>

#include <QString>

namespace sl::ui {

/// Creates a throw-away render context on a separate thread and checks it, so that a missing
/// OpenGL 4.5 is reported before any window opens. On success `description` gets the
/// driver's GL_RENDERER and version.
std::optional<QString> probeOpenGL(QString* description = nullptr);

}  // namespace sl::ui
