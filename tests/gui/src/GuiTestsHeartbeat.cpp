// The heartbeat test (see GuiTests.h): the render service keeps every GL call, trace and
// readback off the UI thread, so the event loop answers a 10 ms timer on time while slow
// techniques render continuously and while the camera is dragged over the view.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QMouseEvent>
#include <QTimer>

#include "GuiTests.h"
#include "window/MainWindow.h"
#include "view/ViewportWidget.h"

namespace sl::ui {

namespace {
constexpr int kBeatMs = 10;            ///< the heartbeat timer's interval
constexpr qint64 kStallBoundMs = 100;  ///< the longest stall allowed (the goal: 50 ms)
constexpr qint64 kPhaseMs = 6000;      ///< each phase (still, dragging) is watched this long
constexpr int kDragTickMs = 16;        ///< a mouse move every 16 ms while dragging
}  // namespace

bool GuiTests::heartbeat(const QString& dir) {
  ViewportWidget* view = w_.viewport();
  QElapsedTimer clock;
  clock.start();
  qint64 lastTick = -1, maxStall = 0;
  long ticks = 0;
  QTimer beat;
  beat.setTimerType(Qt::PreciseTimer);
  beat.setInterval(kBeatMs);
  QObject::connect(&beat, &QTimer::timeout, [&] {
    const qint64 now = clock.elapsed();
    if (lastTick >= 0) maxStall = std::max(maxStall, now - lastTick - kBeatMs);
    lastTick = now;
    ++ticks;
  });
  // Watches the event loop for `ms` (the heartbeat's longest stall), dragging the camera in a
  // circle with the left button when `drag`. Returns the stall and the frames shown meanwhile.
  auto watch = [&](qint64 ms, bool drag) {
    const QPointF centre(view->width() / 2.0, view->height() / 2.0);
    const double radius = std::min(view->width(), view->height()) / 4.0;
    auto at = [&](double t) {
      return QPointF(centre.x() + radius * std::cos(t), centre.y() + radius * std::sin(t));
    };
    QTimer mover;
    mover.setInterval(kDragTickMs);
    double phase = 0.0;
    QObject::connect(&mover, &QTimer::timeout, [&] {
      phase += 0.05;
      const QPointF p = at(phase);
      QMouseEvent move(QEvent::MouseMove, p, view->mapToGlobal(p), Qt::NoButton, Qt::LeftButton,
                       Qt::NoModifier);
      QCoreApplication::sendEvent(view, &move);
    });
    if (drag) {
      const QPointF p = at(0.0);
      QMouseEvent press(QEvent::MouseButtonPress, p, view->mapToGlobal(p), Qt::LeftButton,
                        Qt::LeftButton, Qt::NoModifier);
      QCoreApplication::sendEvent(view, &press);
      mover.start();
    }
    const std::uint64_t framesBefore = auto_.viewReadouts().framesDrawn;
    const std::uint64_t stoppedBefore = auto_.viewReadouts().framesStopped;
    lastTick = -1;
    maxStall = 0;
    ticks = 0;
    const qint64 start = clock.elapsed();
    beat.start();
    while (clock.elapsed() - start < ms) QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    beat.stop();
    mover.stop();
    if (drag) {
      const QPointF p = at(phase);
      QMouseEvent release(QEvent::MouseButtonRelease, p, view->mapToGlobal(p), Qt::LeftButton,
                          Qt::NoButton, Qt::NoModifier);
      QCoreApplication::sendEvent(view, &release);
    }
    struct Result {
      qint64 stallMs;
      long ticks;
      std::uint64_t frames, stopped;
    };
    return Result{maxStall, ticks, auto_.viewReadouts().framesDrawn - framesBefore,
                  auto_.viewReadouts().framesStopped - stoppedBefore};
  };

  qint64 worst = 0;
  for (const QString& technique :
       {QStringLiteral("fvsm"), QStringLiteral("virtual-tiled"), QStringLiteral("da-rtw")}) {
    if (auto e = auto_.setTechnique(technique)) {
      check(false, *e);
      continue;
    }
    waitForFrames(1, 300000);
    if (!view->continuous()) auto_.toggleContinuous();  // F6
    check(view->continuous(), tr("%1: rendering continuously").arg(technique));
    for (const bool drag : {false, true}) {
      const auto r = watch(kPhaseMs, drag);
      const char* what = drag ? "dragging" : "still";
      std::printf(
          "measure heartbeat technique=%s phase=%s max_stall_ms=%lld ticks=%ld frames_drawn=%llu "
          "stopped=%llu view=%dx%d\n",
          qPrintable(technique), what, static_cast<long long>(r.stallMs), r.ticks,
          static_cast<unsigned long long>(r.frames), static_cast<unsigned long long>(r.stopped),
          view->width(), view->height());
      check(r.ticks > kPhaseMs / kBeatMs / 4 && r.stallMs < kStallBoundMs,
            tr("%1, %2: the UI thread's longest stall %3 ms < %4 ms (%5 heartbeats, %6 frames "
               "drawn, %7 stopped by a newer view)")
                .arg(technique, QString::fromLatin1(what))
                .arg(r.stallMs)
                .arg(kStallBoundMs)
                .arg(r.ticks)
                .arg(r.frames)
                .arg(r.stopped));
      worst = std::max(worst, r.stallMs);
      if (drag && !dir.isEmpty() && QDir().mkpath(dir))
        w_.grab().toImage().save(
            QDir(dir).filePath(QStringLiteral("heartbeat-%1.png").arg(technique)));
    }
    auto_.toggleContinuous();  // F6 off
  }
  std::printf("measure heartbeat_worst_stall_ms=%lld\n", static_cast<long long>(worst));
  return true;
}

}  // namespace sl::ui
