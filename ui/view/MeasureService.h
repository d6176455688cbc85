// What the view measures (a part of ViewportWidget): the shadow error of the view as it is
// against the exact reference (traced on the render thread once the view has been still a
// while, or at once for exports and scripts), the live reference of each side in continuous
// rendering (metrics/AsyncReference, at a lower rate), the pixel under the mouse (the hover
// probe), the figure export and the split view's equal-memory match. Each runs as a job on
// the render service; results come back as queued calls and are kept only for the view
// revision they were measured for.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <QObject>
#include <QString>
#include <QTimer>

#include "core/Renderer.h"
#include "figures/FigureKit.h"
#include "metrics/AsyncReference.h"
#include "service/LiveReference.h"
#include "service/ViewFrame.h"
#include "view/ViewParts.h"

namespace sl::ui {

class MeasureService : public QObject {
  Q_OBJECT

 public:
  MeasureService(QWidget& widget, ViewModel& model, const CameraController& camera,
                 FrameLoop& frames);
  ~MeasureService() override;

  using LiveError = sl::ui::LiveError;
  /// Continuous rendering's error: the latest finished reference's error, its age, and
  /// whether it was traced for another view than the one shown (`age.stale`: the number is
  /// that earlier view's, and a trace of the current view is under way or due).
  std::optional<LiveError> liveError() const;
  /// The readout of it: "error 0.420 % · reference 0.8 s old (3 frames ago)", or with
  /// "of an earlier view … re-tracing" when stale; "error — · tracing the reference…"
  /// before the first. Empty when not rendering continuously.
  QString liveErrorText() const;
  /// The split view's right half in continuous rendering: its own reference, traced on its
  /// own worker at the same lower rate (its half may be a pixel wider than the left one and
  /// its technique's frame is its own), what it measured and how old it is; the right
  /// caption shows it. Null / empty without a split view or continuous rendering.
  std::optional<LiveError> splitLiveError() const;
  /// The reference workers of continuous rendering (null before it was first turned on).
  const sl::AsyncReference* liveReference(bool split) const;
  /// Lower rate of the live reference: at most one trace per this many seconds of a still
  /// view, or per this factor times the last trace's duration when that is longer.
  static constexpr double kLiveReferenceMinIntervalS = 0.75;
  static constexpr double kLiveReferenceDurationFactor = 3.0;

  /// Whether a visible panel shows the pixel under the mouse (PublicationDocks): only then
  /// is it read back (a GPU sync) on mouse moves and frames.
  void setProbeWanted(bool wanted);
  bool probeWanted() const { return probeWanted_; }
  /// A probe of the pixel under the mouse is on its way (scripts wait for it).
  bool probePending() const { return probeWanted_ && (probeInFlight_ || probeAgain_); }
  /// Pixels read back for the hover probe (this renderer).
  std::uint64_t probesRead() const { return probesRead_; }

  /// Computes the error of the last frame now on the render thread and waits for it (for
  /// exports and scripts; the interactive view computes it in the background).
  /// Returns the error in percent, or nothing (and emits renderProblem) on failure.
  std::optional<double> computeErrorNow();
  /// Whether the error shown for the current view is up to date.
  bool errorIsCurrent() const;
  /// The error of the (left half of the) view, once computed for it.
  std::optional<double> errorPct() const;
  /// Why the current view's error is n/a (a failed frame, no covered pixel); empty when it
  /// was measured or not evaluated yet.
  QString errorNotMeasured() const;
  /// The error of the right half (split view), once computed.
  std::optional<double> splitErrorPct() const { return splitErrorPct_; }
  /// The same as shown under the halves: each half's error and why it is n/a.
  std::optional<double> mainErrorPct() const { return mainErrorPct_; }
  QString mainUnmeasured() const { return errorUnmeasured_; }
  QString splitUnmeasured() const { return splitErrorUnmeasured_; }
  /// How long the view must be still before the error is recomputed.
  static constexpr int kErrorDelayMs = 1200;

  /// Runs `read` on the render thread with the main renderer holding a complete frame of the
  /// view as it is (drawn first, in the same job, when the frame shown is older or one is on
  /// its way) and waits: scripted reads of the last frame (readback, probe, exact error).
  /// False when the render service is not running.
  bool readCurrentFrame(const std::function<void(sl::Renderer&)>& read);

