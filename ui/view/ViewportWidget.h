// The 3D view: a plain widget that shows the last complete frame of the render service
// (ui/service/RenderService: the renderers and their GL context live on its thread) and turns mouse
// and keys into camera moves. It holds the two ViewSides (core/ViewSide: the main technique
// and the split view's right half, with the parameters being edited), sends the service a
// frame request when something changed (a newer request replaces one not started and stops
// one in progress), and draws what comes back; the UI thread never calls GL and never waits
// on a frame. The (slow) shadow error is traced on the render thread once the view has been
// still a while. Teaching extras: pause and single-step, a banner (lesson, pass being
// stepped), legends of the renderer's overlays, a split view with a second technique on the
// right half, and a note while a slow frame is being computed.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include <QElapsedTimer>
#include <QImage>
#include <QWidget>
#include <QPoint>
#include <QPointF>
#include <QPointF>
#include <QTimer>

#include "figures/FigureKit.h"
#include "algo/AdaptiveResolution.h"
#include "core/Renderer.h"
#include "core/ViewSide.h"
#include "service/LiveReference.h"
#include "service/ViewFrame.h"
#include "metrics/AsyncReference.h"

namespace sl::ui {

class ViewOverlay;
class RenderService;
class RenderContext;

class ViewportWidget : public QWidget {
  Q_OBJECT

 public:
  explicit ViewportWidget(QWidget* parent = nullptr);
  ~ViewportWidget() override;

  /// The main side: its technique, the parameters being edited and what its last frame
  /// published; null before the render service is ready (or after it failed).
  sl::ViewSide* mainSide() { return ready_ ? &main_ : nullptr; }
  const sl::ViewSide* mainSide() const { return ready_ ? &main_ : nullptr; }
  /// The shared view and shading parameters (both halves).
  sl::ParamSet& sharedParams() { return shared_; }
  /// The render context's GL_RENDERER and version (empty before it is ready).
  const QString& glDescription() const { return glDescription_; }
  /// The render service (its thread owns every renderer of the window).
  RenderService& service() { return *service_; }
  /// Asks for a new frame: at once when the view changed (a frame in progress is stopped),
  /// else after the one in progress. Cheap: it only sends a request.
  void requestFrame();

  /// Shows `scene`; the camera goes to the scene's first bookmark (or a framing view) and
  /// the light to the scene's sun when it has one.
  void setScene(std::shared_ptr<const sl::Scene> scene);
  /// While a scene loads off the UI thread (MainWindow::loadScene) no frame starts: the first
  /// frame of a window would otherwise fail with no scene; on false, frames go on.
  void setSceneLoading(bool loading);
  const std::shared_ptr<const sl::Scene>& scene() const { return scene_; }

  /// Switches technique (kept until the renderer exists). Unknown id: error, no change.
  std::optional<std::string> setTechnique(const std::string& id);
  const std::string& techniqueId() const { return main_.techniqueId(); }

  void setCamera(const sl::Camera& camera);
  const sl::Camera& camera() const { return camera_; }
  /// Camera of the scene's bookmark `index`, or the framing view for -1.
  void goToBookmark(int index);
  void resetView();
  /// The outside view (the renderer's view.outside): a third camera showing the frusta;
  /// while on, a left drag orbits it and the wheel moves it in or out (main camera fixed).
  bool outsideView() const;
  bool setOutsideView(bool on);  ///< false when the renderer has no such parameter

  void setLight(const sl::Light& light);
  const sl::Light& light() const { return light_; }

  /// Renders continuously (for techniques that converge over frames) instead of on demand.
  /// The exact reference is then traced on a worker thread (metrics/AsyncReference) at a
  /// lower rate, and liveError() says what the latest one measured and how old it is.
  void setContinuous(bool on);
  bool continuous() const { return continuous_; }

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
  /// Lower rate of the live reference: at most one trace per this many seconds of a still
  /// view, or per this factor times the last trace's duration when that is longer.
  static constexpr double kLiveReferenceMinIntervalS = 0.75;
  static constexpr double kLiveReferenceDurationFactor = 3.0;

