// The render service: ONE thread that owns the GUI's OpenGL context and every renderer of
// the window (the view's main and split halves, the outside view they draw, the Charts
// panel's sweeps, error traces, probes, exports). The UI thread never calls GL: it posts
// jobs here and receives their results as queued calls (qrenderdoc's ReplayManager is the
// model).
//
// Work is of two kinds. Jobs run in the order posted. The FRAME slot holds at most one
// frame not yet started: a newer frame replaces it (a camera drag does not queue frames),
// and may ask the frame in progress to stop (the renderer reads the stop flag between its
// steps and units; a stopped frame is dropped, never shown or measured). A blocking call()
// is for explicit actions only (exports, scripted reads): it stops the frame in progress
// and runs before anything else queued.
//
// No GL header here: the context and renderers live in the .cpp.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>

#include <QObject>
#include <QString>

namespace sl {
class Renderer;
}  // namespace sl

namespace sl::ui {

/// What a job on the render thread uses: the thread's renderers, made on first use and kept
/// until the service stops, and the stop flag of the work in progress.
class RenderContext {
 public:
  virtual ~RenderContext() = default;
  /// The renderer called `name` ("main", "split", "charts"), created on first use; the first
  /// one made owns the context's debug output.
  virtual sl::Renderer& renderer(const std::string& name) = 0;
  /// The renderer called `name` if it exists, else null (no GL).
  virtual sl::Renderer* existing(const std::string& name) = 0;
  /// Set when a newer frame replaced the one in progress, a blocking call waits, or the
  /// service stops (renderers read it: Renderer::setCancelFlag).
  virtual const std::atomic<bool>& stopFlag() const = 0;
  /// The GL_RENDERER / version line of the context.
  virtual const std::string& glDescription() const = 0;
};

class RenderService : public QObject {
  Q_OBJECT

 public:
  using Job = std::function<void(RenderContext&)>;

  explicit RenderService(QObject* parent = nullptr);
  /// Stops the frame in progress, drops queued work, frees every renderer with the context
  /// current and joins the thread.
  ~RenderService() override;

  /// Starts the thread and creates its context; ready() or failed() follows (queued).
  void start();
  bool isRunning() const;

  /// Puts `job` in the frame slot, replacing a frame that has not started (true: one was
  /// replaced; it never runs). `stopRunning`: also ask a frame in progress to stop (the view
  /// changed: its result would be stale).
  bool submitFrame(Job job, bool stopRunning);
  /// Runs `job` after the work queued before it (before the frame slot).
  void post(Job job);
  /// Runs `job` on the render thread now (after the job in progress, which is asked to stop
  /// if it is a frame) and waits for it. False when the service is not running.
  bool call(const Job& job);

  /// What the render thread is doing: a frame or job in progress and for how long.
  struct Activity {
    bool busy = false;
    bool frame = false;  ///< the frame slot's work (else a job)
    double elapsedMs = 0.0;
    std::uint64_t framesStopped = 0;  ///< frames asked to stop since the start
  };
  Activity activity() const;

 Q_SIGNALS:
  /// The context exists: `description` is its GL_RENDERER / version.
  void ready(const QString& description);
  /// The context could not be made (the message names what is missing).
  void failed(const QString& message);

 private:
  class Thread;
  std::unique_ptr<Thread> thread_;
};

}  // namespace sl::ui
