// Pass stepping over the declared passes of a frame (see PassStepper.h). No pass is named
// here: the list, the titles and the explanations come from the technique's declaration.
#include "teaching/PassStepper.h"

#include <algorithm>

#include <QAction>
#include <QDockWidget>

#include "window/MainWindow.h"
#include "view/ViewportWidget.h"

namespace sl::ui {

namespace {
const QString kPassPrefix = QStringLiteral("\u25b6 ");  ///< dock title prefix while stepping
constexpr int kStatusMs = 10000;
}  // namespace

PassStepper::PassStepper(MainWindow& window) : QObject(&window), w_(window) {}

void PassStepper::buildSteps() {
  steps_.clear();
  sl::ViewSide* r = w_.viewport()->mainSide();
  const sl::TechniqueInfo* info = r ? sl::Renderer::findTechnique(r->techniqueId()) : nullptr;
  if (!info) return;
  // The passes this frame runs (a pass of one rmsm.render value only while it holds).
  for (const sl::PassDecl& p : sl::framePassDecls(*info, r->params()))
    steps_.push_back({QString::fromStdString(p.id), QString::fromStdString(p.title),
                      QString::fromStdString(p.explanation), w_.docks().dock(p.panel)});
}

void PassStepper::step(int delta) {
  MainWindow& w = w_;
  if (!w.viewport()->mainSide()) return;
  if (!active()) {
    pausedBefore_ = w.viewport()->frames()->paused();
    if (!w.viewport()->frames()->paused()) w.setPaused(true);
    w.passStopAction()->setEnabled(true);
    if (w.docks().isCurrent(*w.viewport()->mainSide(), true)) {
      index_ = 0;
      show();
    } else {  // the last frame did not publish every panel's keys: render one that does
      waitingForFrame_ = true;
      w.updatePublishing();
      w.viewport()->frames()->stepFrame();
    }
    return;
  }
  if (waitingForFrame_) return;
  const int next = index_ + delta;
  if (next >= static_cast<int>(steps_.size())) {
    // Past the last pass: the frame is done; render the next one and start over.
    waitingForFrame_ = true;
    w.viewport()->frames()->stepFrame();
    return;
  }
  index_ = std::max(0, next);
  show();
}

void PassStepper::restartAtNextFrame() {
  if (index_ < 0) return;
  waitingForFrame_ = true;
  w_.updatePublishing();
}

void PassStepper::onFrameRendered() {
  if (!waitingForFrame_ || !w_.docks().isCurrent(*w_.viewport()->mainSide(), true)) return;
  waitingForFrame_ = false;
  index_ = 0;
  show();
}

void PassStepper::show() {
  MainWindow& w = w_;
  const sl::ViewSide* r = w.viewport()->mainSide();
  if (!r) return;
  w.docks().feed(*r, true);
  buildSteps();
  if (steps_.empty()) return stop();
  index_ = std::clamp(index_, 0, static_cast<int>(steps_.size()) - 1);
  const Step& s = steps_[static_cast<std::size_t>(index_)];
  w.docks().highlightPass(s.id);
  for (QDockWidget* dock : w.findChildren<QDockWidget*>()) {
    QString title = dock->windowTitle();
    if (title.startsWith(kPassPrefix)) title.remove(0, kPassPrefix.size());
    dock->setWindowTitle(dock == s.dock ? kPassPrefix + title : title);
  }
  if (s.dock) {
    s.dock->show();
    s.dock->raise();
  }
  w.updateBanner();
  w.showStatus(tr("Frame %1, pass %2 of %3: %4")
                   .arg(r->publication().frameIndex)
                   .arg(index_ + 1)
                   .arg(steps_.size())
                   .arg(s.title),
               kStatusMs);
}

void PassStepper::stop() {
  if (!active()) return;
  MainWindow& w = w_;
  index_ = -1;
  waitingForFrame_ = false;
  w.passStopAction()->setEnabled(false);
  w.docks().highlightPass(QString());
  for (QDockWidget* dock : w.findChildren<QDockWidget*>()) {
    const QString title = dock->windowTitle();
    if (title.startsWith(kPassPrefix)) dock->setWindowTitle(title.mid(kPassPrefix.size()));
  }
  w.updateBanner();
  w.updatePublishing();
  if (!pausedBefore_) w.setPaused(false);
}

QString PassStepper::bannerTitle() const {
  if (index_ < 0 || index_ >= static_cast<int>(steps_.size())) return {};
  return tr("Pass %1 of %2: %3   ( ] next · [ back · Esc stop )")
      .arg(index_ + 1)
      .arg(steps_.size())
      .arg(steps_[static_cast<std::size_t>(index_)].title);
}

QString PassStepper::bannerText() const {
  if (index_ < 0 || index_ >= static_cast<int>(steps_.size())) return {};
  return steps_[static_cast<std::size_t>(index_)].text;
}

}  // namespace sl::ui
