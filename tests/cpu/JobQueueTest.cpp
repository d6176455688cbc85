// The render service's queue policy (ui/render/JobQueue) and its thread (ui/render/RenderWorker)
// with a fake context, no GL: replacement by tag, order, frames after jobs, cancel, the
// blocking call, shutdown. Real threads; every wait is on a promise or the stop flag (bounded,
// so a broken policy fails instead of hanging).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <future>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "Watchdog.h"
#include "render/JobQueue.h"
#include "render/RenderWorker.h"

namespace {

using sl::ui::JobQueue;
using sl::ui::RenderContext;
using sl::ui::RenderWorker;
using Strings = std::vector<std::string>;

constexpr std::chrono::milliseconds kLimit{5000};

/// The context a job sees: the stop flag, no renderer. Says on which thread it died.
class FakeContext : public RenderContext {
 public:
  FakeContext(const std::atomic<bool>& stopFlag, std::promise<std::thread::id>& destroyedOn)
      : stopFlag_(stopFlag), destroyedOn_(destroyedOn) {}
  ~FakeContext() override { destroyedOn_.set_value(std::this_thread::get_id()); }
  sl::Renderer& renderer(const std::string&) override {
    throw std::logic_error("the fake context has no renderer");
  }
  sl::Renderer* existing(const std::string&) override { return nullptr; }
  const std::atomic<bool>& stopFlag() const override { return stopFlag_; }
  const std::string& glDescription() const override { return description_; }

 private:
  const std::atomic<bool>& stopFlag_;
  std::promise<std::thread::id>& destroyedOn_;
  std::string description_ = "fake";
};

/// What ran or was dropped, in order, from any thread.
class Log {
 public:
  void add(const std::string& s) {
    std::lock_guard lock(m_);
    entries_.push_back(s);
  }
  Strings entries() const {
    std::lock_guard lock(m_);
    return entries_;
  }

 private:
  mutable std::mutex m_;
  Strings entries_;
};

/// A job that holds the render thread until the test opens it: `started` says it runs and
/// `stopFlag` where its stop flag is.
struct Gate {
  std::promise<void> started;
  std::promise<void> opened;
  std::shared_future<void> open = opened.get_future().share();
  std::atomic<const std::atomic<bool>*> stopFlag{nullptr};
  bool released = false;
  void release() {
    if (!std::exchange(released, true)) opened.set_value();
  }
};

/// True when `f` is ready within kLimit (else a test failure naming `what`).
template <class Future>
bool readyWithin(Future& f, const std::string& what) {
  if (f.wait_for(kLimit) == std::future_status::ready) return true;
  ADD_FAILURE() << what << " did not happen within " << kLimit.count() << " ms";
  return false;
}

/// A worker with the fake context and a log, started unless told; its gates are opened and it
/// is stopped (within kLimit) when the rig goes.
class Rig {
 public:
  explicit Rig(bool failContext = false, bool start = true) {
    RenderWorker::Events events;
    events.ready = [this](const std::string& d) { log.add("ready " + d); };
    events.failed = [this](const std::string& m) { log.add("failed " + m); };
    worker = std::make_unique<RenderWorker>(
        [this, failContext](const std::atomic<bool>& stop) -> std::unique_ptr<RenderContext> {
          renderThread = std::this_thread::get_id();
          if (failContext) throw std::runtime_error("no display");
          return std::make_unique<FakeContext>(stop, destroyedOn);
        },
        std::move(events));
    if (start) worker->start();
  }
  ~Rig() {
    for (auto& g : gates) g->release();
    sl::test::finishesWithin(std::chrono::duration_cast<std::chrono::milliseconds>(kLimit),
                             "stopping the worker", [this] { worker->stop(); });
  }

