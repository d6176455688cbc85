// The render service: ONE thread that owns the GUI's OpenGL context and every renderer of
// the window (the view's main and split halves, the outside view they draw, the Charts
// panel's sweeps, error traces, probes, exports). The UI thread never calls GL: it posts
// jobs here and receives their results as queued calls (qrenderdoc's ReplayManager is the
// model).
//
// Every job may carry a tag (RenderTag below). A newer job with the same tag replaces the one
// of that tag not yet started: the older never runs, post() returns true and the older's
// `dropped` callback runs (AsyncInvoke(tag, ...) in qrenderdoc). Untagged jobs run in the
// order posted and are never replaced. cancel(tag) drops the unstarted job of a tag and asks
// the one in progress to stop when it has that tag. Frames are jobs whose tag starts with
// "frame:": they run only when no other job waits, so a frame tag is a slot holding at most
// one frame not yet started (a camera drag does not queue frames); submitFrame() may also ask
// the frame of its tag in progress to stop (the renderer reads the stop flag between its
// steps and units; a stopped frame is dropped, never shown or measured). A blocking call() is
// for explicit actions only (exports, scripted reads): it stops the frame in progress and
// runs before anything else queued. Every job either runs or is dropped, once; `dropped`
// runs on the thread whose action dropped it (the poster's for a replacement, the
// canceller's, the one destroying the service), outside the service's lock.
//
// The queue policy and the thread are plain C++ (render/JobQueue.h, render/RenderWorker.h:
// CPU-tested with a fake context); no GL header here: the context and renderers live in the
// .cpp.
#pragma once

#include <memory>
#include <string>

#include <QObject>
#include <QString>

#include "render/RenderContext.h"
#include "render/RenderWorker.h"

namespace sl::ui {

/// The tags of the window's render jobs: one unstarted job per tag.
struct RenderTag {
  static constexpr char kViewFrame[] = "frame:view";  ///< the view's frame (both halves)
  static constexpr char kError[] = "error";           ///< a still view's error trace
  static constexpr char kProbe[] = "probe";           ///< the hover probe's readback
  static constexpr char kCharts[] = "charts";         ///< the Charts panel's sweep frame
  static constexpr char kVariants[] = "variants";     ///< a panel's parameter variants
  static constexpr char kCall[] = "call";  ///< an action the UI waits for (call()); Esc stops it
};

class RenderService : public QObject {
  Q_OBJECT

 public:
  using Job = RenderWorker::Job;
  using Dropped = RenderWorker::Dropped;
  /// What the render thread is doing: a frame or job in progress and for how long.
  using Activity = RenderWorker::Activity;

  explicit RenderService(QObject* parent = nullptr);
  /// Stops the job in progress, drops queued work (their `dropped` run here), frees every
  /// renderer with the context current and joins the thread.
  ~RenderService() override;

  /// Starts the thread and creates its context; ready() or failed() follows (queued).
  void start();
  bool isRunning() const;

  /// Puts `job` in the view's frame slot (RenderTag::kViewFrame), replacing a frame that has
  /// not started (true: one was replaced; it never runs). `stopRunning`: also ask the view's
  /// frame in progress to stop (the view changed: its result would be stale).
  bool submitFrame(Job job, bool stopRunning);
  /// Runs `job` untagged, after the jobs queued before it (before any frame).
  void post(Job job);
  /// Runs `job` under `tag`: replaces an unstarted job of that tag (true; its `dropped`
  /// runs before this returns).
  bool post(const std::string& tag, Job job, Dropped dropped = {});
  /// Drops the unstarted job of `tag` and asks the one in progress to stop if it has it.
  void cancel(const std::string& tag);
  /// Runs `job` on the render thread now (after the job in progress, which is asked to stop
  /// if it is a frame) and waits for it: from the UI thread, the wait goes on handling events
  /// (the window is drawn, timers fire, input arrives), `note` says in the view what runs
  /// (callStarted / callEnded) and cancelCall() (Esc) asks the job to stop; `job` must not read
  /// what the UI thread may change meanwhile. False when it did not run (the service is not
  /// running, or the job was cancelled before it started). Rethrows what the job threw.
  bool call(const Job& job, const QString& note = {});
  /// Asks the call() in progress (and those queued) to stop: their renderers stop between two
  /// steps; what the caller reads of a stopped frame says so.
  void cancelCall();
  /// How many call()s the UI thread is waiting for (nested when an action is taken during one).
  int callsWaiting() const { return callsWaiting_; }

  Activity activity() const;

 Q_SIGNALS:
  /// The context exists: `description` is its GL_RENDERER / version.
  void ready(const QString& description);
  /// The context could not be made (the message names what is missing).
  void failed(const QString& message);
  /// The UI thread waits for a call(): `note` says what runs ("" for a scripted read).
  void callStarted(const QString& note);
  /// The call() ended (ran, stopped or dropped); `stillWaiting` other calls are waited for.
  void callEnded(int stillWaiting);

 private:
  std::unique_ptr<RenderWorker> worker_;
  int callsWaiting_ = 0;
};

}  // namespace sl::ui
