// Waiting on the UI thread while handling events (OffThread.h).
#include "service/OffThread.h"

#include <exception>
#include <thread>

#include <QCoreApplication>
#include <QMetaObject>

namespace sl::ui {

void waitHandlingEvents(const std::atomic<bool>& done) {
  while (!done.load()) QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
}

void wakeUiThread() {
  if (QCoreApplication* app = QCoreApplication::instance())
    QMetaObject::invokeMethod(
        app, [] {}, Qt::QueuedConnection);
}

void runOffThread(const std::function<void()>& work) {
  std::atomic<bool> done{false};
  std::exception_ptr thrown;
  std::thread worker([&] {
    try {
      work();
    } catch (...) {
      thrown = std::current_exception();
    }
    done = true;
    wakeUiThread();
  });
  waitHandlingEvents(done);
  worker.join();
  if (thrown) std::rethrow_exception(thrown);
}

}  // namespace sl::ui
