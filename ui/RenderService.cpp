// The render service's thread (see RenderService.h): a surfaceless EGL context (as the CLI's),
// a queue of jobs, one frame slot, the stop flag.
#include "RenderService.h"

#include <chrono>
#include <condition_variable>
#include <deque>
#include <future>
#include <map>
#include <mutex>
#include <thread>

#include <QMetaObject>

#include "core/Renderer.h"
#include "gl/EglContext.h"

namespace sl::ui {

class RenderService::Thread : public RenderContext {
 public:
  explicit Thread(RenderService* owner) : owner_(owner) {}

  ~Thread() override { stop(); }

  void start() {
    std::lock_guard lock(m_);
    if (thread_.joinable()) return;
    thread_ = std::thread([this] { run(); });
  }

  void stop() {
    {
      std::lock_guard lock(m_);
      stopping_ = true;
      stopFlag_ = true;
      jobs_.clear();
      frame_ = nullptr;
    }
    cv_.notify_all();
    if (thread_.joinable()) thread_.join();
  }

  bool running() const {
    std::lock_guard lock(m_);
    return started_ && !failed_ && !stopping_;
  }

  bool submitFrame(Job job, bool stopRunning) {
    bool replaced = false;
    {
      std::lock_guard lock(m_);
      if (stopping_) return false;
      replaced = static_cast<bool>(frame_);
      frame_ = std::move(job);
      if (stopRunning && busyFrame_) {
        stopFlag_ = true;
        ++framesStopped_;
      }
    }
    cv_.notify_all();
    return replaced;
  }

  void post(Job job, bool front = false) {
    {
      std::lock_guard lock(m_);
      if (stopping_) return;
      if (front)
        jobs_.push_front(std::move(job));
      else
        jobs_.push_back(std::move(job));
    }
    cv_.notify_all();
  }

  bool call(const Job& job) {
    if (std::this_thread::get_id() == thread_.get_id()) {  // from a job: run it now
      job(*this);
      return true;
    }
    std::promise<void> done;
    std::future<void> finished = done.get_future();
    {
      std::lock_guard lock(m_);
      if (stopping_ || failed_ || !thread_.joinable()) return false;
      jobs_.push_front([&job, &done](RenderContext& c) {
        try {
          job(c);
        } catch (...) {
          done.set_exception(std::current_exception());
          return;
        }
        done.set_value();
      });
      if (busyFrame_) {  // the caller waits: the frame in progress is not finished first
        stopFlag_ = true;
        ++framesStopped_;
      }
    }
    cv_.notify_all();
    while (finished.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
      std::lock_guard lock(m_);
      if (failed_ || stopping_) return false;  // never run: the thread has no context
    }
    finished.get();  // rethrows the job's exception
    return true;
  }

  Activity activity() const {
    std::lock_guard lock(m_);
    Activity a;
    a.busy = busy_;
    a.frame = busyFrame_;
    a.framesStopped = framesStopped_;
    if (busy_)
      a.elapsedMs =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since_)
              .count();
    return a;
  }

  // RenderContext (render thread only)
  sl::Renderer& renderer(const std::string& name) override {
    auto it = renderers_.find(name);
    if (it != renderers_.end()) return *it->second;
    sl::RendererOptions options;
    options.debugOutput = renderers_.empty();  // one callback per context
    auto r = std::make_unique<sl::Renderer>(options);
    r->setCancelFlag(&stopFlag_);
    return *renderers_.emplace(name, std::move(r)).first->second;
  }
  sl::Renderer* existing(const std::string& name) override {
    auto it = renderers_.find(name);
    return it == renderers_.end() ? nullptr : it->second.get();
  }
  const std::atomic<bool>& stopFlag() const override { return stopFlag_; }
  const std::string& glDescription() const override { return description_; }

 private:
  void run() {
    try {
      context_ = std::make_unique<sl::gl::EglContext>(true);
      description_ = renderer("main").glDescription();
    } catch (const std::exception& e) {
      {
        std::lock_guard lock(m_);
        failed_ = true;
      }
      const QString message = QString::fromUtf8(e.what());
      QMetaObject::invokeMethod(
          owner_, [o = owner_, message] { Q_EMIT o->failed(message); }, Qt::QueuedConnection);
      return;
    }
    {
      std::lock_guard lock(m_);
      started_ = true;
    }
    const QString description = QString::fromStdString(description_);
    QMetaObject::invokeMethod(
        owner_, [o = owner_, description] { Q_EMIT o->ready(description); }, Qt::QueuedConnection);
    for (;;) {
      Job job;
      bool isFrame = false;
      {
        std::unique_lock lock(m_);
        cv_.wait(lock, [this] { return stopping_ || !jobs_.empty() || frame_; });
        if (stopping_) break;
        if (!jobs_.empty()) {
          job = std::move(jobs_.front());
          jobs_.pop_front();
        } else {
          job = std::move(frame_);
          frame_ = nullptr;
          isFrame = true;
        }
        stopFlag_ = false;  // whatever starts now starts unasked
        busy_ = true;
        busyFrame_ = isFrame;
        since_ = std::chrono::steady_clock::now();
      }
      try {
        job(*this);
      } catch (const std::exception&) {
        // A job reports its own problems through its result; one that throws is dropped.
      }
      std::lock_guard lock(m_);
      busy_ = false;
      busyFrame_ = false;
    }
    for (auto& [name, r] : renderers_) r.reset();  // with the context current
    renderers_.clear();
    context_.reset();
  }

  RenderService* owner_;
  mutable std::mutex m_;
  std::condition_variable cv_;
  std::deque<Job> jobs_;
  Job frame_;
  bool stopping_ = false, started_ = false, failed_ = false;
  bool busy_ = false, busyFrame_ = false;
  std::uint64_t framesStopped_ = 0;
  std::chrono::steady_clock::time_point since_;
  std::atomic<bool> stopFlag_{false};
  std::thread thread_;
  // Render thread only:
  std::unique_ptr<sl::gl::EglContext> context_;
  std::map<std::string, std::unique_ptr<sl::Renderer>> renderers_;
  std::string description_;
};

RenderService::RenderService(QObject* parent)
    : QObject(parent), thread_(std::make_unique<Thread>(this)) {}

RenderService::~RenderService() {
  thread_->stop();
}

void RenderService::start() {
  thread_->start();
}

bool RenderService::isRunning() const {
  return thread_->running();
}

bool RenderService::submitFrame(Job job, bool stopRunning) {
  return thread_->submitFrame(std::move(job), stopRunning);
}

void RenderService::post(Job job) {
  thread_->post(std::move(job));
}

bool RenderService::call(const Job& job) {
  return thread_->call(job);
}

RenderService::Activity RenderService::activity() const {
  return thread_->activity();
}

}  // namespace sl::ui
