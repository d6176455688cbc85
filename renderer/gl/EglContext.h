// A headless OpenGL 4.5 core context on EGL's surfaceless platform (Mesa), for the
// command-line tool and the renderer tests: no X server, no window.
#pragma once

#include <memory>
#include <string>

namespace sl::gl {

class EglContext {
 public:
  /// Creates the context and makes it current. Throws std::runtime_error with a message
  /// naming what is missing (EGL platform, extension, GL 4.5 core).
  explicit EglContext(bool debug = true);
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;
  void makeCurrent();
  /// GL_RENDERER and GL_VERSION of the context (current on the calling thread).
  std::string driverDescription() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sl::gl
