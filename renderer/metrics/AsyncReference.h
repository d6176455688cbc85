// The exact reference traced on a worker thread while the view renders continuously (issue 15
// item 6). The GUI hands over a snapshot of a frame (CPU data only: the worker never touches
// GL) tagged with the view revision it showed; the worker traces it and compares; the GUI
// takes the latest finished result under a mutex and tells from it how old it is and whether
// it still belongs to the view on screen. Traces start at a lower rate than frames (an
// interval that grows with the trace's own duration), and a cancelled trace (scene changed,
// window closed) is never delivered.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "metrics/ErrorMetrics.h"

namespace sl {

/// What one trace produced: the error of the snapshot's frame against its exact reference.
struct ReferenceTrace {
  ShadowErrorStats stats;
  std::vector<std::uint8_t> referenceMask;  ///< row 0 = top, 1 lit / 0 shadow / 255 empty
  int width = 0, height = 0;
  std::string frameSignature;  ///< what the traced frame showed (Renderer's signature)
};

struct ReferenceJob {
  std::uint64_t viewRevision = 0;  ///< the view (camera, light, scene, parameters) traced
  std::uint64_t frameNumber = 0;   ///< the frame the snapshot was read from
  /// The work, on the worker thread: the result, or nothing once `cancelled` became true.
  std::function<std::optional<ReferenceTrace>(const std::atomic<bool>& cancelled)> trace;
};

struct FinishedReference {
  std::uint64_t viewRevision = 0;
  std::uint64_t frameNumber = 0;
  double submittedS = 0.0;  ///< clock time of the snapshot (the age counts from here)
  double finishedS = 0.0;
  ReferenceTrace trace;
};

/// How the readout describes the latest finished reference.
struct ReferenceAge {
  double ageS = 0.0;            ///< since its frame was rendered
  std::uint64_t framesAgo = 0;  ///< frames rendered since its frame
  bool stale = false;           ///< traced for another view than the one shown now
};
ReferenceAge referenceAge(const FinishedReference& r, std::uint64_t currentViewRevision,
                          std::uint64_t currentFrameNumber, double nowS);
/// "reference 0.8 s old (3 frames ago)"; stale: "reference of an earlier view (2.1 s old)".
std::string describeReferenceAge(const ReferenceAge& age);

class AsyncReference {
 public:
  using Clock = std::function<double()>;  ///< monotonic seconds
  static double steadySeconds();

  /// A new trace starts at most every max(`minIntervalS`, `durationFactor` x the last
  /// trace's duration) for a still view; a view revision not yet traced starts one as soon
  /// as the worker is free.
  explicit AsyncReference(double minIntervalS = 1.0, double durationFactor = 3.0,
                          Clock clock = steadySeconds);
  ~AsyncReference();  ///< cancels the running trace and joins the worker
  AsyncReference(const AsyncReference&) = delete;
  AsyncReference& operator=(const AsyncReference&) = delete;

  /// Whether a trace should start now for the view `viewRevision`.
  bool wantsTrace(std::uint64_t viewRevision) const;
  /// Starts `job` on the worker; false (the job dropped) while another one runs.
  bool submit(ReferenceJob job);
  /// Cancels the running trace and forgets an untaken result (the scene changed): neither
  /// is ever delivered. The worker is free once the trace notices (busy() says when).
  void cancel();
  bool busy() const;
  /// The latest finished trace not taken yet (a newer one replaces an untaken older one).
  std::optional<FinishedReference> takeFinished();

  std::uint64_t submitted() const;
  std::uint64_t finished() const;   ///< delivered (or replaced before being taken)
  std::uint64_t cancelled() const;  ///< started, then cancelled (or returned nothing)
  /// The message of the last trace that threw (each is reported once), else nothing.
  std::optional<std::string> takeFailure();
  double intervalS() const;  ///< the current interval between traces of one view

 private:
  void run();

  const double minIntervalS_, durationFactor_;
  const Clock clock_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<ReferenceJob> pending_;  ///< handed to the worker
  bool running_ = false;                 ///< pending_ or a trace in progress
  bool stop_ = false;
  std::atomic<bool> cancelFlag_{false};
  std::uint64_t generation_ = 0;  ///< bumped by cancel(): older traces are dropped
  std::optional<FinishedReference> finished_;
  std::optional<std::string> failure_;
  std::optional<std::uint64_t> lastRevision_;  ///< of the last submitted trace
  double lastSubmitS_ = 0.0;
  double lastDurationS_ = 0.0;
  std::uint64_t submittedCount_ = 0, finishedCount_ = 0, cancelledCount_ = 0;
  std::thread worker_;  ///< last: starts once everything above exists
};

}  // namespace sl
