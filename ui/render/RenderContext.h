// What a job on the render service's thread works with (RenderService.h, RenderWorker.h): the
// thread's renderers and the stop flag of the work in progress. Plain C++: no Qt, no GL header.
#pragma once

#include <atomic>
#include <string>

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
  /// Set when the job in progress is asked to stop: a newer frame of its tag replaced it,
  /// its tag was cancelled, a blocking call waits, or the service stops (renderers read it:
  /// Renderer::setCancelFlag). Raising it notifies: a job may block on wait(false).
  virtual const std::atomic<bool>& stopFlag() const = 0;
  /// The GL_RENDERER / version line of the context.
  virtual const std::string& glDescription() const = 0;
};

}  // namespace sl::ui
