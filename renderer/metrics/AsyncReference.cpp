// The exact reference on a worker thread (see AsyncReference.h).
#include "metrics/AsyncReference.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <utility>

namespace sl {

ReferenceAge referenceAge(const FinishedReference& r, std::uint64_t currentViewRevision,
                          std::uint64_t currentFrameNumber, double nowS) {
  ReferenceAge age;
  age.ageS = std::max(0.0, nowS - r.submittedS);
  age.framesAgo = currentFrameNumber > r.frameNumber ? currentFrameNumber - r.frameNumber : 0;
  age.stale = r.viewRevision != currentViewRevision;
  return age;
}

std::string describeReferenceAge(const ReferenceAge& age) {
  char buf[96];
  if (age.stale)
    std::snprintf(buf, sizeof buf, "reference of an earlier view (%.1f s old)", age.ageS);
  else
    std::snprintf(buf, sizeof buf, "reference %.1f s old (%llu frame%s ago)", age.ageS,
                  static_cast<unsigned long long>(age.framesAgo), age.framesAgo == 1 ? "" : "s");
  return buf;
}

double AsyncReference::steadySeconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

AsyncReference::AsyncReference(double minIntervalS, double durationFactor, Clock clock)
    : minIntervalS_(minIntervalS),
      durationFactor_(durationFactor),
      clock_(std::move(clock)),
      worker_([this] { run(); }) {}

AsyncReference::~AsyncReference() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
    cancelFlag_ = true;
  }
  wake_.notify_all();
  worker_.join();
}

double AsyncReference::intervalS() const {
  std::lock_guard lock(mutex_);
  return std::max(minIntervalS_, durationFactor_ * lastDurationS_);
}

bool AsyncReference::wantsTrace(std::uint64_t viewRevision) const {
  std::lock_guard lock(mutex_);
  if (running_) return false;
  if (lastRevision_ != viewRevision) return true;
  return clock_() - lastSubmitS_ >= std::max(minIntervalS_, durationFactor_ * lastDurationS_);
}

bool AsyncReference::submit(ReferenceJob job) {
  {
    std::lock_guard lock(mutex_);
    if (running_ || stop_ || !job.trace) return false;
    running_ = true;
    cancelFlag_ = false;
    lastRevision_ = job.viewRevision;
    lastSubmitS_ = clock_();
    ++submittedCount_;
    pending_ = std::move(job);
  }
  wake_.notify_all();
  return true;
}

void AsyncReference::cancel() {
  std::lock_guard lock(mutex_);
  ++generation_;
  cancelFlag_ = true;
  finished_.reset();
  lastRevision_.reset();
}

bool AsyncReference::busy() const {
  std::lock_guard lock(mutex_);
  return running_;
}

std::optional<FinishedReference> AsyncReference::takeFinished() {
  std::lock_guard lock(mutex_);
  return std::exchange(finished_, std::nullopt);
}

std::optional<std::string> AsyncReference::takeFailure() {
  std::lock_guard lock(mutex_);
  return std::exchange(failure_, std::nullopt);
}

std::uint64_t AsyncReference::submitted() const {
  std::lock_guard lock(mutex_);
  return submittedCount_;
}
std::uint64_t AsyncReference::finished() const {
  std::lock_guard lock(mutex_);
  return finishedCount_;
}
std::uint64_t AsyncReference::cancelled() const {
  std::lock_guard lock(mutex_);
  return cancelledCount_;
}

void AsyncReference::run() {
  for (;;) {
    ReferenceJob job;
    std::uint64_t generation = 0;
    double startS = 0.0;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stop_ || pending_.has_value(); });
      if (stop_) return;
      job = std::move(*pending_);
      pending_.reset();
      generation = generation_;
      startS = lastSubmitS_;
    }
    std::optional<ReferenceTrace> trace;
    std::optional<std::string> failure;
    try {
      trace = job.trace(cancelFlag_);
    } catch (const std::exception& e) {  // delivers nothing; the next trace tries again
      failure = e.what();
    }
    std::lock_guard lock(mutex_);
    if (failure) failure_ = std::move(failure);
    running_ = false;
    if (stop_) return;
    if (!trace || generation != generation_ || cancelFlag_) {
      ++cancelledCount_;
      continue;
    }
    const double nowS = clock_();
    lastDurationS_ = std::max(0.0, nowS - startS);
    FinishedReference done;
    done.viewRevision = job.viewRevision;
    done.frameNumber = job.frameNumber;
    done.submittedS = startS;
    done.finishedS = nowS;
    done.trace = std::move(*trace);
    finished_ = std::move(done);
    ++finishedCount_;
  }
}

}  // namespace sl