  /// Whether a visible panel shows the pixel under the mouse (PublicationDocks): only then
  /// is it read back (a GPU sync) on mouse moves and frames.
  void setProbeWanted(bool wanted);
  bool probeWanted() const { return probeWanted_; }
  /// Adaptive internal resolution (the shared parameters view.adaptive and
  /// view.adaptive.budget_ms, algo/AdaptiveResolution): a frame slower than the budget makes
  /// the view render at half its size (never less), stretched, with a note in the view.
  /// Scripted runs (--grab, ui/Automation.h) keep it off so that what they measure is at full
  /// size; the window allows it when interactive.
  void setAdaptiveAllowed(bool allowed);
  bool adaptiveAllowed() const { return adaptiveAllowed_; }
  /// "internal resolution 240×150: frame took 610 ms" while reduced, else empty.
  QString resolutionNote() const;
  /// While a progressive frame is partial (continuous rendering of a tiled technique):
  /// "tile k of N: drawn progressively, error when complete"; empty otherwise.
  QString progressText() const;

  /// Computes the error of the last frame now on the render thread and waits for it (for
  /// exports and scripts; the interactive view computes it in the background).
  /// Returns the error in percent, or nothing (and emits renderProblem) on failure.
  std::optional<double> computeErrorNow();
  /// The frame being computed, while it has taken longer than kBusyNoteMs: "rendering fvsm
  /// · 2.3 s" (the last complete frame stays on screen); empty otherwise.
  QString busyText() const;
  static constexpr int kBusyNoteMs = 250;
  /// Whether the error shown for the current view is up to date.
  bool errorIsCurrent() const { return errorRevision_ == viewRevision_; }

  /// Reloads the shaders on the render thread (last good programs stay on error).
  std::optional<std::string> reloadShaders();

  /// Frames rendered since the renderer was created.
  std::uint64_t framesRendered() const { return framesRendered_; }
  /// The main renderer's last frame size (device pixels).
  QSize frameSize() const { return internalSize_; }

  /// How long the view must be still before the error is recomputed.
  static constexpr int kErrorDelayMs = 1200;
  /// A reduced (adaptive resolution) frame of a still view is redrawn at full size after this.
  static constexpr int kSettleDelayMs = 200;
  /// Views (and split halves) narrower or lower than this are not rendered.
  static constexpr int kMinDrawnPx = 16;
  /// The fly keys' tick while one is held.
  static constexpr int kFlyTickMs = 16;

  /// Paused: no new frames (the last one stays on screen) until stepFrame() or resume.
  /// Camera and parameter changes wait for the next frame.
  /// `badge` false: no "paused" badge (grabs freeze the frame without one).
  void setPaused(bool paused, bool badge = true);
  bool paused() const { return paused_; }
  /// Renders exactly one frame while paused (or the next frame when running).
  void stepFrame();

  /// Split view: `techniqueId` on the right half (a second renderer, same camera, light and
  /// shared parameters), the main technique on the left. Empty: off. Unknown id: error.
  /// `params`: the right technique's own parameters (KEY -> text, the rest at their
  /// defaults); a key it does not declare or a value out of range: error, no change.
  std::optional<std::string> setSplitTechnique(
      const std::string& techniqueId, const std::map<std::string, std::string>& params = {});
  const std::string& splitTechnique() const { return splitTechniqueId_; }
  /// The right technique's own parameter values (every one it declares, as text) once its
  /// renderer has it, else those given to setSplitTechnique. Empty when the split is off.
  std::map<std::string, std::string> splitParams() const;

  /// Presenter mode: a ring follows the mouse over the view (the pointer highlight).
  void setPointerHighlight(bool on);
  /// Presenter mode: adaptive resolution is never used (every frame at full size).
  void setPresenting(bool on);
  /// Adaptive resolution is used for this frame: an interactive window, view.adaptive on, no
  /// presenter mode and no split view (whose halves are compared at full size).
  bool adaptiveActive() const;
  /// Renders the view at full size now when its last frame was reduced or is not of the view
  /// as it is (exports, grabs), or `always`; waits for it.
  void renderFullSizeNow(bool always = false);
  /// Runs `read` on the render thread with the main renderer holding a complete frame of the
  /// view as it is (drawn first, in the same job, when the frame shown is older or one is on
  /// its way) and waits: scripted reads of the last frame (readback, probe, exact error).
  /// False when the render service is not running.
  bool readCurrentFrame(const std::function<void(sl::Renderer&)>& read);
  /// A probe of the pixel under the mouse is on its way (scripts wait for it).
  bool probePending() const { return probeWanted_ && (probeInFlight_ || probeAgain_); }

