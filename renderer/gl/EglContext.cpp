#include "EglContext.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <stdexcept>
#include <string>

namespace sl::gl {

struct EglContext::Impl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
};

namespace {
std::string eglErrorString() {
  char buf[32];
  std::snprintf(buf, sizeof buf, "0x%04x", eglGetError());
  return buf;
}
}  // namespace

EglContext::EglContext(bool debug) : impl_(std::make_unique<Impl>()) {
  const char* clientExts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  const std::string exts = clientExts ? clientExts : "";
  auto has = [&](const char* ext) { return exts.find(ext) != std::string::npos; };
  // Mesa's surfaceless platform first; else the first GPU of EGL's device platform (drivers
  // without Mesa's platform, e.g. NVIDIA's, offer that one for rendering without a window).
  if (has("EGL_MESA_platform_surfaceless")) {
    impl_->display =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (impl_->display != EGL_NO_DISPLAY && !eglInitialize(impl_->display, &major, &minor))
      impl_->display = EGL_NO_DISPLAY;
  }
  if (impl_->display == EGL_NO_DISPLAY && has("EGL_EXT_platform_device") &&
      has("EGL_EXT_device_enumeration")) {
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (eglQueryDevicesEXT(16, devices, &count))
      for (EGLint i = 0; i < count && impl_->display == EGL_NO_DISPLAY; ++i) {
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        EGLint major = 0, minor = 0;
        if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) impl_->display = d;
      }
  }
  if (impl_->display == EGL_NO_DISPLAY)
    throw std::runtime_error(
        "EGL: no display to render without a window: neither Mesa's surfaceless platform "
        "(EGL_MESA_platform_surfaceless; install libegl-mesa0) nor a device of "
        "EGL_EXT_platform_device could be initialised (" +
        eglErrorString() + ")");
  if (!epoxy_has_egl_extension(impl_->display, "EGL_KHR_surfaceless_context"))
    throw std::runtime_error("EGL: EGL_KHR_surfaceless_context is missing");
  if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("EGL: desktop OpenGL API unavailable");
  // Surfaceless rendering needs no config; fall back to any desktop-GL config.
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!epoxy_has_egl_extension(impl_->display, "EGL_KHR_no_config_context")) {
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0,
                                    EGL_NONE};
    EGLint count = 0;
    if (!eglChooseConfig(impl_->display, configAttribs, &config, 1, &count) || count == 0)
      throw std::runtime_error("EGL: no config with desktop OpenGL");
  }
  const EGLint ctxAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                               4,
                               EGL_CONTEXT_MINOR_VERSION,
                               5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                               EGL_CONTEXT_OPENGL_DEBUG,
                               debug ? EGL_TRUE : EGL_FALSE,
                               EGL_NONE};
  impl_->context = eglCreateContext(impl_->display, config, EGL_NO_CONTEXT, ctxAttribs);
  if (impl_->context == EGL_NO_CONTEXT)
    throw std::runtime_error("EGL: could not create an OpenGL 4.5 core context (" +
                             eglErrorString() + "); ShadowLab needs OpenGL 4.5");
  makeCurrent();
  if (epoxy_gl_version() < 45)
    throw std::runtime_error("OpenGL 4.5 core is required, the driver gives " +
                             std::to_string(epoxy_gl_version() / 10) + "." +
                             std::to_string(epoxy_gl_version() % 10));
}

EglContext::~EglContext() {
  if (impl_->display != EGL_NO_DISPLAY) {
    eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (impl_->context != EGL_NO_CONTEXT) eglDestroyContext(impl_->display, impl_->context);
    eglTerminate(impl_->display);
  }
}

void EglContext::makeCurrent() {
  if (!eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl_->context))
    throw std::runtime_error("EGL: eglMakeCurrent failed (" + eglErrorString() + ")");
}

std::string EglContext::driverDescription() const {
  auto str = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "?");
  };
  return str(GL_RENDERER) + ", OpenGL " + str(GL_VERSION);
}

}  // namespace sl::gl
