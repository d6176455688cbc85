// The 3D view (see ViewportWidget.h): wires its parts together and paints the frame shown
// with its overlay. It never calls GL.
#include "view/ViewportWidget.h"

#include <algorithm>
#include <optional>

#include <QPainter>

#include "service/RenderService.h"
#include "view/LightGizmo.h"
#include "view/ViewOverlay.h"
#include "window/MessageText.h"

namespace sl::ui {

ViewportWidget::ViewportWidget(QWidget* parent) : QWidget(parent) {
  setAttribute(Qt::WA_OpaquePaintEvent);
  overlay_ = new ViewOverlay(this);
  overlay_->hide();
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(true);  // hover: the pixel under the mouse (pixelProbed)
  setMinimumSize(160, 120);
  camera_ = new CameraController(*this, model_);
  frames_ = new FrameLoop(*this, model_, *camera_);
  measure_ = new MeasureService(*this, model_, *camera_, *frames_);
  frames_->setMeasure(measure_);

  connect(camera_, &CameraController::viewEdited, frames_, &FrameLoop::markViewChanged);
  connect(camera_, &CameraController::frameWanted, frames_, &FrameLoop::requestFrame);
  connect(camera_, &CameraController::overlayChanged, this, &ViewportWidget::updateOverlayWidget);
  connect(camera_, &CameraController::hoverMoved, this, [this] {
    if (pointerHighlight_) updateOverlayWidget();
    measure_->probeHover();  // only when a visible panel shows it: else no readback
  });
  connect(camera_, &CameraController::hoverLeft, this, [this] {
    Q_EMIT measure_->pixelProbed(std::nullopt);
    if (pointerHighlight_) updateOverlayWidget();
  });
  connect(camera_, &CameraController::dragEnded, measure_, &MeasureService::dragEnded);
  connect(camera_, &CameraController::zoomAreaPicked, this, &ViewportWidget::setZoomArea);

  connect(frames_, &FrameLoop::overlayChanged, this, &ViewportWidget::updateOverlayWidget);
  connect(frames_, &FrameLoop::frameShown, this, [this] {
    updateZoomInset();
    updateOverlayWidget();
    update();
  });
  connect(frames_, &FrameLoop::renderProblem, this, &ViewportWidget::renderProblem);
  connect(frames_, &FrameLoop::initializationFailed, this, &ViewportWidget::initializationFailed);
  connect(frames_, &FrameLoop::serviceReady, this, &ViewportWidget::serviceReady);
  connect(measure_, &MeasureService::overlayChanged, this, &ViewportWidget::updateOverlayWidget);
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
  QPainter p(this);
  if (model_.mainImage.isNull()) {
    p.fillRect(rect(), QColor(24, 26, 29));
    return;
  }
  // A reduced (adaptive) frame is stretched smoothly, as a GPU blit would; a full-size one is
  // drawn pixel for pixel.
  p.setRenderHint(QPainter::SmoothPixmapTransform, model_.frameDivisor > 1);
  const int mainW = model_.splitImage.isNull() ? width() : width() / 2;
  p.drawImage(QRect(0, 0, mainW, height()), model_.mainImage);
  if (mainW < width() && model_.splitImage.isNull())
    p.fillRect(QRect(mainW, 0, width() - mainW, height()), Qt::black);
}

void ViewportWidget::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  overlay_->setGeometry(rect());
  frames_->markViewChanged();
  frames_->requestFrame();
}

void ViewportWidget::setZoomArea(const std::optional<QRect>& area) {
  zoomArea_ = area ? std::optional<QRect>(area->intersected(rect())) : std::nullopt;
  if (zoomArea_ && zoomArea_->isEmpty()) zoomArea_.reset();
  updateZoomInset();
  updateOverlayWidget();
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
  r.leftCaption = overlay_->leftCaption;
  r.rightCaption = overlay_->rightCaption;
  r.errorOverlayNote = overlay_->errorNote;
  r.pointerHighlight = pointerHighlight_;
  r.zoomArea = zoomArea_;
  overlay_->placeInset();
  r.zoomInset = overlay_->insetRect;
  r.zoomFactor = overlay_->insetFactor;
  r.liveReference = measure_->liveReference(false);
  r.splitLiveReference = measure_->liveReference(true);
  return r;
}