  /// File > Export figure: each half of the view (the main technique, the split view's) as
  /// rendered in the last frame with its error image (wrong pixels dilated by `dilatePx`),
  /// labelled with the technique and the parameters that differ from their defaults, and
  /// its texels, bytes, error and frame time. Computes the error now (a fraction of a
  /// second); empty before the first frame or when it fails (renderProblem says why).
  std::vector<FigureCell> figureCells(int dilatePx);

  /// "Equal memory": the split technique's declared memory knob (`ParamDecl::memoryKnob`: a
  /// map's resolution, rmsm/asm's pool pages, virtual-tiled's tile resolution; fvsm has none:
  /// its textures follow each frame's needs) searched for the largest value whose memory() is
  /// at most the main technique's, each candidate measured by rendering the right half
  /// (memory need not be a function of the knob alone). Assumes memory grows with it
  /// (doubling, then bisection: about 2 log2(range) frames; tests/gl checks the growth for
  /// every technique).
  struct MemoryMatch {
    std::string key;               ///< the parameter set
    long long value = 0;           ///< its value now
    std::uint64_t mainBytes = 0;   ///< the main technique's memory()
    std::uint64_t splitBytes = 0;  ///< the split technique's at `value`
    bool belowMinimum = false;     ///< even the smallest value spends more than main
    int framesMeasured = 0;
  };
  std::optional<MemoryMatch> matchSplitMemory(std::string* error);

  // What the frame loop, the camera and the view tell the measurement.
  /// A frame order goes out: the hover probe and the reference snapshots it carries.
  void prepareOrder(FrameOrder& order);
  /// Continuous rendering, after a complete frame of the view: takes finished references
  /// (the main one's mask to the error overlay when it is of this view) and submits traces
  /// that are due.
  void updateLiveReferences(FrameOutcome& outcome);
  /// A frame of the current view was shown (`partial`: a progressive one, not measured): its
  /// probe goes out and the still view's error is scheduled.
  void frameApplied(const FrameOutcome& outcome, bool partial);
  /// Continuous rendering was turned on or off; paused; the split view was replaced or
  /// edited; a drag ended; a new scene.
  void continuousChanged(bool on);
  void pausedChanged(bool paused);
  void forgetSplitError(bool cancelTrace);
  void dragEnded();
  /// Cancels both halves' running traces and forgets their results.
  void cancelLiveReferences();
  /// Asks the render thread for the pixel under the mouse (pixelProbed).
  void probeHover();

 Q_SIGNALS:
  /// A fresh error for the current view, in percent of covered pixels.
  void errorComputed(double errorPct);
  /// The error of the current view was evaluated and is not a number: `why` (the frame
  /// failed: its problem; no covered pixel). Never shown as 0.
  void errorUnmeasured(const QString& why);
  /// The main camera's pixel under the mouse (the left half in split view), read from the
  /// last frame on every mouse move and every new frame; nothing when the mouse left the
  /// view, is over the right half or the outside view is shown.
  void pixelProbed(const std::optional<sl::PixelProbe>& probe);
  /// A measurement failed (the view keeps working).
  void renderProblem(const QString& message);
  /// What the overlay shows changed (the error, its note).
  void overlayChanged();

 private:
  /// Back from the render thread: the errors of the view `viewRevision` (dropped when the
  /// view moved on since).
  void applyError(std::uint64_t viewRevision, const SideError& main,
                  const std::optional<SideError>& split);
  /// The last main frame failed: its error is n/a with the reason (true), else false.
  bool failedFrameUnmeasured();
  void computeErrorIfStill();

  QWidget& widget_;
  ViewModel& model_;
  const CameraController& camera_;
  FrameLoop& frames_;
  LiveReference liveMain_, liveSplit_;  ///< each side's live reference (continuous rendering)
  /// A finished main trace's mask for the error overlay, sent with the next frame order.
  std::optional<sl::FinishedReference> maskToUpload_;
  std::optional<double> splitErrorPct_;
  std::optional<double> mainErrorPct_;
  QString errorUnmeasured_, splitErrorUnmeasured_;  ///< why the error is n/a (empty: measured)
  std::uint64_t errorRevision_ = 0;
  QTimer errorTimer_;  ///< single shot: fires when the view has been still
  bool probeWanted_ = false;
  std::uint64_t probesRead_ = 0;
  bool probeInFlight_ = false;  ///< a hover probe is on the render thread
  bool probeAgain_ = false;     ///< the mouse moved meanwhile: probe again when it answers
};

}  // namespace sl::ui