  /// A job that logs `name`.
  RenderWorker::Job logs(const std::string& name) {
    return [this, name](RenderContext&) { log.add(name); };
  }
  /// A `dropped` callback that logs "dropped `name`".
  RenderWorker::Dropped drops(const std::string& name) {
    return [this, name] { log.add("dropped " + name); };
  }
  /// Posts a job under `tag` that logs `name` and holds the thread until the gate opens; returns
  /// once it runs.
  std::shared_ptr<Gate> hold(const std::string& tag, const std::string& name) {
    auto gate = std::make_shared<Gate>();
    gates.push_back(gate);
    auto job = [this, gate, name](RenderContext& c) {
      gate->stopFlag = &c.stopFlag();
      log.add(name);
      gate->started.set_value();
      gate->open.wait();
    };
    if (JobQueue::isFrameTag(tag))
      worker->submitFrame(tag, job, false);
    else
      worker->post(tag, job);
    std::future<void> started = gate->started.get_future();
    readyWithin(started, name + " starting");
    return gate;
  }
  /// Waits until everything posted before has run: a frame runs after every job queued before
  /// it, and frames in order.
  void drain() {
    auto done = std::make_shared<std::promise<void>>();
    worker->post("frame:drain", [done](RenderContext&) { done->set_value(); });
    std::future<void> f = done->get_future();
    readyWithin(f, "the queue draining");
  }
  /// Opens `gate` and waits until everything posted has run: the log then.
  Strings releaseAndDrain(Gate& gate) {
    gate.release();
    drain();
    return ran();
  }
  /// The log without the context's "ready" line.
  Strings ran() {
    Strings out;
    for (const std::string& s : log.entries())
      if (!s.starts_with("ready ")) out.push_back(s);
    return out;
  }

  Log log;
  std::promise<std::thread::id> destroyedOn;
  std::thread::id renderThread;
  std::unique_ptr<RenderWorker> worker;
  std::vector<std::shared_ptr<Gate>> gates;
};

// --- The policy alone (JobQueue: no thread).

JobQueue::Entry entry(const std::string& tag, const std::string& name, Strings& ran) {
  return {tag, [&ran, name](RenderContext&) { ran.push_back(name); }, {}};
}

TEST(JobQueue, OrderIsCallsThenJobsThenFramesAndANewerTagReplacesTheOlder) {
  std::atomic<bool> stop{false};
  std::promise<std::thread::id> gone;
  {
    FakeContext c(stop, gone);
    JobQueue q;
    Strings unused;
    EXPECT_FALSE(q.push(entry("frame:view", "f1", unused)));
    EXPECT_FALSE(q.push(entry("", "a", unused)));
    EXPECT_FALSE(q.push(entry("error", "e1", unused)));
    EXPECT_FALSE(q.push(entry("", "b", unused)));
    std::optional<JobQueue::Entry> older = q.push(entry("error", "e2", unused));
    ASSERT_TRUE(older);
    older->job(c);
    EXPECT_EQ(unused, Strings{"e1"});  // the one returned is the older
    EXPECT_TRUE(q.push(entry("frame:view", "f2", unused)));
    EXPECT_FALSE(q.push(entry("frame:split", "s", unused)));
    q.pushFront(entry("", "call", unused));
    EXPECT_EQ(q.size(), 6u);
    unused.clear();
    while (std::optional<JobQueue::Entry> e = q.pop()) e->job(c);
    // The replacing job takes its place at the back (qrenderdoc); frames after every job.
    EXPECT_EQ(unused, (Strings{"call", "a", "b", "e2", "f2", "s"}));
    EXPECT_TRUE(q.empty());
  }
}

TEST(JobQueue, TakeRemovesOnlyItsTagAndTakeAllKeepsTheRunOrder) {
  JobQueue q;
  Strings unused;
  q.push(entry("frame:view", "f", unused));
  q.push(entry("probe", "p", unused));
  q.push(entry("", "u", unused));
  q.push(entry("charts", "c", unused));
  EXPECT_TRUE(q.take("").empty());  // untagged work is never cancelled by name
  std::vector<JobQueue::Entry> probes = q.take("probe");
  ASSERT_EQ(probes.size(), 1u);
  EXPECT_EQ(probes[0].tag, "probe");
  EXPECT_EQ(q.size(), 3u);
  std::vector<JobQueue::Entry> all = q.takeAll();
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].tag, "");
  EXPECT_EQ(all[1].tag, "charts");
  EXPECT_EQ(all[2].tag, "frame:view");
  EXPECT_TRUE(q.empty());
}

