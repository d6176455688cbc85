// Waiting on the UI thread without freezing the window: the wait handles events until what it
// waits for is done (RenderService::call for the render thread's work; runOffThread for work
// that is not GL, such as parsing a glTF file and building its BVH).
#pragma once

#include <atomic>
#include <functional>

namespace sl::ui {

/// Handles the calling (UI) thread's events until `done` is set; whoever sets it then calls
/// wakeUiThread(), so that the wait does not sleep on until the next event.
void waitHandlingEvents(const std::atomic<bool>& done);

/// Wakes the UI thread's event loop (an empty queued call); from any thread.
void wakeUiThread();

/// Runs `work` on a new thread and returns once it has ended (rethrowing what it threw); the
/// calling (UI) thread handles events meanwhile. What `work` touches must not be changed by
/// those events.
void runOffThread(const std::function<void()>& work);

}  // namespace sl::ui
