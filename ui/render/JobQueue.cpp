// The render service's queue policy (JobQueue.h).
#include "render/JobQueue.h"

#include <algorithm>
#include <iterator>

namespace sl::ui {

bool JobQueue::isFrameTag(std::string_view tag) {
  return tag.starts_with("frame:");
}

std::optional<JobQueue::Entry> JobQueue::push(Entry entry) {
  std::deque<Entry>& lane = laneOf(entry.tag);
  std::optional<Entry> replaced;
  if (!entry.tag.empty()) {
    auto same =
        std::find_if(lane.begin(), lane.end(), [&](const Entry& e) { return e.tag == entry.tag; });
    if (same != lane.end()) {  // at most one: every push of a tag removes the older
      replaced = std::move(*same);
      lane.erase(same);
    }
  }
  lane.push_back(std::move(entry));
  return replaced;
}

void JobQueue::pushFront(Entry entry) {
  jobs_.push_front(std::move(entry));
}

std::optional<JobQueue::Entry> JobQueue::pop() {
  std::deque<Entry>& lane = jobs_.empty() ? frames_ : jobs_;
  if (lane.empty()) return std::nullopt;
  Entry next = std::move(lane.front());
  lane.pop_front();
  return next;
}

std::vector<JobQueue::Entry> JobQueue::take(std::string_view tag) {
  std::vector<Entry> taken;
  if (tag.empty()) return taken;  // untagged work is not cancelled by name
  std::deque<Entry>& lane = laneOf(tag);
  auto keep =
      std::stable_partition(lane.begin(), lane.end(), [&](const Entry& e) { return e.tag != tag; });
  std::move(keep, lane.end(), std::back_inserter(taken));
  lane.erase(keep, lane.end());
  return taken;
}

std::vector<JobQueue::Entry> JobQueue::takeAll() {
  std::vector<Entry> taken;
  taken.reserve(size());
  std::move(jobs_.begin(), jobs_.end(), std::back_inserter(taken));
  std::move(frames_.begin(), frames_.end(), std::back_inserter(taken));
  jobs_.clear();
  frames_.clear();
  return taken;
}

}  // namespace sl::ui