  /// The zoom inset: `area` of the view (widget pixels) magnified by a whole factor,
  /// nearest neighbour, into the bottom-right corner; nothing: off. Ctrl+Shift+drag over the
  /// view sets it, Ctrl+Shift+click clears it.
  void setZoomArea(const std::optional<QRect>& area);
  /// How the view drew its last frame and what its captions say, read by scripts
  /// (ui/Automation.h) as one snapshot.
  struct Readouts {
    int internalDivisor = 1;   ///< the divisor the last frame was rendered at (1: full size)
    int adaptiveDivisor = 1;   ///< adaptive state's (a still view's settle frame may be full size)
    double lastFrameMs = 0.0;  ///< wall clock of the last frame (both halves; >= its timed passes)
    std::optional<sl::FrameStats::Progress> progress;  ///< last frame's progressive resolve
    std::uint64_t framesStopped = 0;  ///< frames stopped by a newer request before completing
    std::uint64_t framesDrawn = 0;    ///< frames put on screen (also those of a view changed since)
    std::uint64_t probesRead = 0;     ///< pixels read back for the hover probe (this renderer)
    QString leftCaption, rightCaption;  ///< drawn under the split view's halves (empty: none)
    /// The line under the error overlay's legend (the reference's age, or that it is being
    /// traced); empty when the reference is current in on-demand rendering.
    QString errorOverlayNote;
    bool pointerHighlight = false;  ///< presenter mode's ring follows the mouse
    std::optional<QRect> zoomArea;  ///< the zoom inset's source (widget pixels)
    QRect zoomInset;                ///< where the inset was last drawn; empty when off
    int zoomFactor = 0;             ///< its magnification; 0 when off
    /// The reference workers of continuous rendering (null before it was first turned on).
    const sl::AsyncReference* liveReference = nullptr;
    const sl::AsyncReference* splitLiveReference = nullptr;
  };
  Readouts readouts() const;
  /// The view as the renderer drew it (both halves in split view, no overlay), device
  /// pixels of the internal size; null before a frame. No GL: the last frame's copy.
  QImage renderedImage() const;

  /// The split view's side (its technique and parameters, so that a panel may edit them);
  /// null when the split view is off or the service is not ready.
  sl::ViewSide* splitSide() { return ready_ && split_ ? &*split_ : nullptr; }
  const sl::ViewSide* splitSide() const { return ready_ && split_ ? &*split_ : nullptr; }
  /// What the split side publishes from its next frame on (a lesson text's numbers of the
  /// right half).
  void setSplitPublications(std::set<std::string> keys);

  /// "Equal memory": the split technique's declared memory knob (`ParamDecl::memoryKnob`: a
  /// map's resolution, rmsm/asm's pool pages, virtual-tiled's tile resolution; fvsm has none: its
  /// textures follow each frame's needs)
  /// searched for the largest value whose memory() is at most the main technique's, each
  /// candidate measured by rendering the right half (memory need not be a function of the
  /// knob alone). Assumes memory grows with it (doubling, then bisection: about
  /// 2 log2(range) frames; tests/gl checks the growth for every technique).
  struct MemoryMatch {
    std::string key;               ///< the parameter set
    long long value = 0;           ///< its value now
    std::uint64_t mainBytes = 0;   ///< the main technique's memory()
    std::uint64_t splitBytes = 0;  ///< the split technique's at `value`
    bool belowMinimum = false;     ///< even the smallest value spends more than main
    int framesMeasured = 0;
  };
  std::optional<MemoryMatch> matchSplitMemory(std::string* error);

  /// A banner over the top of the view (lesson title, pass being stepped); empty: none.
  void setBanner(const QString& title, const QString& text);

  /// The view as shown, with the split half, captions, banner and legends (for PNGs).
  QImage grabView();

  /// File > Export figure: each half of the view (the main technique, the split view's) as
  /// rendered in the last frame with its error image (wrong pixels dilated by `dilatePx`),
  /// labelled with the technique and the parameters that differ from their defaults, and
  /// its texels, bytes, error and frame time. Computes the error now (a fraction of a
  /// second); empty before the first frame or when it fails (renderProblem says why).
  std::vector<FigureCell> figureCells(int dilatePx);

