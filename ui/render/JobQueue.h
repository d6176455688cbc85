// The render service's queue policy (RenderService.h), plain C++ without Qt or GL: jobs carry
// a tag, and a newer job replaces an unstarted one of the same tag (qrenderdoc's
// ReplayManager::AsyncInvoke); frames wait until no other job does. Not thread-safe on its
// own: RenderWorker holds its lock around every call.
#pragma once

#include <cstddef>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "render/RenderContext.h"

namespace sl::ui {

class JobQueue {
 public:
  using Job = std::function<void(RenderContext&)>;
  /// Told when a job will never run (replaced, cancelled, shut down, refused).
  using Dropped = std::function<void()>;

  /// One piece of work as queued.
  struct Entry {
    std::string tag;  ///< "" untagged: never replaces, never replaced
    Job job;
    Dropped dropped;  ///< may be empty; whoever removes the entry unrun calls it
  };

  /// A tag that names a frame ("frame:view"): frames run only when no other job waits.
  static bool isFrameTag(std::string_view tag);

  /// Queues `entry` after the work of its lane queued before it. A tagged entry removes the
  /// unstarted entry of its tag, returned so that the caller can tell its `dropped`.
  std::optional<Entry> push(Entry entry);
  /// Queues `entry` ahead of everything (a blocking call).
  void pushFront(Entry entry);
  /// The next entry to run: the oldest job, else the oldest frame; none when empty.
  std::optional<Entry> pop();
  /// Removes every unstarted entry tagged `tag` (a cancel), oldest first.
  std::vector<Entry> take(std::string_view tag);
  /// Removes every entry (a shutdown), in the order they would have run.
  std::vector<Entry> takeAll();
  bool empty() const { return jobs_.empty() && frames_.empty(); }
  std::size_t size() const { return jobs_.size() + frames_.size(); }

 private:
  std::deque<Entry>& laneOf(std::string_view tag) { return isFrameTag(tag) ? frames_ : jobs_; }

  std::deque<Entry> jobs_;    ///< every job that is not a frame, in order queued
  std::deque<Entry> frames_;  ///< frames (one per tag), in order queued
};

}  // namespace sl::ui