// --- The worker: real threads.

TEST(RenderWorker, ANewerJobOfATagReplacesTheUnstartedOneWhichNeverRuns) {
  Rig rig;
  std::shared_ptr<Gate> gate = rig.hold("", "hold");
  EXPECT_FALSE(rig.worker->post("probe", rig.logs("probe 1"), rig.drops("probe 1")));
  EXPECT_TRUE(rig.worker->post("probe", rig.logs("probe 2"), rig.drops("probe 2")));
  // Told before post returned, on this thread.
  EXPECT_EQ(rig.ran(), (Strings{"hold", "dropped probe 1"}));
  EXPECT_EQ(rig.releaseAndDrain(*gate), (Strings{"hold", "dropped probe 1", "probe 2"}));
}

TEST(RenderWorker, DifferentTagsAndUntaggedJobsAllRunInTheOrderPosted) {
  Rig rig;
  std::shared_ptr<Gate> gate = rig.hold("", "hold");
  EXPECT_FALSE(rig.worker->post("error", rig.logs("error")));
  rig.worker->post("", rig.logs("u1"));
  EXPECT_FALSE(rig.worker->post("probe", rig.logs("probe")));
  rig.worker->post("", rig.logs("u2"));
  rig.worker->post("", rig.logs("u3"));
  EXPECT_FALSE(rig.worker->post("charts", rig.logs("charts")));
  EXPECT_EQ(rig.releaseAndDrain(*gate),
            (Strings{"hold", "error", "u1", "probe", "u2", "u3", "charts"}));
}

TEST(RenderWorker, FramesRunAfterQueuedJobsOnePerTag) {
  Rig rig;
  std::shared_ptr<Gate> gate = rig.hold("", "hold");
  EXPECT_FALSE(rig.worker->submitFrame("frame:view", rig.logs("view 1"), false));
  EXPECT_FALSE(rig.worker->submitFrame("frame:split", rig.logs("split"), false));
  rig.worker->post("", rig.logs("job"));
  EXPECT_TRUE(rig.worker->submitFrame("frame:view", rig.logs("view 2"), false));
  EXPECT_THROW(rig.worker->submitFrame("charts", rig.logs("not a frame"), false),
               std::invalid_argument);
  EXPECT_EQ(rig.releaseAndDrain(*gate), (Strings{"hold", "job", "split", "view 2"}));
}

TEST(RenderWorker, CancelDropsTheQueuedJobsOfItsTagAndStopsOnlyARunningJobOfThatTag) {
  Rig rig;
  std::shared_ptr<Gate> gate = rig.hold("charts", "charts 1");
  const std::atomic<bool>& stop = *gate->stopFlag.load();
  rig.worker->post("charts", rig.logs("charts 2"), rig.drops("charts 2"));
  rig.worker->post("error", rig.logs("error"), rig.drops("error"));
  rig.worker->post("", rig.logs("untagged"), rig.drops("untagged"));

  rig.worker->cancel("probe");  // nothing of that tag
  rig.worker->cancel("");       // untagged work is not cancelled by name
  EXPECT_FALSE(stop);
  rig.worker->cancel("error");  // queued only: the running charts job goes on
  EXPECT_FALSE(stop);
  EXPECT_EQ(rig.ran(), (Strings{"charts 1", "dropped error"}));
  rig.worker->cancel("charts");  // the queued one dropped, the running one asked to stop
  EXPECT_TRUE(stop);
  EXPECT_EQ(rig.ran(), (Strings{"charts 1", "dropped error", "dropped charts 2"}));
  EXPECT_EQ(rig.worker->activity().framesStopped, 0u);  // not a frame

  gate->release();
  bool stoppedAtStart = true;
  rig.worker->post("", [&](RenderContext& c) { stoppedAtStart = c.stopFlag(); });
  rig.drain();
  EXPECT_FALSE(stoppedAtStart);  // the next job starts unasked
  EXPECT_EQ(rig.ran(), (Strings{"charts 1", "dropped error", "dropped charts 2", "untagged"}));
}