  /// The error of the (left half of the) view, once computed for it.
  std::optional<double> errorPct() const { return errorIsCurrent() ? mainErrorPct_ : std::nullopt; }
  /// Why the current view's error is n/a (a failed frame, no covered pixel); empty when it
  /// was measured or not evaluated yet.
  QString errorNotMeasured() const { return errorIsCurrent() ? errorUnmeasured_ : QString(); }
  /// The last main frame's problem (empty: it rendered): its time and error are not numbers.
  QString frameFailure() const { return frameFailure_; }
  /// The error of the right half (split view), once computed.
  std::optional<double> splitErrorPct() const { return splitErrorPct_; }

 public Q_SLOTS:
  /// The fly keys W/S, A/D, Q/E (ui/window/WindowShortcuts sends them from anywhere in the window):
  /// the view flies while one is held. A repeat changes nothing; false for another key.
  bool flyKeyPressed(int key, bool autoRepeat);
  bool flyKeyReleased(int key, bool autoRepeat);
  /// Lets go of every held fly key (the window lost the keyboard).
  void stopFlying();

 Q_SIGNALS:
  /// The render service is ready: panels may bind to the sides' parameters.
  void rendererReady();
  /// The view is about to be destroyed: panels must drop references into its sides.
  void rendererAboutToBeDestroyed();
  /// The GL context is unusable or the renderer could not be created.
  void initializationFailed(const QString& message);
  /// A frame was rendered; mainSide()->stats() describes it.
  void frameRendered();
  /// renderFrame or the GL debug output reported a problem (the view keeps working).
  void renderProblem(const QString& message);
  /// The split view's technique or parameter set was replaced (setSplitTechnique).
  void splitChanged();
  /// The camera moved (mouse, keys, bookmark, reset).
  void cameraChanged();
  /// The light changed (setLight, a new scene, Alt+drag in the view).
  void lightChanged();
  /// Something that changes the image changed: the shown error is out of date.
  void viewChanged();
  /// A fresh error for the current view, in percent of covered pixels.
  void errorComputed(double errorPct);
  /// The error of the current view was evaluated and is not a number: `why` (the frame
  /// failed: its problem; no covered pixel). Never shown as 0.
  void errorUnmeasured(const QString& why);
  /// The main camera's pixel under the mouse (the left half in split view), read from the
  /// last frame on every mouse move and every new frame; nothing when the mouse left the
  /// view, is over the right half or the outside view is shown.
  void pixelProbed(const std::optional<sl::PixelProbe>& probe);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void leaveEvent(QEvent* event) override;
  void keyReleaseEvent(QKeyEvent* event) override;
  void focusOutEvent(QFocusEvent* event) override;

 private:
  QString errorOverlayNote() const;
  QString splitCaption(bool right) const;
  QRect zoomInsetRect() const;  ///< places the inset first
  int zoomFactor() const;
  /// Turns the outside camera and scales its zoom (clamped to the declared ranges).
  void adjustOutsideView(float azimuthDeg, float elevationDeg, float zoomFactor);
  void serviceReady(const QString& description);
  QSize deviceSize() const;  ///< the view in device pixels
  /// Back from the render thread: the errors of the view `viewRevision` (dropped when the
  /// view moved on since).
  void applyError(std::uint64_t viewRevision, const SideError& main,
                  const std::optional<SideError>& split);
  /// The last main frame failed: its error is n/a with the reason (true), else false.
  bool failedFrameUnmeasured();
  /// Sends the next frame request when one is wanted (see requestFrame).
  void pump();
  /// What the next frame is: sizes, the sides' requests, probe and reference snapshots.
  std::shared_ptr<FrameOrder> makeOrder();
  /// Back on the UI thread: shows a complete frame, drops a stopped one.
  void applyOutcome(const std::shared_ptr<FrameOutcome>& outcome);
  /// Renders `order` on the render thread and waits (exports, the settle of a grab).
  bool renderNow(const std::shared_ptr<FrameOrder>& order);
  void updateOverlayWidget();
  /// The light gizmo in widget pixels (sun arrow, bulb, or spot cone) for the overlay.
  void updateLightGizmo();
  /// Alt+left drag: az/el for a directional light, the position on a horizontal plane
  /// for spot and point (the point under the cursor follows it, at the light's depth).
  void dragLight(const QPoint& delta);
  void markViewChanged();
  /// Notices edits of the sides' parameters (a panel, a preset): the view changed.
  void noticeEdits();
  void flyStep();
  void computeErrorIfStill();
  /// Continuous rendering, after a frame: takes finished references (the main one's mask to
  /// the error overlay when it is of this view) and submits traces that are due.
  void updateLiveReferences(FrameOutcome& outcome);
  void updateZoomInset();
  void probeHover();  ///< asks the render thread for the pixel under hover_ (pixelProbed)

