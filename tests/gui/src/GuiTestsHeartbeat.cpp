// The heartbeat test (see GuiTests.h): the render service keeps every GL call, trace and
// readback off the UI thread, so the event loop answers a 10 ms timer on time while slow
// techniques render continuously and while the camera is dragged over the view.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
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

/// A 10 ms timer on the UI thread and its longest stall (gap minus interval) since restart().
struct HeartbeatClock {
  HeartbeatClock() {
    clock.start();
    beat.setTimerType(Qt::PreciseTimer);
    beat.setInterval(kBeatMs);
    QObject::connect(&beat, &QTimer::timeout, [this] {
      const qint64 now = clock.elapsed();
      if (lastTick >= 0) maxStall = std::max(maxStall, now - lastTick - kBeatMs);
      lastTick = now;
      ++ticks;
    });
  }
  QElapsedTimer clock;
  QTimer beat;
  qint64 lastTick = -1, maxStall = 0;
  long ticks = 0;
};

bool GuiTests::heartbeat(const QString& dir) {
  ViewportWidget* view = w_.viewport();
  HeartbeatClock hb;
  QElapsedTimer& clock = hb.clock;
  QTimer& beat = hb.beat;
  qint64& lastTick = hb.lastTick;
  qint64& maxStall = hb.maxStall;
  long& ticks = hb.ticks;
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
    if (!view->frames()->continuous()) auto_.toggleContinuous();  // F6
    check(view->frames()->continuous(), tr("%1: rendering continuously").arg(technique));
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
  worst = std::max(worst, heartbeatActions(dir, hb));
  std::printf("measure heartbeat_worst_stall_ms=%lld\n", static_cast<long long>(worst));
  return true;
}

qint64 GuiTests::heartbeatActions(const QString& dir, HeartbeatClock& hb) {
  // The actions that wait for the render thread (an error trace, a shader reload, an export,
  // a full-size grab, the equal-memory search: RenderService::call) handle events while they
  // wait: the heartbeat goes on. Each is taken from a timer, as a key press would be.
  QElapsedTimer& clock = hb.clock;
  const QString out = dir.isEmpty() ? QDir::tempPath() : dir;
  QDir().mkpath(out);
  if (auto e = auto_.setTechnique(QStringLiteral("da-rtw"))) check(false, *e);
  auto_.setSplit(QStringLiteral("uniform"));
  waitForFrames(2, 300000);
  qint64 worst = 0;
  auto during = [&](const QString& what, const std::function<bool()>& action) {
    // The watch starts at the first beat's due time, and its last gap counts: an action that
    // held the thread from before the first beat to the end is a stall too.
    const qint64 start = clock.elapsed();
    hb.lastTick = start;
    hb.maxStall = 0;
    hb.ticks = 0;
    bool done = false, ok = false;
    hb.beat.start();
    QTimer::singleShot(2 * kBeatMs, [&] {
      ok = action();
      done = true;
    });
    // The action, then a few beats after it.
    while ((!done || clock.elapsed() - start < 300) && clock.elapsed() - start < 300000)
      QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    hb.beat.stop();
    const qint64 maxStall = std::max(hb.maxStall, clock.elapsed() - hb.lastTick - kBeatMs);
    const long ticks = hb.ticks;
    const qint64 took = clock.elapsed() - start;
    std::printf("measure heartbeat action=\"%s\" max_stall_ms=%lld ticks=%ld took_ms=%lld\n",
                qPrintable(what), static_cast<long long>(maxStall), ticks,
                static_cast<long long>(took));
    check(done && ok, tr("%1: done").arg(what));
    check(maxStall < kStallBoundMs, tr("%1: the UI thread's longest stall %2 ms < %3 ms (%4 "
                                       "heartbeats in %5 ms)")
                                        .arg(what)
                                        .arg(maxStall)
                                        .arg(kStallBoundMs)
                                        .arg(ticks)
                                        .arg(took));
    worst = std::max(worst, maxStall);
  };
  during(QStringLiteral("O (the error overlay: a frame and the exact trace)"), [&] {
    const bool pressed = auto_.trigger(QKeySequence(Qt::Key_O));
    return pressed && auto_.waitForFrames(1);  // O queues the error: wait until it is drawn
  });
  during(QStringLiteral("Ctrl+E (compute the error now)"),
         [&] { return auto_.trigger(QKeySequence(Qt::CTRL | Qt::Key_E)); });
  during(QStringLiteral("F5 (reload the shaders)"),
         [&] { return auto_.trigger(QKeySequence(Qt::Key_F5)); });
  during(QStringLiteral("Export figure"), [&] {
    return !auto_.exportFigure(QDir(out).filePath(QStringLiteral("heartbeat-figure.png")));
  });
  during(QStringLiteral("Save viewport image"), [&] {
    return !auto_.saveViewImage(QDir(out).filePath(QStringLiteral("heartbeat-view.png")));
  });
  during(QStringLiteral("Equal memory"), [&] {
    auto_.setEqualMemory(true);
    return true;
  });
  auto_.setEqualMemory(false);
  auto_.setSplit(QString());
  // A 260 k-triangle glTF file (heartbeat.sh writes the generated atrium): its parse and BVH
  // run off the UI thread.
  const QString big = qEnvironmentVariable("SHADOWLAB_HEARTBEAT_SCENE");
  check(!big.isEmpty(), QStringLiteral("SHADOWLAB_HEARTBEAT_SCENE names a large scene"));
  if (!big.isEmpty())
    during(QStringLiteral("opening %1").arg(QFileInfo(big).fileName()),
           [&] { return auto_.openScene(big); });
  return worst;
}

}  // namespace sl::ui
