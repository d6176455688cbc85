// The live reference of one side of the view in continuous rendering: the exact reference
// traced on a worker thread (metrics/AsyncReference) at a lower rate than frames are drawn,
// what the latest trace measured and how old it is. The view has one per side (the main
// technique, the split view's right half); neither calls GL.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <QString>

#include "metrics/AsyncReference.h"

namespace sl::ui {

/// A side's live error: the latest finished trace's error, its age, and whether it was traced
/// for another view than the one shown (`age.stale`).
struct LiveError {
  double errorPct = 0.0;
  QString unmeasured;  ///< why errorPct is not a measurement (no covered pixel); empty: it is
  sl::ReferenceAge age;
};

class LiveReference {
 public:
  LiveReference(double minIntervalS, double durationFactor)
      : minIntervalS_(minIntervalS), durationFactor_(durationFactor) {}

  /// Creates the worker (continuous rendering turned on).
  void start();
  /// Cancels a running trace and forgets the latest result (the view's scene, technique or
  /// the split changed).
  void cancel();
  const sl::AsyncReference* worker() const { return worker_.get(); }

  /// After a frame: a finished trace not taken yet, whole (its mask for the error overlay);
  /// it is kept as the latest without its mask. `failure` gets a failed trace's message.
  std::optional<sl::FinishedReference> takeFinished(std::string* failure);
  bool wantsTrace(std::uint64_t viewRevision) const;
  void submit(sl::ReferenceJob job);

  /// The latest trace's error for the view `viewRevision` after `framesRendered` frames.
  std::optional<LiveError> error(std::uint64_t viewRevision, std::uint64_t framesRendered) const;
  /// The latest finished trace (without its mask), of whatever view it was traced for.
  const std::optional<sl::FinishedReference>& latest() const { return latest_; }

 private:
  double minIntervalS_, durationFactor_;
  std::unique_ptr<sl::AsyncReference> worker_;
  std::optional<sl::FinishedReference> latest_;  ///< its mask dropped
};

/// "no covered pixel" when a trace measured nothing (never shown as 0), else empty.
QString unmeasuredReason(const sl::ShadowErrorStats& stats);

}  // namespace sl::ui
