// The asynchronous reference scheduler (metrics/AsyncReference) with a fake tracer and a fake
// clock: submit, the rate of traces for a still view, age and staleness, cancel.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>

#include <gtest/gtest.h>

#include "Watchdog.h"
#include "metrics/AsyncReference.h"

namespace {

/// A trace that runs until the test opens its gate (or it is cancelled).
struct Gate {
  std::mutex m;
  std::condition_variable cv;
  bool open = false;
  std::atomic<int> started{0};
  void release() {
    {
      std::lock_guard l(m);
      open = true;
    }
    cv.notify_all();
  }
};

sl::ReferenceJob gatedJob(Gate& gate, std::uint64_t revision, std::uint64_t frame, double errorPct,
                          std::atomic<double>* clock = nullptr, double finishAtS = 0.0) {
  sl::ReferenceJob job;
  job.viewRevision = revision;
  job.frameNumber = frame;
  job.trace = [&gate, errorPct, clock,
               finishAtS](const std::atomic<bool>& cancelled) -> std::optional<sl::ReferenceTrace> {
    ++gate.started;
    std::unique_lock l(gate.m);
    while (!gate.open) {
      if (cancelled) return std::nullopt;
      gate.cv.wait_for(l, std::chrono::milliseconds(2));
    }
    if (clock) *clock = finishAtS;  // the trace took until finishAtS
    sl::ReferenceTrace t;
    t.stats.errorPct = errorPct;
    t.width = 2;
    t.height = 1;
    t.referenceMask = {1, 0};
    t.frameSignature = "frame " + std::to_string(errorPct);
    return t;
  };
  return job;
}

/// Waits (real time, bounded) until `done` holds.
template <class F>
bool eventually(F done) {
  for (int i = 0; i < 2000; ++i) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return done();
}

TEST(AsyncReference, TracesOnTheWorkerAndHandsTheResultOver) {
  std::atomic<double> now{10.0};
  Gate gate, other;  // outlive `ref`, whose destructor joins the traces waiting on them
  sl::AsyncReference ref(1.0, 3.0, [&] { return now.load(); });
  EXPECT_TRUE(ref.wantsTrace(1));
  ASSERT_TRUE(ref.submit(gatedJob(gate, 1, 7, 0.5, &now, 10.25)));
  EXPECT_TRUE(ref.busy());
  EXPECT_FALSE(ref.wantsTrace(1));  // one trace at a time
  EXPECT_FALSE(ref.wantsTrace(2));
  EXPECT_FALSE(ref.submit(gatedJob(other, 2, 8, 0.7)));  // refused while busy
  EXPECT_FALSE(ref.takeFinished());                      // nothing finished yet
  gate.release();
  ASSERT_TRUE(eventually([&] { return !ref.busy(); }));
  const auto done = ref.takeFinished();
  ASSERT_TRUE(done);
  EXPECT_EQ(done->viewRevision, 1u);
  EXPECT_EQ(done->frameNumber, 7u);
  EXPECT_EQ(done->submittedS, 10.0);
  EXPECT_EQ(done->finishedS, 10.25);
  EXPECT_EQ(done->trace.stats.errorPct, 0.5);
  EXPECT_EQ(done->trace.referenceMask, (std::vector<std::uint8_t>{1, 0}));
  EXPECT_FALSE(ref.takeFinished());  // taken once
  EXPECT_EQ(ref.submitted(), 1u);
  EXPECT_EQ(ref.finished(), 1u);
  EXPECT_EQ(ref.cancelled(), 0u);
}

TEST(AsyncReference, AStillViewIsRetracedAtALowerRateANewViewAtOnce) {
  std::atomic<double> now{0.0};
  Gate gate;  // outlives `ref`, whose destructor joins the trace waiting on it
  sl::AsyncReference ref(1.0, 3.0, [&] { return now.load(); });
  gate.release();
  ASSERT_TRUE(ref.submit(gatedJob(gate, 5, 1, 1.0, &now, 0.5)));  // took 0.5 s
  ASSERT_TRUE(eventually([&] { return !ref.busy(); }));
  ASSERT_TRUE(ref.takeFinished());
  // The interval is max(1 s, 3 x 0.5 s) = 1.5 s from the submission at 0 s.
  EXPECT_EQ(ref.intervalS(), 1.5);
  now = 1.4;
  EXPECT_FALSE(ref.wantsTrace(5));
  EXPECT_TRUE(ref.wantsTrace(6));  // the view changed: trace it now
  now = 1.5;
  EXPECT_TRUE(ref.wantsTrace(5));
}

TEST(AsyncReference, AgeAndStaleness) {
  sl::FinishedReference r;
  r.viewRevision = 3;
  r.frameNumber = 40;
  r.submittedS = 100.0;
  const sl::ReferenceAge fresh = sl::referenceAge(r, 3, 43, 100.8);
  EXPECT_FALSE(fresh.stale);
  EXPECT_EQ(fresh.framesAgo, 3u);
  EXPECT_NEAR(fresh.ageS, 0.8, 1e-9);
  EXPECT_EQ(sl::describeReferenceAge(fresh), "reference 0.8 s old (3 frames ago)");
  const sl::ReferenceAge one = sl::referenceAge(r, 3, 41, 100.0);
  EXPECT_EQ(sl::describeReferenceAge(one), "reference 0.0 s old (1 frame ago)");
  const sl::ReferenceAge stale = sl::referenceAge(r, 4, 50, 102.1);
  EXPECT_TRUE(stale.stale);
  EXPECT_EQ(sl::describeReferenceAge(stale), "reference of an earlier view (2.1 s old)");
  // A clock or frame counter behind the reference (never negative).
  const sl::ReferenceAge behind = sl::referenceAge(r, 3, 10, 99.0);
  EXPECT_EQ(behind.ageS, 0.0);
  EXPECT_EQ(behind.framesAgo, 0u);
}

TEST(AsyncReference, ACancelledTraceIsNeverDelivered) {
  std::atomic<double> now{0.0};
  Gate gate, next;  // outlive `ref`, whose destructor joins the traces waiting on them
  sl::AsyncReference ref(1.0, 3.0, [&] { return now.load(); });
  ASSERT_TRUE(ref.submit(gatedJob(gate, 1, 1, 2.0)));
  ASSERT_TRUE(eventually([&] { return gate.started.load() == 1; }));
  ref.cancel();                                          // e.g. the scene changed while it traced
  ASSERT_TRUE(eventually([&] { return !ref.busy(); }));  // the trace saw the flag
  EXPECT_FALSE(ref.takeFinished());
  EXPECT_EQ(ref.cancelled(), 1u);
  EXPECT_EQ(ref.finished(), 0u);
  // The same revision traces again at once (the cancelled one counts for nothing).
  EXPECT_TRUE(ref.wantsTrace(1));
  next.release();
  ASSERT_TRUE(ref.submit(gatedJob(next, 1, 2, 3.0)));
  ASSERT_TRUE(eventually([&] { return !ref.busy(); }));
  const auto done = ref.takeFinished();
  ASSERT_TRUE(done);
  EXPECT_EQ(done->trace.stats.errorPct, 3.0);
}

TEST(AsyncReference, CancelDropsAnUntakenResultAndANewerReplacesAnOlder) {
  std::atomic<double> now{0.0};
  Gate open;  // outlives `ref`, whose destructor joins the traces waiting on it
  sl::AsyncReference ref(0.0, 0.0, [&] { return now.load(); });
  open.release();
  ASSERT_TRUE(ref.submit(gatedJob(open, 1, 1, 1.0)));
  ASSERT_TRUE(eventually([&] { return !ref.busy(); }));
  ASSERT_TRUE(ref.submit(gatedJob(open, 2, 2, 2.0)));
  ASSERT_TRUE(eventually([&] { return !ref.busy(); }));
  auto done = ref.takeFinished();
  ASSERT_TRUE(done);
  EXPECT_EQ(done->viewRevision, 2u);  // the older untaken one was replaced
  EXPECT_EQ(ref.finished(), 2u);
  ASSERT_TRUE(ref.submit(gatedJob(open, 3, 3, 3.0)));
  ASSERT_TRUE(eventually([&] { return !ref.busy(); }));
  ref.cancel();  // finished but not taken: a scene change drops it too
  EXPECT_FALSE(ref.takeFinished());
}

TEST(AsyncReference, AThrowingTraceIsReportedOnceAndDeliversNothing) {
  sl::AsyncReference ref(0.0, 0.0);
  sl::ReferenceJob job;
  job.viewRevision = 1;
  job.trace = [](const std::atomic<bool>&) -> std::optional<sl::ReferenceTrace> {
    throw std::runtime_error("embree: out of memory");
  };
  ASSERT_TRUE(ref.submit(std::move(job)));
  ASSERT_TRUE(eventually([&] { return !ref.busy(); }));
  EXPECT_FALSE(ref.takeFinished());
  EXPECT_EQ(ref.takeFailure(), std::optional<std::string>("embree: out of memory"));
  EXPECT_FALSE(ref.takeFailure());
  EXPECT_FALSE(ref.submit(sl::ReferenceJob{}));  // no work: refused
}

// The window closes mid-trace: the destructor returns once the trace saw the cancel flag. A
// destructor that never cancels fails within seconds (then the gate opens so that the trace
// ends and the worker joins) instead of hanging until the ctest timeout.
TEST(AsyncReference, DestroyedWhileATraceRunsCancelsAndJoins) {
  Gate gate;
  auto ref = std::make_unique<sl::AsyncReference>();
  ASSERT_TRUE(ref->submit(gatedJob(gate, 1, 1, 1.0)));
  ASSERT_TRUE(eventually([&] { return gate.started.load() == 1; }));
  EXPECT_TRUE(sl::test::finishesWithin(
      std::chrono::seconds(5), "~AsyncReference during a trace (the cancel flag unseen?)",
      [&] { ref.reset(); }, [&] { gate.release(); }));
}

}  // namespace
