// Context checks for the GUI (see GlSupport.h). Uses Qt's own function table only to read
// strings; all rendering goes through sl::Renderer.
#include "GlSupport.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QSurfaceFormat>

namespace sl::ui {

namespace {
constexpr int kGlMajor = 4;
constexpr int kGlMinor = 5;

QString profileName(QSurfaceFormat::OpenGLContextProfile profile) {
  switch (profile) {
    case QSurfaceFormat::CoreProfile:
      return QStringLiteral("core");
    case QSurfaceFormat::CompatibilityProfile:
      return QStringLiteral("compatibility");
    case QSurfaceFormat::NoProfile:
      break;
  }
  return QStringLiteral("no");
}

QString glString(QOpenGLContext& context, unsigned name) {
  const auto* s = context.functions()->glGetString(name);
  return s ? QString::fromLatin1(reinterpret_cast<const char*>(s)) : QString();
}
}  // namespace

QSurfaceFormat requiredSurfaceFormat() {
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(kGlMajor, kGlMinor);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setOption(QSurfaceFormat::DebugContext);
  format.setDepthBufferSize(24);
  format.setStencilBufferSize(8);
  return format;
}

std::optional<QString> checkContext(const QOpenGLContext& context) {
  if (!context.isValid())
    return QStringLiteral(
               "no OpenGL context could be created (platform '%1'; ShadowLab needs "
               "OpenGL %2.%3 core through GLX or EGL)")
        .arg(QGuiApplication::platformName())
        .arg(kGlMajor)
        .arg(kGlMinor);
  const QSurfaceFormat f = context.format();
  const bool versionOk =
      f.majorVersion() > kGlMajor || (f.majorVersion() == kGlMajor && f.minorVersion() >= kGlMinor);
  if (context.isOpenGLES() || !versionOk || f.profile() != QSurfaceFormat::CoreProfile)
    return QStringLiteral("OpenGL %1.%2 core profile required, got %3 %4.%5 %6 profile")
        .arg(kGlMajor)
        .arg(kGlMinor)
        .arg(context.isOpenGLES() ? QStringLiteral("OpenGL ES") : QStringLiteral("OpenGL"))
        .arg(f.majorVersion())
        .arg(f.minorVersion())
        .arg(profileName(f.profile()));
  return std::nullopt;
}

std::optional<QString> probeOpenGL(QString* description) {
  // These platforms create contexts but cannot show a QOpenGLWidget (Qt crashes or draws
  // nothing): say so instead of failing later.
  const QString platform = QGuiApplication::platformName();
  if (platform == QLatin1String("offscreen") || platform == QLatin1String("minimal") ||
      platform == QLatin1String("vnc") || platform == QLatin1String("linuxfb"))
    return QStringLiteral(
               "the Qt platform '%1' cannot show an OpenGL viewport; run under an X "
               "server (xcb, e.g. Xvfb) or Wayland, or use shadowlab-cli headless")
        .arg(platform);
  QOffscreenSurface surface;
  surface.setFormat(requiredSurfaceFormat());
  surface.create();
  QOpenGLContext context;
  context.setFormat(requiredSurfaceFormat());
  if (!context.create())
    return QStringLiteral(
               "no OpenGL context could be created on platform '%1' (ShadowLab needs "
               "OpenGL %2.%3 core)")
        .arg(platform)
        .arg(kGlMajor)
        .arg(kGlMinor);
  if (auto problem = checkContext(context)) return problem;
  if (!surface.isValid() || !context.makeCurrent(&surface))
    return QStringLiteral("the OpenGL context cannot be made current on an offscreen surface");
  // What the driver really gave (the QSurfaceFormat can echo the request).
  QOpenGLFunctions* gl = context.functions();
  GLint major = 0, minor = 0, profileMask = 0;
  gl->glGetIntegerv(GL_MAJOR_VERSION, &major);
  gl->glGetIntegerv(GL_MINOR_VERSION, &minor);
  gl->glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profileMask);
  const QString renderer = glString(context, GL_RENDERER);
  context.doneCurrent();
  const bool versionOk = major > kGlMajor || (major == kGlMajor && minor >= kGlMinor);
  if (!versionOk || !(profileMask & GL_CONTEXT_CORE_PROFILE_BIT))
    return QStringLiteral("OpenGL %1.%2 core profile required, the driver (%3) gave %4.%5 %6")
        .arg(kGlMajor)
        .arg(kGlMinor)
        .arg(renderer)
        .arg(major)
        .arg(minor)
        .arg(profileMask & GL_CONTEXT_CORE_PROFILE_BIT ? QStringLiteral("core")
                                                       : QStringLiteral("compatibility"));
  if (description) *description = renderer;
  return std::nullopt;
}

}  // namespace sl::ui
