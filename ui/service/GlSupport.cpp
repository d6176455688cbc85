#include "service/GlSupport.h"

#include <exception>
#include <string>
#include <thread>

#include "gl/EglContext.h"

namespace sl::ui {

std::optional<QString> probeOpenGL(QString* description) {
  std::optional<QString> problem;
  std::string driver;
  std::thread probe([&] {
    try {
      sl::gl::EglContext context(false);
      driver = context.driverDescription();
    } catch (const std::exception& e) {
      problem = QStringLiteral("no OpenGL 4.5 core render context: %1").arg(e.what());
    }
  });
  probe.join();
  if (!problem && description) *description = QString::fromStdString(driver);
  return problem;
}

}  // namespace sl::ui
