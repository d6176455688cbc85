// The render service's thread (RenderService.h) without Qt or GL: one thread that makes its
// context through an injected factory and then runs the JobQueue's jobs, one at a time, with
// one stop flag. The window's factory makes the EGL context and its renderers
// (RenderService.cpp); the CPU tests give it a fake one (tests/cpu/JobQueueTest.cpp).
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "render/JobQueue.h"
#include "render/RenderContext.h"

namespace sl::ui {

class RenderWorker {
 public:
  using Job = JobQueue::Job;
  using Dropped = JobQueue::Dropped;
  /// Makes the thread's context, on the thread; throws (what() says what is missing) when it
  /// cannot. `stopFlag` is the flag the context's stopFlag() returns and its renderers read.
  using ContextFactory =
      std::function<std::unique_ptr<RenderContext>(const std::atomic<bool>& stopFlag)>;
  /// Told on the render thread: the context exists (its glDescription()), or could not be
  /// made (the message).
  struct Events {
    std::function<void(const std::string& description)> ready;
    std::function<void(const std::string& message)> failed;
  };

  /// What the render thread is doing: a frame or job in progress and for how long.
  struct Activity {
    bool busy = false;
    bool frame = false;  ///< a frame (a "frame:" tag) is in progress, else a job
    std::string tag;     ///< the tag of the work in progress ("" untagged)
    double elapsedMs = 0.0;
    std::uint64_t framesStopped = 0;  ///< frames asked to stop since the start
  };

  RenderWorker(ContextFactory makeContext, Events events);
  /// stop().
  ~RenderWorker();
  RenderWorker(const RenderWorker&) = delete;
  RenderWorker& operator=(const RenderWorker&) = delete;

  /// Starts the thread; it makes the context, then Events::ready or Events::failed. Jobs posted
  /// before wait for it; when the context fails they are dropped (and every later one).
  void start();
  /// The shutdown: asks the job in progress to stop, drops every queued job (each `dropped`
  /// runs here, on the calling thread, in the order they would have run), waits for the job in
  /// progress, joins; the context is destroyed on the render thread. Later jobs are dropped at
  /// once. Idempotent.
  void stop();
  /// Started, the context made, not stopped.
  bool running() const;

  /// Queues `job` under `tag` ("" untagged: runs in order posted, never replaced). An unstarted
  /// job of the same tag is replaced: it never runs, its `dropped` runs here before post
  /// returns, and post returns true. A frame tag ("frame:...") runs only when no other job
  /// waits. A job the worker refuses (stopped, or its context failed) is dropped at once.
  bool post(std::string tag, Job job, Dropped dropped = {});
  /// post() of a frame tag; `stopRunning`: also asks a job in progress with the same tag to
  /// stop (its result would be stale).
  bool submitFrame(std::string tag, Job job, bool stopRunning, Dropped dropped = {});
  /// Drops every unstarted job tagged `tag` (each `dropped` runs here) and asks the job in
  /// progress to stop when it has that tag. Untagged work is never cancelled.
  void cancel(const std::string& tag);
  /// Runs `job` on the render thread before anything queued (after the job in progress, which
  /// is asked to stop if it is a frame) and waits for it; rethrows what it threw. From a job,
  /// runs it at once. False when it never ran (not started, failed, or stopped meanwhile).
  bool call(const Job& job);
  /// What call() runs, without the wait: queues `job` under `tag` before anything queued
  /// (a frame in progress is asked to stop) and returns at once. `done(ran, thrown)` runs
  /// exactly once: on the render thread after the job (true; `thrown` what it threw, else
  /// null), or where the job is dropped (false: cancel(tag), stop(), or refused, then before
  /// this returns). From a job it runs the job at once. The caller keeps what `job` refers to
  /// alive until `done`.
  using CallDone = std::function<void(bool ran, std::exception_ptr thrown)>;
  void callAsync(std::string tag, Job job, CallDone done);

  Activity activity() const;

 private:
  using Entry = JobQueue::Entry;
  bool enqueue(Entry entry, bool stopRunning);
  /// Raises the stop flag for the job in progress (counted when it is a frame). Lock held.
  void askRunningToStop();
  static void notifyDropped(std::vector<Entry>& entries);
  void run();

  const ContextFactory makeContext_;
  const Events events_;
  mutable std::mutex m_;
  std::condition_variable cv_;
  JobQueue queue_;
  bool stopping_ = false, started_ = false, failed_ = false;
  bool busy_ = false;
  std::string runningTag_;
  std::uint64_t framesStopped_ = 0;
  std::chrono::steady_clock::time_point since_;
  std::atomic<bool> stopFlag_{false};
  std::thread thread_;
  std::unique_ptr<RenderContext> context_;  ///< render thread only
};

}  // namespace sl::ui
