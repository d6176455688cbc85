// Work off the UI thread (OffThread.h).
#include "service/OffThread.h"

#include <atomic>
#include <exception>
#include <memory>
#include <thread>

#include <QCoreApplication>
#include <QMetaObject>

namespace sl::ui {

void runOffThread(const std::function<void()>& work) {
  auto done = std::make_shared<std::atomic<bool>>(false);
  std::exception_ptr thrown;
  QCoreApplication* app = QCoreApplication::instance();
  std::thread worker([&work, &thrown, done, app] {
    try {
      work();
    } catch (...) {
      thrown = std::current_exception();
    }
    *done = true;
    // An empty queued call wakes the UI thread's event loop.
    if (app)
      QMetaObject::invokeMethod(
          app, [] {}, Qt::QueuedConnection);
  });
  while (!done->load()) QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
  worker.join();
  if (thrown) std::rethrow_exception(thrown);
}

}  // namespace sl::ui
