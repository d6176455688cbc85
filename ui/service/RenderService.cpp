// The render service (RenderService.h): its thread (render/RenderWorker) with the window's
// context, a surfaceless EGL context (as the CLI's) and the renderers made on it.
#include "service/RenderService.h"

#include <atomic>
#include <exception>
#include <map>

#include <QMetaObject>
#include <QThread>

#include "core/Renderer.h"
#include "gl/EglContext.h"
#include "service/OffThread.h"

namespace sl::ui {

namespace {

/// The render thread's GL context and its renderers, made and destroyed on that thread.
class GlRenderContext : public RenderContext {
 public:
  explicit GlRenderContext(const std::atomic<bool>& stopFlag)
      : stopFlag_(stopFlag), context_(std::make_unique<sl::gl::EglContext>(true)) {
    description_ = renderer("main").glDescription();
  }
  ~GlRenderContext() override {
    renderers_.clear();  // with the context current, before it goes
    context_.reset();
  }

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
  const std::atomic<bool>& stopFlag_;
  std::unique_ptr<sl::gl::EglContext> context_;
  std::map<std::string, std::unique_ptr<sl::Renderer>> renderers_;
  std::string description_;
};

}  // namespace

RenderService::RenderService(QObject* parent) : QObject(parent) {
  RenderWorker::Events events;
  events.ready = [this](const std::string& description) {
    QMetaObject::invokeMethod(
        this, [this, d = QString::fromStdString(description)] { Q_EMIT ready(d); },
        Qt::QueuedConnection);
  };
  events.failed = [this](const std::string& message) {
    QMetaObject::invokeMethod(
        this, [this, m = QString::fromStdString(message)] { Q_EMIT failed(m); },
        Qt::QueuedConnection);
  };
  worker_ = std::make_unique<RenderWorker>(
      [](const std::atomic<bool>& stopFlag) -> std::unique_ptr<RenderContext> {
        return std::make_unique<GlRenderContext>(stopFlag);
      },
      std::move(events));
}

RenderService::~RenderService() {
  worker_->stop();
}

void RenderService::start() {
  worker_->start();
}

bool RenderService::isRunning() const {
  return worker_->running();
}

bool RenderService::submitFrame(Job job, bool stopRunning) {
  return worker_->submitFrame(RenderTag::kViewFrame, std::move(job), stopRunning);
}

void RenderService::post(Job job) {
  worker_->post({}, std::move(job));
}

bool RenderService::post(const std::string& tag, Job job, Dropped dropped) {
  return worker_->post(tag, std::move(job), std::move(dropped));
}

void RenderService::cancel(const std::string& tag) {
  worker_->cancel(tag);
}

bool RenderService::call(const Job& job, const QString& note) {
  if (QThread::currentThread() != thread()) return worker_->call(job);
  // On the UI thread: wait while handling events, so that the window never freezes behind a
  // long action (an error trace, an export, the equal-memory search). The state is shared:
  // the job's end is told on the render thread.
  struct State {
    std::atomic<bool> ended{false};
    bool ran = false;  ///< false: dropped (cancelled before it started, or refused)
    std::exception_ptr thrown;
  };
  auto state = std::make_shared<State>();
  ++callsWaiting_;
  Q_EMIT callStarted(note);
  worker_->callAsync(RenderTag::kCall, std::cref(job),
                     [state](bool ran, std::exception_ptr thrown) {
                       state->ran = ran;
                       state->thrown = std::move(thrown);
                       state->ended = true;
                       wakeUiThread();
                     });
  waitHandlingEvents(state->ended);
  --callsWaiting_;
  Q_EMIT callEnded(callsWaiting_);
  if (state->thrown) std::rethrow_exception(state->thrown);
  return state->ran;
}

void RenderService::cancelCall() {
  worker_->cancel(RenderTag::kCall);
}

RenderService::Activity RenderService::activity() const {
  return worker_->activity();
}

}  // namespace sl::ui
