// The render service's thread (RenderWorker.h).
#include "render/RenderWorker.h"

#include <exception>
#include <future>
#include <stdexcept>
#include <utility>

namespace sl::ui {

namespace {
/// The worker whose thread this is (a call() from one of its own jobs runs at once).
thread_local const RenderWorker* tCurrentWorker = nullptr;
}  // namespace

RenderWorker::RenderWorker(ContextFactory makeContext, Events events)
    : makeContext_(std::move(makeContext)), events_(std::move(events)) {}

RenderWorker::~RenderWorker() {
  stop();
}

void RenderWorker::start() {
  std::lock_guard lock(m_);
  if (thread_.joinable() || stopping_) return;
  thread_ = std::thread([this] { run(); });
}

void RenderWorker::stop() {
  std::vector<Entry> dropped;
  {
    std::lock_guard lock(m_);
    stopping_ = true;
    stopFlag_ = true;
    stopFlag_.notify_all();
    dropped = queue_.takeAll();
  }
  cv_.notify_all();
  notifyDropped(dropped);
  if (thread_.joinable() && std::this_thread::get_id() != thread_.get_id()) thread_.join();
}

bool RenderWorker::running() const {
  std::lock_guard lock(m_);
  return started_ && !failed_ && !stopping_;
}

bool RenderWorker::post(std::string tag, Job job, Dropped dropped) {
  return enqueue({std::move(tag), std::move(job), std::move(dropped)}, false);
}

bool RenderWorker::submitFrame(std::string tag, Job job, bool stopRunning, Dropped dropped) {
  if (!JobQueue::isFrameTag(tag)) throw std::invalid_argument("not a frame tag: " + tag);
  return enqueue({std::move(tag), std::move(job), std::move(dropped)}, stopRunning);
}

bool RenderWorker::enqueue(Entry entry, bool stopRunning) {
  std::vector<Entry> dropped;
  bool replaced = false;
  {
    std::lock_guard lock(m_);
    if (stopping_ || failed_) {
      dropped.push_back(std::move(entry));  // refused
    } else {
      if (stopRunning && busy_ && runningTag_ == entry.tag) askRunningToStop();
      if (std::optional<Entry> older = queue_.push(std::move(entry))) {
        dropped.push_back(std::move(*older));
        replaced = true;
      }
    }
  }
  cv_.notify_all();
  notifyDropped(dropped);
  return replaced;
}

void RenderWorker::cancel(const std::string& tag) {
  if (tag.empty()) return;
  std::vector<Entry> dropped;
  {
    std::lock_guard lock(m_);
    dropped = queue_.take(tag);
    if (busy_ && runningTag_ == tag) askRunningToStop();
  }
  notifyDropped(dropped);
}

bool RenderWorker::call(const Job& job) {
  std::promise<bool> ran;
  std::future<bool> finished = ran.get_future();
  std::exception_ptr thrown;
  callAsync({}, std::cref(job), [&ran, &thrown](bool r, std::exception_ptr e) {
    thrown = std::move(e);
    ran.set_value(r);
  });
  const bool done = finished.get();  // set exactly once: run or dropped
  if (thrown) std::rethrow_exception(thrown);
  return done;
}

void RenderWorker::callAsync(std::string tag, Job job, CallDone done) {
  auto shared = std::make_shared<CallDone>(std::move(done));
  auto run = [job = std::move(job), shared](RenderContext& c) {
    std::exception_ptr thrown;
    try {
      job(c);
    } catch (...) {
      thrown = std::current_exception();
    }
    (*shared)(true, thrown);
  };
  if (tCurrentWorker == this) {  // from one of this worker's jobs: run it now
    run(*context_);
    return;
  }
  std::vector<Entry> refused;
  {
    std::lock_guard lock(m_);
    Entry entry{std::move(tag), std::move(run), [shared] { (*shared)(false, nullptr); }};
    if (stopping_ || failed_ || !thread_.joinable()) {
      refused.push_back(std::move(entry));
    } else {
      queue_.pushFront(std::move(entry));
      // The caller waits: a frame in progress is not finished first.
      if (busy_ && JobQueue::isFrameTag(runningTag_)) askRunningToStop();
    }
  }
  cv_.notify_all();
  notifyDropped(refused);
}

RenderWorker::Activity RenderWorker::activity() const {
  std::lock_guard lock(m_);
  Activity a;
  a.busy = busy_;
  a.frame = busy_ && JobQueue::isFrameTag(runningTag_);
  a.tag = runningTag_;
  a.framesStopped = framesStopped_;
  if (busy_)
    a.elapsedMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since_)
            .count();
  return a;
}

void RenderWorker::askRunningToStop() {
  stopFlag_ = true;
  stopFlag_.notify_all();  // a job may wait on it (std::atomic::wait)
  if (JobQueue::isFrameTag(runningTag_)) ++framesStopped_;
}

void RenderWorker::notifyDropped(std::vector<Entry>& entries) {
  for (Entry& e : entries)
    if (e.dropped) e.dropped();
  entries.clear();  // the jobs' captures are released here too, outside the lock
}

void RenderWorker::run() {
  tCurrentWorker = this;
  try {
    context_ = makeContext_(stopFlag_);
    if (!context_) throw std::runtime_error("the render context could not be made");
  } catch (const std::exception& e) {
    std::vector<Entry> dropped;
    {
      std::lock_guard lock(m_);
      failed_ = true;
      dropped = queue_.takeAll();
    }
    notifyDropped(dropped);
    if (events_.failed) events_.failed(e.what());
    return;
  }
  {
    std::lock_guard lock(m_);
    started_ = true;
  }
  if (events_.ready) events_.ready(context_->glDescription());
  for (;;) {
    std::optional<Entry> next;
    {
      std::unique_lock lock(m_);
      cv_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (stopping_) break;  // stop() took what was queued
      next = queue_.pop();
      stopFlag_ = false;  // whatever starts now starts unasked
      busy_ = true;
      runningTag_ = next->tag;
      since_ = std::chrono::steady_clock::now();
    }
    try {
      next->job(*context_);
    } catch (const std::exception&) {
      // A job reports its own problems through its result; one that throws is dropped.
    }
    next.reset();
    std::lock_guard lock(m_);
    busy_ = false;
    runningTag_.clear();
  }
  context_.reset();  // on this thread: the renderers are freed with the context current
}

}  // namespace sl::ui
