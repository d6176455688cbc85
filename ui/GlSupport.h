// OpenGL context requirements of the GUI: the surface format every window asks for
// (4.5 core, debug) and a check that names what a context lacks. No GL headers here.
#pragma once

#include <optional>

#include <QString>

class QOpenGLContext;
class QSurfaceFormat;

namespace sl::ui {

/// 4.5 core profile with the debug flag, 24-bit depth, 8-bit stencil. Set it as the
/// default (QSurfaceFormat::setDefaultFormat) before the QApplication is created.
QSurfaceFormat requiredSurfaceFormat();

/// An error naming what `context` lacks (not valid, version below 4.5, not core), or
/// nothing when the renderer can use it.
std::optional<QString> checkContext(const QOpenGLContext& context);

/// Creates a throw-away context on an offscreen surface and checks it, so that a missing
/// GL 4.5 is reported before any window opens. On success `description` gets the
/// GL_RENDERER string.
std::optional<QString> probeOpenGL(QString* description = nullptr);

}  // namespace sl::ui