TEST(RenderWorker, SubmitFrameStopsTheRunningFrameOfItsTagOnlyWhenAsked) {
  Rig rig;
  std::shared_ptr<Gate> gate = rig.hold("frame:view", "view 1");
  const std::atomic<bool>& stop = *gate->stopFlag.load();
  EXPECT_TRUE(rig.worker->activity().busy);
  EXPECT_TRUE(rig.worker->activity().frame);
  EXPECT_EQ(rig.worker->activity().tag, "frame:view");
  rig.worker->submitFrame("frame:split", rig.logs("split"), true);  // another tag
  EXPECT_FALSE(stop);
  rig.worker->submitFrame("frame:view", rig.logs("view 2"), false);  // not asked
  EXPECT_FALSE(stop);
  EXPECT_TRUE(rig.worker->submitFrame("frame:view", rig.logs("view 3"), true));
  EXPECT_TRUE(stop);
  EXPECT_EQ(rig.worker->activity().framesStopped, 1u);
  EXPECT_EQ(rig.releaseAndDrain(*gate), (Strings{"view 1", "split", "view 3"}));
}

TEST(RenderWorker, CallRunsBeforeQueuedWorkAndStopsTheRunningFrame) {
  Rig rig;
  std::promise<void> frameStarted;
  // A frame that runs until it is asked to stop (as a renderer reads the flag).
  rig.worker->submitFrame(
      "frame:view",
      [&](RenderContext& c) {
        rig.log.add("frame");
        frameStarted.set_value();
        c.stopFlag().wait(false);
        rig.log.add("frame stopped");
      },
      false);
  std::future<void> started = frameStarted.get_future();
  ASSERT_TRUE(readyWithin(started, "the frame starting"));
  rig.worker->post("", rig.logs("queued job"));
  rig.worker->submitFrame("frame:view", rig.logs("queued frame"), false);
  Strings beforeCall;
  bool called = false;
  // A call() that does not stop the frame would wait for ever: the watchdog then cancels it.
  ASSERT_TRUE(sl::test::finishesWithin(
      kLimit, "call()",
      [&] { called = rig.worker->call([&](RenderContext&) { beforeCall = rig.ran(); }); },
      [&] { rig.worker->cancel("frame:view"); }));
  EXPECT_TRUE(called);
  // The frame stopped, and nothing queued before the call ran before it.
  EXPECT_EQ(beforeCall, (Strings{"frame", "frame stopped"}));
  EXPECT_EQ(rig.worker->activity().framesStopped, 1u);
  rig.drain();
  EXPECT_EQ(rig.ran(), (Strings{"frame", "frame stopped", "queued job", "queued frame"}));
}

TEST(RenderWorker, CallRethrowsAndRunsAtOnceFromAJob) {
  Rig rig;
  EXPECT_THROW(rig.worker->call([](RenderContext&) { throw std::runtime_error("job failed"); }),
               std::runtime_error);
  rig.worker->post("", [&](RenderContext&) {
    rig.log.add("outer");
    rig.worker->call(rig.logs("inner"));  // on the render thread: no deadlock
  });
  rig.worker->post("", [](RenderContext&) { throw std::runtime_error("dropped job"); });
  rig.worker->post("", rig.logs("after a throwing job"));
  rig.drain();
  EXPECT_EQ(rig.ran(), (Strings{"outer", "inner", "after a throwing job"}));
}

