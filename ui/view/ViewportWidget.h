// The 3D view: a plain widget that shows the last complete frame of the render service
// (ui/service/RenderService: the renderers and their GL context live on its thread). It owns
// the view's parts, which share its state (ViewModel: the two ViewSides, core/ViewSide: the
// main technique and the split view's right half with the parameters being edited; scene,
// camera, light, the frame shown):
//  - CameraController: the camera and light, moved by the mouse and keys;
//  - FrameLoop: frame requests to the render service and what comes back (pause and step,
//    the split view, adaptive resolution, continuous rendering);
//  - MeasureService: the error against the exact reference, live references, hover probes;
//  - ViewPainter: the frame shown and its overlay (ViewOverlay: banner, legends, split
//    captions, notes, zoom inset, pointer ring, light gizmo).
// The UI thread never calls GL and never waits on a frame.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <QImage>
#include <QRect>
#include <QString>
#include <QWidget>

#include "core/Renderer.h"
#include "core/ViewSide.h"
#include "metrics/AsyncReference.h"
#include "view/CameraController.h"
#include "view/FrameLoop.h"
#include "view/MeasureService.h"
#include "view/ViewModel.h"
#include "view/ViewPainter.h"

namespace sl::ui {

class RenderService;

class ViewportWidget : public QWidget {
  Q_OBJECT

 public:
  explicit ViewportWidget(QWidget* parent = nullptr);
  ~ViewportWidget() override;

  /// The main side: its technique, the parameters being edited and what its last frame
  /// published; null before the render service is ready (or after it failed).
  sl::ViewSide* mainSide() { return model_.ready ? &model_.main : nullptr; }
  const sl::ViewSide* mainSide() const { return model_.ready ? &model_.main : nullptr; }
  /// The split view's side (its technique and parameters, so that a panel may edit them);
  /// null when the split view is off or the service is not ready.
  sl::ViewSide* splitSide() { return model_.ready && model_.split ? &*model_.split : nullptr; }
  const sl::ViewSide* splitSide() const {
    return model_.ready && model_.split ? &*model_.split : nullptr;
  }
  /// The shared view and shading parameters (both halves).
  sl::ParamSet& sharedParams() { return model_.shared; }
  /// The render context's GL_RENDERER and version (empty before it is ready).
  const QString& glDescription() const { return model_.glDescription; }
  /// The render service (its thread owns every renderer of the window).
  RenderService& service() { return frames_->service(); }

  /// Shows `scene`; the camera goes to the scene's first bookmark (or a framing view) and
  /// the light to the scene's sun when it has one.
  void setScene(std::shared_ptr<const sl::Scene> scene);
  const std::shared_ptr<const sl::Scene>& scene() const { return model_.scene; }
  /// Switches technique (kept until the renderer exists). Unknown id: error, no change.
  std::optional<std::string> setTechnique(const std::string& id);
  const std::string& techniqueId() const { return model_.main.techniqueId(); }

  /// The camera and light, and the input that moves them.
  CameraController* camera() const { return camera_; }
  /// Frame requests, pause and step, the split view, adaptive resolution, continuous rendering.
  FrameLoop* frames() const { return frames_; }
  /// The error against the exact reference, live references, hover probes, figures.
  MeasureService* measure() const { return measure_; }

  /// The frame and its overlay drawn: banner, pointer ring, zoom inset, captions, notes.
  ViewPainter* painter() const { return painter_; }

  /// The view as shown, with the split half, captions, banner and legends (for PNGs).
  QImage grabView();

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

 Q_SIGNALS:
  /// The render service is ready: panels may bind to the sides' parameters.
  void rendererReady();
  /// The view is about to be destroyed: panels must drop references into its sides.
  void rendererAboutToBeDestroyed();
  /// The GL context is unusable or the renderer could not be created.
  void initializationFailed(const QString& message);
  /// A frame, a measurement or the GL debug output reported a problem (the view keeps
  /// working).
  void renderProblem(const QString& message);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

 private:
  void serviceReady(const QString& description);

  ViewModel model_;  ///< the view's state, shared by its parts
  CameraController* camera_ = nullptr;
  FrameLoop* frames_ = nullptr;
  MeasureService* measure_ = nullptr;
  ViewPainter* painter_ = nullptr;
};

}  // namespace sl::ui
