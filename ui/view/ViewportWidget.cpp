// The 3D view (see ViewportWidget.h): wires its parts together; ViewPainter draws it. It
// never calls GL.
#include "view/ViewportWidget.h"

#include <optional>

#include "service/RenderService.h"

namespace sl::ui {

ViewportWidget::ViewportWidget(QWidget* parent) : QWidget(parent) {
  setAttribute(Qt::WA_OpaquePaintEvent);
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(true);  // hover: the pixel under the mouse (pixelProbed)
  setMinimumSize(160, 120);
  camera_ = new CameraController(*this, model_);
  frames_ = new FrameLoop(*this, model_, *camera_);
  measure_ = new MeasureService(*this, model_, *camera_, *frames_);
  frames_->setMeasure(measure_);
  painter_ = new ViewPainter(*this, model_, *camera_, *frames_, *measure_);

  connect(camera_, &CameraController::viewEdited, frames_, &FrameLoop::markViewChanged);
  connect(camera_, &CameraController::frameWanted, frames_, &FrameLoop::requestFrame);
  connect(camera_, &CameraController::overlayChanged, painter_, &ViewPainter::updateOverlay);
  connect(camera_, &CameraController::hoverMoved, this, [this] {
    if (painter_->pointerHighlight()) painter_->updateOverlay();
    measure_->probeHover();  // only when a visible panel shows it: else no readback
  });
  connect(camera_, &CameraController::hoverLeft, this, [this] {
    Q_EMIT measure_->pixelProbed(std::nullopt);
    if (painter_->pointerHighlight()) painter_->updateOverlay();
  });
  connect(camera_, &CameraController::dragEnded, measure_, &MeasureService::dragEnded);
  connect(camera_, &CameraController::zoomAreaPicked, painter_, &ViewPainter::setZoomArea);

  connect(frames_, &FrameLoop::overlayChanged, painter_, &ViewPainter::updateOverlay);
  connect(frames_, &FrameLoop::frameShown, painter_, &ViewPainter::frameShown);
  connect(frames_, &FrameLoop::renderProblem, this, &ViewportWidget::renderProblem);
  connect(frames_, &FrameLoop::initializationFailed, this, &ViewportWidget::initializationFailed);
  connect(frames_, &FrameLoop::serviceReady, this, &ViewportWidget::serviceReady);
  connect(measure_, &MeasureService::overlayChanged, painter_, &ViewPainter::updateOverlay);
  connect(measure_, &MeasureService::renderProblem, this, &ViewportWidget::renderProblem);
  frames_->service().start();
}

ViewportWidget::~ViewportWidget() {
  measure_->cancelLiveReferences();
  if (model_.ready) Q_EMIT rendererAboutToBeDestroyed();
  // No input while the widget goes (its filter would reach parts already gone).
  delete camera_;
  camera_ = nullptr;
  // Stops the frame in progress, frees the renderers, joins the render thread; the other
  // parts go with the widget's children.
  delete frames_;
  frames_ = nullptr;
}

void ViewportWidget::serviceReady(const QString& description) {
  model_.glDescription = description;
  model_.ready = true;
  Q_EMIT rendererReady();
  frames_->requestFrame();
}

void ViewportWidget::setScene(std::shared_ptr<const sl::Scene> scene) {
  model_.scene = std::move(scene);
  measure_->cancelLiveReferences();  // a trace of the old scene is never shown
  camera_->frameScene();
}

std::optional<std::string> ViewportWidget::setTechnique(const std::string& id) {
  if (auto error = model_.main.setTechnique(id)) return error;
  frames_->requestFrame();
  return std::nullopt;
}

void ViewportWidget::paintEvent(QPaintEvent*) {
  painter_->paint();
}

void ViewportWidget::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  painter_->resized();
  frames_->markViewChanged();
  frames_->requestFrame();
}

ViewportWidget::Readouts ViewportWidget::readouts() const {
  Readouts r;
  r.internalDivisor = model_.frameDivisor;
  r.adaptiveDivisor = frames_->adaptiveDivisor();
  r.lastFrameMs = model_.lastFrameMs;
  r.progress = frames_->progress();
  r.framesStopped = frames_->framesStopped();
  r.framesDrawn = frames_->framesDrawn();
  r.probesRead = measure_->probesRead();
  r.leftCaption = painter_->caption(false);
  r.rightCaption = painter_->caption(true);
  r.errorOverlayNote = painter_->errorOverlayNote();
  r.pointerHighlight = painter_->pointerHighlight();
  r.zoomArea = painter_->zoomArea();
  r.zoomInset = painter_->zoomInset();
  r.zoomFactor = painter_->zoomFactor();
  r.liveReference = measure_->liveReference(false);
  r.splitLiveReference = measure_->liveReference(true);
  return r;
}

QImage ViewportWidget::grabView() {
  frames_->renderFullSizeNow();
  return grab().toImage();
}

}  // namespace sl::ui
