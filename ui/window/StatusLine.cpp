// The status line's readouts (see StatusLine.h).
#include "window/StatusLine.h"

#include <QLabel>
#include <QLocale>
#include <QStatusBar>

#include "view/ViewportWidget.h"
#include "window/MessageText.h"

namespace sl::ui {

QString shortGlName(const QString& description) {
  return description.section(QStringLiteral(" | "), 0, 0).trimmed();
}

StatusLine::StatusLine(QStatusBar& bar, ViewportWidget& view, QObject* parent)
    : QObject(parent), view_(view) {
  auto permanent = [&bar](const QString& name, const QString& tip) {
    auto* label = new QLabel;
    label->setObjectName(name);
    label->setToolTip(tip);
    label->setContentsMargins(8, 0, 8, 0);
    bar.addPermanentWidget(label);
    return label;
  };
  sceneLabel_ = permanent(QStringLiteral("sceneStatus"), tr("Scene shown"));
  frameLabel_ = permanent(QStringLiteral("frameStatus"),
                          tr("Time of the last frame, and how it was measured"));
  errorLabel_ =
      permanent(QStringLiteral("errorStatus"),
                tr("Shadow error of the current view against the exact ray-traced reference "
                   "(percent of covered pixels; computed once the view is still, or Ctrl+E)"));
  glLabel_ = permanent(QStringLiteral("glStatus"), tr("OpenGL renderer"));
  frameLabel_->setMinimumWidth(frameLabel_->fontMetrics().horizontalAdvance(
                                   QStringLiteral("frame 999.9 ms (glFinish+wallclock)")) +
                               16);
  frameLabel_->setText(tr("frame —"));
  errorLabel_->setText(tr("error —"));
  glLabel_->setText(tr("GL —"));

  connect(view_.frames(), &FrameLoop::frameRendered, this, &StatusLine::onFrameRendered);
  connect(view_.measure(), &MeasureService::errorComputed, this, &StatusLine::onErrorComputed);
  connect(view_.measure(), &MeasureService::errorUnmeasured, this, &StatusLine::onErrorUnmeasured);
  connect(view_.frames(), &FrameLoop::viewChanged, this, [this] {
    if (view_.frames()->continuous()) return showLiveError();
    if (!view_.measure()->errorIsCurrent()) errorLabel_->setText(tr("error —"));
  });
}

void StatusLine::showScene(const sl::Scene& scene) {
  sceneLabel_->setText(
      tr("%1 · %2 triangles")
          .arg(shownMessage(QString::fromStdString(scene.name)))
          .arg(QLocale::c().toString(static_cast<qulonglong>(scene.triangleCount()))));
  sceneLabel_->setToolTip(shownMessage(QString::fromStdString(scene.sourcePath)));
}

void StatusLine::showGl(const QString& description) {
  glLabel_->setText(shortGlName(description));
  glLabel_->setToolTip(description);
}

void StatusLine::onContinuousChanged(bool on) {
  if (on) return showLiveError();
  errorLabel_->setEnabled(true);
  errorLabel_->setText(view_.measure()->errorPct()
                           ? tr("error %1 %").arg(*view_.measure()->errorPct(), 0, 'f', 3)
                       : view_.measure()->errorNotMeasured().isEmpty()
                           ? tr("error —")
                           : tr("error n/a (%1)").arg(view_.measure()->errorNotMeasured()));
}

void StatusLine::onFrameRendered() {
  const sl::ViewSide* side = view_.mainSide();
  if (!side) return;
  const sl::FrameStats& stats = side->stats();
  if (const QString failure = view_.frames()->frameFailure(); !failure.isEmpty()) {
    frameLabel_->setText(tr("frame n/a (failed)"));
    frameLabel_->setToolTip(failure);
  } else {
    frameLabel_->setToolTip({});
    frameLabel_->setText(tr("frame %1 ms (%2)")
                             .arg(stats.totalMs, 0, 'f', stats.totalMs < 10 ? 2 : 1)
                             .arg(stats.timingMethod.empty()
                                      ? tr("untimed")
                                      : QString::fromStdString(stats.timingMethod)));
  }
  // As wide as its text at the current font (presenter mode's is larger): never cut.
  frameLabel_->setMinimumWidth(frameLabel_->sizeHint().width());
  if (view_.frames()->continuous()) showLiveError();
}

void StatusLine::onErrorUnmeasured(const QString& why) {
  errorLabel_->setEnabled(true);
  if (view_.frames()->continuous()) return showLiveError();
  errorLabel_->setText(tr("error n/a (%1)").arg(why));
  errorLabel_->setToolTip(tr("The error of this view was not measured: %1").arg(why));
}

void StatusLine::onErrorComputed(double errorPct) {
  errorLabel_->setEnabled(true);
  if (view_.frames()->continuous()) return showLiveError();
  errorLabel_->setText(tr("error %1 %").arg(errorPct, 0, 'f', errorPct < 1 ? 3 : 2));
  errorLabel_->setToolTip({});
}

void StatusLine::showLiveError() {
  // Greyed while the number is an earlier view's (or there is none yet).
  if (const QString failure = view_.frames()->frameFailure(); !failure.isEmpty()) {
    errorLabel_->setEnabled(true);  // a failed frame is never measured, nor shown as 0
    errorLabel_->setText(tr("error n/a (the frame failed)"));
    errorLabel_->setToolTip(failure);
    return;
  }
  const auto live = view_.measure()->liveError();
  errorLabel_->setEnabled(live && !live->age.stale);
  errorLabel_->setText(view_.measure()->liveErrorText());
}

}  // namespace sl::ui
