// A value a technique carries from one frame to the next under the transactional-frame rule
// (Technique::commitFrame, docs/ARCHITECTURE.md): a frame reads and writes the working copy;
// a complete frame commits it, a stopped frame's changes are discarded.
#pragma once

#include <utility>

namespace sl {

template <class T>
class FrameCarried {
 public:
  /// The working copy: what the frame being rendered reads and changes.
  T& operator*() { return working_; }
  const T& operator*() const { return working_; }
  T* operator->() { return &working_; }
  const T* operator->() const { return &working_; }
  /// What the last complete frame left.
  const T& committed() const { return committed_; }
  /// The frame completed: its changes are what the next frame starts from.
  void commit() { committed_ = working_; }
  /// The frame was stopped: back to what the last complete frame left.
  void discard() { working_ = committed_; }
  /// Both copies to `value` (a reset between frames: Technique::resetTemporalState).
  void reset(T value = T{}) {
    committed_ = value;
    working_ = std::move(value);
  }

 private:
  T working_{}, committed_{};
};

}  // namespace sl
