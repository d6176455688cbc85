// What the 3D view draws (see ViewPainter.h). No GL: the frame is the last one's copy.
#include "view/ViewPainter.h"

#include <optional>

#include <QPainter>
#include <QWidget>

#include "view/CameraController.h"
#include "view/FrameLoop.h"
#include "view/LightGizmo.h"
#include "view/MeasureService.h"
#include "view/ViewModel.h"
#include "view/ViewOverlay.h"
#include "window/MessageText.h"

namespace sl::ui {

ViewPainter::ViewPainter(QWidget& widget, const ViewModel& model, const CameraController& camera,
                         const FrameLoop& frames, const MeasureService& measure)
    : QObject(&widget),
      widget_(widget),
      model_(model),
      camera_(camera),
      frames_(frames),
      measure_(measure) {
  overlay_ = new ViewOverlay(&widget_);
  overlay_->hide();
}

void ViewPainter::resized() {
  overlay_->setGeometry(widget_.rect());
}

void ViewPainter::frameShown() {
  updateZoomInset();
  updateOverlay();
  widget_.update();
}

QRect ViewPainter::zoomInset() const {
  overlay_->placeInset();
  return overlay_->insetRect;
}

int ViewPainter::zoomFactor() const {
  overlay_->placeInset();
  return overlay_->insetFactor;
}

QString ViewPainter::caption(bool right) const {
  return right ? overlay_->rightCaption : overlay_->leftCaption;
}

QString ViewPainter::errorOverlayNote() const {
  return overlay_->errorNote;
}

void ViewPainter::paint() {
  QPainter p(&widget_);
  if (model_.mainImage.isNull()) {
    p.fillRect(widget_.rect(), QColor(24, 26, 29));
    return;
  }
  // A reduced (adaptive) frame is stretched smoothly, as a GPU blit would; a full-size one is
  // drawn pixel for pixel.
  p.setRenderHint(QPainter::SmoothPixmapTransform, model_.frameDivisor > 1);
  const int mainW = model_.splitImage.isNull() ? widget_.width() : widget_.width() / 2;
  p.drawImage(QRect(0, 0, mainW, widget_.height()), model_.mainImage);
  if (mainW < widget_.width() && model_.splitImage.isNull())
    p.fillRect(QRect(mainW, 0, widget_.width() - mainW, widget_.height()), Qt::black);
}

void ViewPainter::setZoomArea(const std::optional<QRect>& area) {
  zoomArea_ = area ? std::optional<QRect>(area->intersected(widget_.rect())) : std::nullopt;
  if (zoomArea_ && zoomArea_->isEmpty()) zoomArea_.reset();
  updateZoomInset();
  updateOverlay();
}

void ViewPainter::updateZoomInset() {
  if (!zoomArea_ || model_.mainImage.isNull()) {
    overlay_->zoomSource = QImage();
    return;
  }
  // The view as shown, in device pixels: each half stretched over its part (nearest).
  const QSize size = frames_.deviceSize();
  QImage shown(size, QImage::Format_RGBA8888);
  shown.fill(Qt::black);
  QPainter p(&shown);
  const int mainW = model_.splitImage.isNull() ? size.width() : size.width() / 2;
  p.drawImage(QRect(0, 0, mainW, size.height()), model_.mainImage);
  if (!model_.splitImage.isNull())
    p.drawImage(QRect(mainW, 0, size.width() - mainW, size.height()), model_.splitImage);
  p.end();
  shown.setDevicePixelRatio(widget_.devicePixelRatioF());
  overlay_->zoomSource = shown;
}

void ViewPainter::updateOverlay() {
  const LightGizmo gizmo = model_.outsideView()
                               ? LightGizmo{}
                               : lightGizmo(model_.scene.get(), model_.light, model_.camera,
                                            widget_.width(), widget_.height());
  overlay_->gizmoLines = gizmo.lines;
  overlay_->gizmoPoint = gizmo.point;
  const bool split = model_.split && !model_.splitImage.isNull();
  overlay_->split = split ? model_.splitImage : QImage();
  if (split) {
    // Continuous rendering: each half's live error (its own reference) and how old it is.
    auto captionOf = [this](const std::string& id, const sl::FrameStats& stats,
                            std::optional<double> exact, const std::optional<LiveError>& live,
                            const QString& unmeasured) {
      if (!model_.continuous)
        return QString::fromStdString(
            sl::sideCaption(id, stats, measure_.errorIsCurrent() ? exact : std::nullopt, {},
                            measure_.errorIsCurrent() ? unmeasured.toStdString() : std::string()));
      const bool measured = live && live->unmeasured.isEmpty();
      return QString::fromStdString(
          sl::sideCaption(id, stats, measured ? std::optional(live->errorPct) : std::nullopt,
                          live ? sl::describeReferenceAge(live->age)
                               : tr("tracing the reference\u2026").toStdString(),
                          live ? live->unmeasured.toStdString() : std::string()));
    };
    overlay_->leftCaption =
        captionOf(model_.main.techniqueId(), model_.main.stats(), measure_.mainErrorPct(),
                  measure_.liveError(), measure_.mainUnmeasured());
    overlay_->rightCaption =
        captionOf(model_.splitTechniqueId, model_.split->stats(), measure_.splitErrorPct(),
                  measure_.splitLiveError(), measure_.splitUnmeasured());
  }
  const sl::TechniqueInfo* mainInfo = sl::Renderer::findTechnique(model_.main.techniqueId());
  overlay_->setLegends(model_.shared, model_.main.stats(), model_.outsideView(),
                       mainInfo ? mainInfo->aliasingPattern : std::string());
  overlay_->pointerRing.reset();
  if (pointerHighlight_ && model_.hover.x() >= 0) overlay_->pointerRing = model_.hover;
  overlay_->zoomArea = zoomArea_.value_or(QRect());
  overlay_->zoomDrag = camera_.zoomDrag().value_or(QRect());
  overlay_->resolutionNote = frames_.resolutionNote();
  if (const QString busy = frames_.busyText(); !busy.isEmpty())
    overlay_->resolutionNote +=
        (overlay_->resolutionNote.isEmpty() ? QString() : QStringLiteral("  \u00b7  ")) + busy;
  overlay_->errorNote.clear();
  if (model_.continuous) {  // the live reference: how old, or being traced for this view
    const auto live = measure_.liveError();
    overlay_->errorNote = !live || live->age.stale
                              ? tr("view changed: tracing its reference\u2026")
                              : QString::fromStdString(sl::describeReferenceAge(live->age));
  } else if (!measure_.errorIsCurrent()) {
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

void ViewPainter::setBanner(const QString& title, const QString& text) {
  overlay_->bannerTitle = shownMessage(title);
  overlay_->bannerText = shownSummary(text);
  overlay_->setVisible(overlay_->hasContent());
  overlay_->raise();
  overlay_->update();
}

void ViewPainter::setPointerHighlight(bool on) {
  pointerHighlight_ = on;
  widget_.setMouseTracking(true);
  updateOverlay();
}

}  // namespace sl::ui
