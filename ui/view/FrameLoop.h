// The view's frame loop (a part of ViewportWidget): asks the render service
// (ui/service/RenderService: the renderers and their GL context live on its thread) for a
// frame when something changed (a newer request replaces one not started and stops one in
// progress), and takes back what comes: the last complete frame goes into the view model.
// Also what decides how a frame is drawn: pause and single-step, the split view's second
// technique, adaptive internal resolution, continuous or on-demand rendering, and the note
// while a slow frame (or an action the window waits for) is computed. The UI thread never
// calls GL and never waits on a frame here.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include <QElapsedTimer>
#include <QImage>
#include <QObject>
#include <QSize>
#include <QString>
#include <QTimer>

#include "algo/AdaptiveResolution.h"
#include "core/Renderer.h"
#include "service/ViewFrame.h"
#include "view/ViewParts.h"

namespace sl::ui {

class RenderService;

class FrameLoop : public QObject {
  Q_OBJECT

 public:
  /// Starts the render service; frames are of `widget`'s size, of the state in `model`.
  FrameLoop(QWidget& widget, ViewModel& model, const CameraController& camera);
  ~FrameLoop() override;
  /// The measurement (live references, probes) that each order and outcome involves.
  void setMeasure(MeasureService* measure) { measure_ = measure; }

  /// The render service (its thread owns every renderer of the window).
  RenderService& service() { return *service_; }
  /// Asks for a new frame: at once when the view changed (a frame in progress is stopped),
  /// else after the one in progress. Cheap: it only sends a request.
  void requestFrame();
  /// Something that changes the image changed: the view's revision moves on (viewChanged).
  void markViewChanged();
  /// While a scene loads off the UI thread (MainWindow::loadScene) no frame starts: the first
  /// frame of a window would otherwise fail with no scene; on false, frames go on.
  void setSceneLoading(bool loading);

  /// Renders continuously (for techniques that converge over frames) instead of on demand.
  /// The exact reference is then traced on a worker thread (MeasureService::liveError).
  void setContinuous(bool on);
  bool continuous() const;

  /// Paused: no new frames (the last one stays on screen) until stepFrame() or resume.
  /// Camera and parameter changes wait for the next frame.
  /// `badge` false: no "paused" badge (grabs freeze the frame without one).
  void setPaused(bool paused, bool badge = true);
  bool paused() const;
  /// Renders exactly one frame while paused (or the next frame when running).
  void stepFrame();

  /// Split view: `techniqueId` on the right half (a second renderer, same camera, light and
  /// shared parameters), the main technique on the left. Empty: off. Unknown id: error.
  /// `params`: the right technique's own parameters (KEY -> text, the rest at their
  /// defaults); a key it does not declare or a value out of range: error, no change.
  std::optional<std::string> setSplitTechnique(
      const std::string& techniqueId, const std::map<std::string, std::string>& params = {});
  const std::string& splitTechnique() const;
  /// The right technique's own parameter values (every one it declares, as text) once its
  /// renderer has it, else those given to setSplitTechnique. Empty when the split is off.
  std::map<std::string, std::string> splitParams() const;
  /// What the split side publishes from its next frame on (a lesson text's numbers of the
  /// right half).
  void setSplitPublications(std::set<std::string> keys);

  /// Adaptive internal resolution (the shared parameters view.adaptive and
  /// view.adaptive.budget_ms, algo/AdaptiveResolution): a frame slower than the budget makes
  /// the view render at half its size (never less), stretched, with a note in the view.
  /// Scripted runs (--grab, ui/Automation.h) keep it off so that what they measure is at full
  /// size; the window allows it when interactive.
  void setAdaptiveAllowed(bool allowed);
  bool adaptiveAllowed() const { return adaptiveAllowed_; }
  /// Presenter mode: adaptive resolution is never used (every frame at full size).
  void setPresenting(bool on);
  /// Adaptive resolution is used for this frame: an interactive window, view.adaptive on, no
  /// presenter mode and no split view (whose halves are compared at full size).
  bool adaptiveActive() const;
  int adaptiveDivisor() const { return adaptive_.divisor(); }
  /// Renders the view at full size now when its last frame was reduced or is not of the view
  /// as it is (exports, grabs), or `always`; waits for it.
  void renderFullSizeNow(bool always = false);
  /// Reloads the shaders on the render thread (last good programs stay on error).
  std::optional<std::string> reloadShaders();

  /// "internal resolution 240×150: frame took 610 ms" while reduced, else empty.
  QString resolutionNote() const;
  /// While a progressive frame is partial (continuous rendering of a tiled technique):
  /// "tile k of N: drawn progressively, error when complete"; empty otherwise.
  QString progressText() const;
  /// The frame being computed, while it has taken longer than kBusyNoteMs: "rendering fvsm
  /// · 2.3 s" (the last complete frame stays on screen); empty otherwise.
  QString busyText() const;
  static constexpr int kBusyNoteMs = 250;