TEST(RenderWorker, CallAsyncTellsDoneOnceCancelDropsOrStopsIt) {
  Rig rig;
  // What `done` said, in order ("ran", "ran threw", "dropped"), with the thread it ran on.
  Log done;
  auto tell = [&](const std::string& name) {
    return [&done, name](bool ran, std::exception_ptr thrown) {
      done.add(name + (ran ? thrown ? " ran threw" : " ran" : " dropped"));
    };
  };
  // A call in progress (holds the thread until asked to stop) and one queued behind it.
  std::promise<void> started;
  rig.worker->callAsync(
      "call",
      [&](RenderContext& c) {
        rig.log.add("first");
        started.set_value();
        c.stopFlag().wait(false);  // until cancel("call") asks it to stop
        rig.log.add("first stopped");
      },
      tell("first"));
  std::future<void> first = started.get_future();
  ASSERT_TRUE(readyWithin(first, "the first call starting"));
  rig.worker->callAsync("call", rig.logs("second"), tell("second"));
  // Esc: the queued call is dropped at once (here, on this thread), the running one stops.
  rig.worker->cancel("call");
  rig.drain();
  EXPECT_EQ(rig.ran(), (Strings{"first", "first stopped"}));
  Strings told = done.entries();  // the two are told on two threads: in either order
  std::sort(told.begin(), told.end());
  EXPECT_EQ(told, (Strings{"first ran", "second dropped"}));
  // A call that throws tells it; the worker goes on.
  rig.worker->callAsync(
      "call", [](RenderContext&) { throw std::runtime_error("job failed"); }, tell("third"));
  rig.drain();
  EXPECT_EQ(done.entries().back(), "third ran threw");
  // After the shutdown: refused, told at once.
  rig.worker->stop();
  rig.worker->callAsync("call", rig.logs("late"), tell("late"));
  EXPECT_EQ(done.entries().back(), "late dropped");
}

TEST(RenderWorker, ShutdownDropsQueuedWorkStopsTheRunningJobAndJoins) {
  Rig rig;
  std::promise<void> jobStarted;
  rig.worker->post("charts", [&](RenderContext& c) {
    rig.log.add("running");
    jobStarted.set_value();
    c.stopFlag().wait(false);  // until the shutdown asks it to stop
    rig.log.add("running stopped");
  });
  std::future<void> started = jobStarted.get_future();
  ASSERT_TRUE(readyWithin(started, "the job starting"));
  rig.worker->post("", rig.logs("u"), rig.drops("u"));
  rig.worker->post("probe", rig.logs("probe"), rig.drops("probe"));
  rig.worker->submitFrame("frame:view", rig.logs("frame"), false, rig.drops("frame"));

  ASSERT_TRUE(sl::test::finishesWithin(kLimit, "stop()", [&] { rig.worker->stop(); }));
  // Dropped in the order they would have run (by stop(), while the running job stops), and
  // the running job stopped before the join; nothing queued ran.
  Strings ran = rig.ran();
  const auto stopped = std::find(ran.begin(), ran.end(), "running stopped");
  ASSERT_NE(stopped, ran.end());
  ran.erase(stopped);
  EXPECT_EQ(ran, (Strings{"running", "dropped u", "dropped probe", "dropped frame"}));
  std::future<std::thread::id> destroyed = rig.destroyedOn.get_future();
  ASSERT_TRUE(readyWithin(destroyed, "the context's destruction"));
  EXPECT_EQ(destroyed.get(), rig.renderThread);  // on the render thread

  // Afterwards: refused, each job dropped at once; call() does not wait.
  EXPECT_FALSE(rig.worker->running());
  EXPECT_FALSE(rig.worker->post("probe", rig.logs("late"), rig.drops("late")));
  EXPECT_FALSE(rig.worker->call(rig.logs("late call")));
  EXPECT_EQ(rig.ran().back(), "dropped late");
}

TEST(RenderWorker, AFailedContextDropsWhatWaitedAndRefusesMore) {
  Rig rig(true, false);
  rig.worker->post("", rig.logs("early"), rig.drops("early"));
  std::promise<void> failed;
  rig.worker->start();
  // The failure is told after the queued work is dropped: wait for it through a late post.
  std::future<void> refused = failed.get_future();
  rig.worker->post("", rig.logs("late"), [&] { failed.set_value(); });
  ASSERT_TRUE(readyWithin(refused, "the late job being dropped"));
  EXPECT_FALSE(rig.worker->running());
  EXPECT_FALSE(rig.worker->call(rig.logs("call")));
  rig.worker->stop();
  EXPECT_EQ(rig.ran(), (Strings{"dropped early", "failed no display"}));
}

}  // namespace