  RenderService* service_ = nullptr;
  bool ready_ = false;
  QString glDescription_;
  sl::ParamSet shared_;
  sl::ViewSide main_;
  std::optional<sl::ViewSide> split_;  ///< the right half, while the split view is on
  std::set<std::string> splitPublicationKeys_;
  std::string splitTechniqueId_;
  std::map<std::string, std::string> splitParams_;  ///< given to setSplitTechnique
  std::optional<double> splitErrorPct_;
  std::optional<double> mainErrorPct_;
  QString errorUnmeasured_, splitErrorUnmeasured_;  ///< why the error is n/a (empty: measured)
  QString frameFailure_;  ///< the last main frame's problem (empty: it rendered)
  QImage mainImage_;      ///< the last complete frame's main half (internal size)
  QImage splitImage_;     ///< its right half (internal size)
  ViewOverlay* overlay_ = nullptr;
  bool paused_ = false;
  bool pausedBadge_ = true;
  int pendingSteps_ = 0;
  QSize lastFrameSize_;        ///< device pixels of the view when the last frame was ordered
  int lastMainWidth_ = 0;      ///< device pixels of the main renderer's part of the view
  QPointF hover_{-1.0, -1.0};  ///< the mouse over the view (widget pixels), -1: not over it
  bool pointerHighlight_ = false;
  std::optional<QRect> zoomArea_;      ///< widget pixels
  std::optional<QRect> zoomDragging_;  ///< the rectangle while Ctrl+Shift+drag draws it
  QPoint zoomDragStart_;
  std::shared_ptr<const sl::Scene> scene_;
  sl::Camera camera_;
  sl::Light light_;
  bool continuous_ = false;
  LiveReference liveMain_, liveSplit_;  ///< each side's live reference (continuous rendering)
  /// A finished main trace's mask for the error overlay, sent with the next frame order.
  std::optional<sl::FinishedReference> maskToUpload_;
  /// Cancels both halves' running traces and forgets their results.
  void cancelLiveReferences();
  bool probeWanted_ = false;
  bool adaptiveAllowed_ = false;
  bool presenting_ = false;
  /// The next frame renders at full size whatever the adaptive divisor (the still view's
  /// settle frame, exports).
  bool fullSizeNext_ = false;
  QTimer settleTimer_;  ///< a reduced frame of a still view is redrawn at full size
  sl::AdaptiveResolution adaptive_;
  int frameDivisor_ = 1;  ///< of the last frame
  QSize internalSize_;    ///< the main renderer's last frame (device pixels)
  double lastFrameMs_ = 0.0;
  std::optional<sl::FrameStats::Progress> progressNote_;  ///< the last frame's progress
  /// Share of view.adaptive.budget_ms a progressive frame spends on tiles (the rest: G-buffer,
  /// composite, the overshoot of the last tile, the event loop).
  static constexpr double kProgressiveShare = 0.5;
  std::uint64_t probesRead_ = 0;
  bool probeInFlight_ = false;  ///< a hover probe is on the render thread
  bool probeAgain_ = false;     ///< the mouse moved meanwhile: probe again when it answers
                                ///< probe asked for (older answers are dropped)

  // The frame loop: a wanted frame, the orders sent and the outcomes back.
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
  std::uint64_t viewRevision_ = 1;
  std::uint64_t shownViewRevision_ = 0;  ///< of the frame on screen
  std::uint64_t errorRevision_ = 0;
  std::uint64_t framesRendered_ = 0;
  std::string lastProblem_;

  QTimer errorTimer_;  ///< single shot: fires when the view has been still
  QTimer flyTimer_;    ///< ticks while a fly key is held
  QElapsedTimer flyClock_;
  std::set<int> heldKeys_;
  Qt::MouseButton dragButton_ = Qt::NoButton;
  QPoint lastMouse_;
};

}  // namespace sl::ui
