// Work that is not GL (parsing a glTF file and building its BVH) run on a thread of its own
// while the UI thread goes on handling events, so that the window never freezes behind it
// (RenderService::call does the same for the render thread's work).
#pragma once

#include <functional>

namespace sl::ui {

/// Runs `work` on a new thread and returns once it has ended (rethrowing what it threw); the
/// calling (UI) thread handles events meanwhile. What `work` touches must not be changed by
/// those events.
void runOffThread(const std::function<void()>& work);

}  // namespace sl::ui