  /// Frames rendered since the renderer was created.
  std::uint64_t framesRendered() const;
  /// The main renderer's last frame size (device pixels).
  QSize frameSize() const;
  /// The last main frame's problem (empty: it rendered): its time and error are not numbers.
  QString frameFailure() const;
  /// The view as the renderer drew it (both halves in split view, no overlay), device
  /// pixels of the internal size; null before a frame. No GL: the last frame's copy.
  QImage renderedImage() const;
  /// The last frame's progressive resolve, if any.
  std::optional<sl::FrameStats::Progress> progress() const { return progressNote_; }
  std::uint64_t framesStopped() const { return framesStopped_; }
  std::uint64_t framesDrawn() const { return framesDrawn_; }
  /// Device pixels of the main renderer's part of the view in the last order.
  int mainWidth() const { return lastMainWidth_; }
  /// The view in device pixels.
  QSize deviceSize() const;

  // For the measurement: frames of the view as it is, drawn in the jobs that read them.
  /// Frames submitted whose outcome has not come back.
  int framesInFlight() const { return framesInFlight_; }
  /// The next order renders at full size whatever the adaptive divisor.
  void setFullSizeNext() { fullSizeNext_ = true; }
  /// What the next frame is: sizes, the sides' requests, probe and reference snapshots.
  std::shared_ptr<FrameOrder> makeOrder();
  /// Back on the UI thread: shows a complete frame, drops a stopped one.
  void applyOutcome(const std::shared_ptr<FrameOutcome>& outcome);

  /// A reduced (adaptive resolution) frame of a still view is redrawn at full size after this.
  static constexpr int kSettleDelayMs = 200;
  /// Views (and split halves) narrower or lower than this are not rendered.
  static constexpr int kMinDrawnPx = 16;

 Q_SIGNALS:
  /// The render service is ready (its GL description).
  void serviceReady(const QString& description);
  /// The GL context is unusable or the renderer could not be created.
  void initializationFailed(const QString& message);
  /// A frame was rendered; the main side's stats() describe it.
  void frameRendered();
  /// A frame or the GL debug output reported a problem (the view keeps working).
  void renderProblem(const QString& message);
  /// The split view's technique or parameter set was replaced (setSplitTechnique).
  void splitChanged();
  /// Something that changes the image changed: the shown error is out of date.
  void viewChanged();
  /// What the overlay shows changed (busy note, paused badge, split, resolution note).
  void overlayChanged();
  /// A new frame is in the model: the view is drawn again.
  void frameShown();

 private:
  /// Sends the next frame request when one is wanted (see requestFrame).
  void pump();
  /// Notices edits of the sides' parameters (a panel, a preset): the view changed.
  void noticeEdits();
  /// Renders `order` on the render thread and waits (exports, the settle of a grab).
  bool renderNow(const std::shared_ptr<FrameOrder>& order);

  QWidget& widget_;
  ViewModel& model_;
  const CameraController& camera_;
  MeasureService* measure_ = nullptr;
  RenderService* service_ = nullptr;
  int pendingSteps_ = 0;
  QSize lastFrameSize_;    ///< device pixels of the view when the last frame was ordered
  int lastMainWidth_ = 0;  ///< device pixels of the main renderer's part of the view
  bool adaptiveAllowed_ = false;
  bool presenting_ = false;
  /// The next frame renders at full size whatever the adaptive divisor (the still view's
  /// settle frame, exports).
  bool fullSizeNext_ = false;
  QTimer settleTimer_;  ///< a reduced frame of a still view is redrawn at full size
  sl::AdaptiveResolution adaptive_;
  std::optional<sl::FrameStats::Progress> progressNote_;  ///< the last frame's progress
  /// Share of view.adaptive.budget_ms a progressive frame spends on tiles (the rest: G-buffer,
  /// composite, the overshoot of the last tile, the event loop).
  static constexpr double kProgressiveShare = 0.5;

  bool frameWanted_ = false;
  std::uint64_t ordersSent_ = 0;  ///< id of the last order submitted
  std::uint64_t ordersDone_ = 0;
  std::uint64_t lastAppliedId_ = 0;  ///< the order whose frame is on screen
  /// Frames submitted to the service whose outcome has not come back (a replaced one never
  /// does; the frames of blocking calls are not counted).
  int framesInFlight_ = 0;
  std::uint64_t framesDrawn_ = 0;       ///< id of the last outcome received (shown or stopped)
  std::uint64_t sentViewRevision_ = 0;  ///< view revision of the last order submitted
  std::uint64_t framesStopped_ = 0;     ///< orders stopped before they completed
  QTimer busyTimer_;                    ///< refreshes the busy note while a frame renders
  bool busyShown_ = false;              ///< the busy note was in the overlay at the last tick
  QString busyTechnique_;               ///< of the order in flight
  bool sceneLoading_ = false;           ///< setSceneLoading
  QString callNote_;                    ///< what the window waits for (RenderService::call)
  QElapsedTimer callClock_;             ///< since that call started

  // What the sides looked like when last ordered; any difference means "view changed".
  std::uint64_t lastMainRevision_ = ~0ull;
  unsigned lastSharedRevision_ = ~0u;
  std::uint64_t lastSplitRevision_ = ~0ull;
  std::string lastProblem_;
};

}  // namespace sl::ui
