// The Teaching toolbar (see TeachingBar.h): overlays and split view bound to the renderer's
// declarations, pause and stepping.
#include "teaching/TeachingBar.h"

#include <QAction>
#include <QComboBox>
#include <QStyle>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>

#include "window/MainWindow.h"
#include "teaching/PassStepper.h"
#include "view/ViewportWidget.h"
#include "panels/common/ParamPanel.h"

namespace sl::ui {

namespace {
const QString kOverlayParam = QStringLiteral("view.overlay");
}  // namespace

TeachingBar::TeachingBar(MainWindow& window) : QObject(&window), w_(window) {}

void TeachingBar::create() {
  MainWindow& w = w_;
  QToolBar* bar = w.addFixedToolBar(tr("Teaching"), QStringLiteral("teachingToolBar"));
  auto addLabel = [bar](const QString& text) { MainWindow::addToolBarLabel(bar, text); };

  // Overlay: the choices come from the declaration of the shared `view.overlay` parameter.
  addLabel(tr("Overlay"));
  overlayCombo_ = new QComboBox;
  overlayCombo_->setObjectName(QStringLiteral("overlayCombo"));
  overlayCombo_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  for (const sl::ParamDecl& d : sl::rendererParamDecls()) {
    if (QString::fromStdString(d.key) != kOverlayParam) continue;
    for (std::size_t i = 0; i < d.enumNames.size(); ++i)
      overlayCombo_->addItem(QString::fromStdString(d.enumNames[i]), static_cast<int>(i));
    overlayCombo_->setToolTip(QStringLiteral("<b>%1</b> (O cycles)<br>%2")
                                  .arg(QString::fromStdString(d.label).toHtmlEscaped(),
                                       QString::fromStdString(d.help).toHtmlEscaped()));
  }
  overlayCombo_->setEnabled(false);  // until the renderer exists
  connect(overlayCombo_, &QComboBox::activated, this,
          [this](int index) { setOverlay(overlayCombo_->itemData(index).toInt()); });
  bar->addWidget(overlayCombo_);
  if (overlayCombo_->count() == 0) overlayCombo_->hide();
  bar->addSeparator();

  addLabel(tr("Compare with"));
  splitCombo_ = new QComboBox;
  splitCombo_->setObjectName(QStringLiteral("splitCombo"));
  splitCombo_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  splitCombo_->setToolTip(
      tr("Split view (F7): this technique on the right half, same camera and light, with the "
         "time and error of both halves"));
  splitCombo_->addItem(tr("— (no split)"), QString());
  for (const sl::TechniqueInfo& t : sl::Renderer::techniques())
    splitCombo_->addItem(QString::fromStdString(t.name), QString::fromStdString(t.id));
  connect(splitCombo_, &QComboBox::activated, this,
          [this](int index) { setSplitTechnique(splitCombo_->itemData(index).toString()); });
  bar->addWidget(splitCombo_);
  bar->addSeparator();

  w.pauseAction()->setIcon(w.style()->standardIcon(QStyle::SP_MediaPause));
  bar->addAction(w.pauseAction());
  auto addButton = [this, bar](const QString& text, const QString& tip, auto slot) {
    auto* b = new QToolButton;
    b->setText(text);
    b->setToolTip(tip);
    connect(b, &QToolButton::clicked, this, slot);
    bar->addWidget(b);
  };
  addButton(tr("Step frame"), tr("Render one frame and pause (.)"), [this] { w_.stepFrame(); });
  addButton(tr("Step passes ▶"),
            tr("Walk through the passes of this frame as the technique declares them, each "
               "with the panel showing its output (] next, [ back, Esc stop)"),
            [this] { w_.passes()->step(+1); });
}

void TeachingBar::setRendererAvailable(bool on) {
  if (overlayCombo_) overlayCombo_->setEnabled(on);
  if (on) syncOverlayCombo();
}

void TeachingBar::syncOverlayCombo() {
  sl::ViewSide* r = w_.viewport()->mainSide();
  const bool has = r && r->rendererParams().has(kOverlayParam.toStdString());
  overlayCombo_->setEnabled(has);
  if (!has) return;
  const int value = r->rendererParams().getInt(kOverlayParam.toStdString());
  const QSignalBlocker block(overlayCombo_);
  overlayCombo_->setCurrentIndex(overlayCombo_->findData(value));
}

void TeachingBar::setOverlay(int value) {
  ViewportWidget* viewport = w_.viewport();
  sl::ViewSide* r = viewport->mainSide();
  if (!r) return;
  if (auto error = r->rendererParams().set(kOverlayParam.toStdString(), value)) {
    w_.report(QString::fromStdString(*error));
    syncOverlayCombo();
    return;
  }
  w_.paramPanel()->refreshValues();
  syncOverlayCombo();
  const sl::ParamDecl* d = r->rendererParams().find(kOverlayParam.toStdString());
  const bool error = d && value >= 0 && value < static_cast<int>(d->enumNames.size()) &&
                     d->enumNames[static_cast<std::size_t>(value)] == "error";
  if (viewport->frames()->paused()) viewport->frames()->stepFrame();
  viewport->update();
  // The error overlay needs the exact reference of this view: compute it now.
  if (error && !viewport->measure()->errorIsCurrent())
    QTimer::singleShot(0, this, [viewport] { viewport->measure()->computeErrorNow(); });
}

void TeachingBar::cycleOverlay() {
  const sl::ViewSide* r = w_.viewport()->mainSide();
  if (!r || overlayCombo_->count() == 0) return;
  const int next = (overlayCombo_->currentIndex() + 1) % overlayCombo_->count();
  setOverlay(overlayCombo_->itemData(next).toInt());
  w_.info(tr("Overlay: %1").arg(overlayCombo_->currentText()));
}

void TeachingBar::setSplitTechnique(const QString& id,
                                    const std::map<std::string, std::string>& params) {
  ViewportWidget* viewport = w_.viewport();
  if (auto error = viewport->frames()->setSplitTechnique(id.toStdString(), params)) {
    w_.report(QString::fromStdString(*error));
    return;
  }
  if (!id.isEmpty()) lastSplitTechnique_ = id;
  const QSignalBlocker block(splitCombo_);
  splitCombo_->setCurrentIndex(std::max(0, splitCombo_->findData(id)));
  w_.info(id.isEmpty() ? tr("Split view off.")
                       : tr("Split view: %1 (left) against %2 (right).")
                             .arg(QString::fromStdString(viewport->techniqueId()), id));
}

void TeachingBar::restoreSplit() {
  if (!lastSplitTechnique_.isEmpty() && splitCombo_->currentIndex() > 0)
    setSplitTechnique(lastSplitTechnique_, w_.viewport()->frames()->splitParams());
}

void TeachingBar::toggleSplit() {
  ViewportWidget* viewport = w_.viewport();
  if (!viewport->frames()->splitTechnique().empty()) return setSplitTechnique(QString());
  QString id = lastSplitTechnique_;
  if (id.isEmpty()) {  // the baseline (uniform) against anything else, else the first other
                       // technique
    const QString current = QString::fromStdString(viewport->techniqueId());
    for (const sl::TechniqueInfo& t : sl::Renderer::techniques()) {
      const QString candidate = QString::fromStdString(t.id);
      if (candidate == current) continue;
      if (id.isEmpty() || t.baseline) id = candidate;
    }
  }
  if (id.isEmpty()) {
    w_.report(tr("split view: there is only one technique to compare"));
    return;
  }
  setSplitTechnique(id);
}

}  // namespace sl::ui
