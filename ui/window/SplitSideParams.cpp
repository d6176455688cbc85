// The split view's own parameters and "equal memory" (see SplitSideParams.h).
#include "window/SplitSideParams.h"

#include <QCheckBox>
#include <QLabel>
#include <QLocale>
#include <QScrollArea>
#include <QSplitter>
#include <QTimer>
#include <QVBoxLayout>

#include "window/MainWindow.h"
#include "window/Theme.h"
#include "view/ViewportWidget.h"
#include "core/Renderer.h"
#include "panels/common/ParamPanel.h"

namespace sl::ui {

namespace {
QString mib(std::uint64_t bytes) {
  return QStringLiteral("%1 MiB (%2 B)")
      .arg(double(bytes) / (1024.0 * 1024.0), 0, 'f', 2)
      .arg(QLocale().toString(qulonglong(bytes)));
}
}  // namespace

SplitSideParams::SplitSideParams(MainWindow& window) : QObject(&window), w_(window) {}

QWidget* SplitSideParams::createDockWidget(ParamPanel* mainPanel) {
  auto* splitter = new QSplitter(Qt::Vertical);
  splitter->setObjectName(QStringLiteral("parametersSplitter"));
  splitter->addWidget(mainPanel);
  box_ = new QWidget;
  box_->setObjectName(QStringLiteral("splitParams"));
  auto* layout = new QVBoxLayout(box_);
  layout->setContentsMargins(4, 4, 4, 0);
  title_ = new QLabel;
  title_->setWordWrap(true);
  followBodyFont(title_, 1.0, true);
  layout->addWidget(title_);
  equalMemory_ =
      new QCheckBox(tr("Equal memory (the right half's memory parameter spends the left "
                       "half's bytes)"));
  equalMemory_->setObjectName(QStringLiteral("equalMemory"));
  equalMemory_->setToolTip(
      tr("Searches the parameter the right technique's memory grows with (a map's "
         "resolution, a pool's pages) for the largest value whose shadow memory is at most "
         "the left technique's, measuring each candidate with a frame (memory need not follow "
         "that parameter alone); matches again when the left side's memory changes"));
  layout->addWidget(equalMemory_);
  bytes_ = new QLabel;
  bytes_->setObjectName(QStringLiteral("splitBytes"));
  bytes_->setWordWrap(true);
  bytes_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(bytes_);
  panel_ = new ParamPanel;
  panel_->setObjectName(QStringLiteral("splitParamPanel"));
  layout->addWidget(panel_, 1);
  // In a scroll area: the compare side must not raise the dock's minimum height (the window
  // would grow past a small screen).
  auto* scroll = new QScrollArea;
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setWidget(box_);
  area_ = scroll;
  splitter->addWidget(scroll);
  splitter->setStretchFactor(0, 3);
  splitter->setStretchFactor(1, 2);
  box_->hide();
  area_->hide();
  connect(panel_, &ParamPanel::paramChanged, this, [this] {
    if (w_.viewport()->frames()->paused()) w_.viewport()->frames()->stepFrame();
    w_.viewport()->frames()->requestFrame();
  });
  connect(panel_, &ParamPanel::editRefused, this,
          [this](const QString& message) { w_.report(message); });
  connect(equalMemory_, &QCheckBox::toggled, this, [this](bool on) {
    matchedMainBytes_.reset();
    matchNote_.clear();
    if (on) match();
    bytes_->setText(bytesText());
  });
  return splitter;
}

void SplitSideParams::clear() {
  if (panel_) panel_->clear();
}

void SplitSideParams::rebuild() {
  if (!panel_) return;
  sl::ViewSide* split = w_.viewport()->splitSide();
  if (!split) {
    panel_->clear();
    box_->hide();
    area_->hide();
    matchedMainBytes_.reset();
    return;
  }
  rebuildRows();
  box_->show();
  area_->show();
  matchedMainBytes_.reset();
  if (equalMemory_->isChecked()) match();
  bytes_->setText(bytesText());
}

void SplitSideParams::rebuildRows() {
  sl::ViewSide* split = w_.viewport()->splitSide();
  if (!panel_ || !split) return;
  const sl::TechniqueInfo* info = sl::Renderer::findTechnique(split->techniqueId());
  const QString name =
      info ? QString::fromStdString(info->name) : QString::fromStdString(split->techniqueId());
  title_->setText(tr("Right half (split view): %1").arg(name));
  panel_->setSections(
      {{name, info ? QString::fromStdString(info->description) : QString(), &split->params()}});
}

QString SplitSideParams::bytesText() const {
  const sl::ViewSide* main = w_.viewport()->mainSide();
  const sl::ViewSide* split = w_.viewport()->splitSide();
  if (!main || !split) return {};
  QString text = tr("Memory: left %1, right %2")
                     .arg(mib(main->stats().memory.bytes()), mib(split->stats().memory.bytes()));
  if (!matchNote_.isEmpty()) text += QStringLiteral("\n") + matchNote_;
  return text;
}

void SplitSideParams::match() {
  if (matching_) return;
  matching_ = true;
  std::string error;
  const auto m = w_.viewport()->measure()->matchSplitMemory(&error);
  matching_ = false;
  if (!m) {
    matchNote_ = tr("Equal memory: %1").arg(QString::fromStdString(error));
    // Not again every frame: again when the left side's memory changes.
    const sl::ViewSide* main = w_.viewport()->mainSide();
    if (main) matchedMainBytes_ = main->stats().memory.bytes();
    return;
  }
  matchedMainBytes_ = m->mainBytes;
  matchNote_ = m->belowMinimum
                   ? tr("Equal memory: even %1 = %2 spends more than the left half")
                         .arg(QString::fromStdString(m->key))
                         .arg(m->value)
                   : tr("Equal memory: %1 = %2, the largest within the left half's bytes "
                        "(%3 frames measured)")
                         .arg(QString::fromStdString(m->key))
                         .arg(m->value)
                         .arg(m->framesMeasured);
  panel_->refreshValues();
}

void SplitSideParams::onFrameRendered() {
  if (!box_ || box_->isHidden() || matching_) return;
  const sl::ViewSide* main = w_.viewport()->mainSide();
  // Not here: this runs inside the view's frame (its GL context current); the match renders.
  if (equalMemory_->isChecked() && main &&
      (!matchedMainBytes_ || *matchedMainBytes_ != main->stats().memory.bytes()))
    QTimer::singleShot(0, this, [this] {
      const sl::ViewSide* r = w_.viewport()->mainSide();
      if (r && equalMemory_->isChecked() &&
          (!matchedMainBytes_ || *matchedMainBytes_ != r->stats().memory.bytes())) {
        match();
        bytes_->setText(bytesText());
      }
    });
  bytes_->setText(bytesText());
}

}  // namespace sl::ui