void ViewportWidget::updateZoomInset() {
  if (!zoomArea_ || model_.mainImage.isNull()) {
    overlay_->zoomSource = QImage();
    return;
  }
  // The view as shown, in device pixels: each half stretched over its part (nearest).
  const QSize size = frames_->deviceSize();
  QImage shown(size, QImage::Format_RGBA8888);
  shown.fill(Qt::black);
  QPainter p(&shown);
  const int mainW = model_.splitImage.isNull() ? size.width() : size.width() / 2;
  p.drawImage(QRect(0, 0, mainW, size.height()), model_.mainImage);
  if (!model_.splitImage.isNull())
    p.drawImage(QRect(mainW, 0, size.width() - mainW, size.height()), model_.splitImage);
  p.end();
  shown.setDevicePixelRatio(devicePixelRatioF());
  overlay_->zoomSource = shown;
}

QImage ViewportWidget::grabView() {
  frames_->renderFullSizeNow();
  return grab().toImage();
}

void ViewportWidget::updateOverlayWidget() {
  const LightGizmo gizmo = model_.outsideView() ? LightGizmo{}
                                                : lightGizmo(model_.scene.get(), model_.light,
                                                             model_.camera, width(), height());
  overlay_->gizmoLines = gizmo.lines;
  overlay_->gizmoPoint = gizmo.point;
  const bool split = model_.split && !model_.splitImage.isNull();
  overlay_->split = split ? model_.splitImage : QImage();
  if (split) {
    // Continuous rendering: each half's live error (its own reference) and how old it is.
    auto caption = [this](const std::string& id, const sl::FrameStats& stats,
                          std::optional<double> exact, const std::optional<LiveError>& live,
                          const QString& unmeasured) {
      if (!model_.continuous)
        return QString::fromStdString(
            sl::sideCaption(id, stats, measure_->errorIsCurrent() ? exact : std::nullopt, {},
                            measure_->errorIsCurrent() ? unmeasured.toStdString() : std::string()));
      const bool measured = live && live->unmeasured.isEmpty();
      return QString::fromStdString(
          sl::sideCaption(id, stats, measured ? std::optional(live->errorPct) : std::nullopt,
                          live ? sl::describeReferenceAge(live->age)
                               : tr("tracing the reference\u2026").toStdString(),
                          live ? live->unmeasured.toStdString() : std::string()));
    };
    overlay_->leftCaption =
        caption(model_.main.techniqueId(), model_.main.stats(), measure_->mainErrorPct(),
                measure_->liveError(), measure_->mainUnmeasured());
    overlay_->rightCaption =
        caption(model_.splitTechniqueId, model_.split->stats(), measure_->splitErrorPct(),
                measure_->splitLiveError(), measure_->splitUnmeasured());
  }
  const sl::TechniqueInfo* mainInfo = sl::Renderer::findTechnique(model_.main.techniqueId());
  overlay_->setLegends(model_.shared, model_.main.stats(), model_.outsideView(),
                       mainInfo ? mainInfo->aliasingPattern : std::string());
  overlay_->pointerRing.reset();
  if (pointerHighlight_ && model_.hover.x() >= 0) overlay_->pointerRing = model_.hover;
  overlay_->zoomArea = zoomArea_.value_or(QRect());
  overlay_->zoomDrag = camera_->zoomDrag().value_or(QRect());
  overlay_->resolutionNote = frames_->resolutionNote();
  if (const QString busy = frames_->busyText(); !busy.isEmpty())
    overlay_->resolutionNote +=
        (overlay_->resolutionNote.isEmpty() ? QString() : QStringLiteral("  \u00b7  ")) + busy;
  overlay_->errorNote.clear();
  if (model_.continuous) {  // the live reference: how old, or being traced for this view
    const auto live = measure_->liveError();
    overlay_->errorNote = !live || live->age.stale
                              ? tr("view changed: tracing its reference\u2026")
                              : QString::fromStdString(sl::describeReferenceAge(live->age));
  } else if (!measure_->errorIsCurrent()) {
    overlay_->errorNote = tr("(computing the reference\u2026)");
  }
  overlay_->pausedText = model_.paused && model_.pausedBadge
                             ? tr("PAUSED at frame %1  \u00b7  . step  \u00b7  Space resume")
                                   .arg(static_cast<qulonglong>(model_.main.stats().frameIndex))
                             : QString();
  overlay_->setVisible(overlay_->hasContent());
  overlay_->raise();
  overlay_->update();
}

void ViewportWidget::setBanner(const QString& title, const QString& text) {
  overlay_->bannerTitle = shownMessage(title);
  overlay_->bannerText = shownSummary(text);
  overlay_->setVisible(overlay_->hasContent());
  overlay_->raise();
  overlay_->update();
}

void ViewportWidget::setPointerHighlight(bool on) {
  pointerHighlight_ = on;
  setMouseTracking(true);
  updateOverlayWidget();
}

}  // namespace sl::ui
