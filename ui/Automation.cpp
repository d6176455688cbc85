// Scripted control of the window (see Automation.h).
#include "Automation.h"

#include "service/RenderService.h"

#include <QAction>
#include <QCheckBox>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFontInfo>
#include <QLabel>
#include <QStatusBar>
#include <QTimer>

#include "launch/LaunchOptions.h"
#include "teaching/LessonController.h"
#include "window/MainWindow.h"
#include "window/SessionFiles.h"
#include "window/SplitSideParams.h"
#include "teaching/TeachingBar.h"
#include "window/StatusLine.h"
#include "window/WindowImages.h"
#include "view/ViewportWidget.h"
#include "core/Renderer.h"

namespace sl::ui {

Automation::Automation(MainWindow& window) : QObject(&window), w_(window) {
  w_.setScripted(true);
}

ViewportWidget& Automation::viewport() const {
  return *w_.viewport();
}

sl::ViewSide* Automation::mainSide() const {
  return w_.viewport()->mainSide();
}

void Automation::whenReady(std::function<void()> ready, std::function<void(const QString&)> failed,
                           int timeoutMs) {
  auto* timer = new QTimer(this);
  auto clock = std::make_shared<QElapsedTimer>();
  clock->start();
  connect(timer, &QTimer::timeout, this,
          [this, timer, clock, timeoutMs, ready = std::move(ready), failed = std::move(failed)] {
            if (w_.failed()) {
              timer->stop();
              timer->deleteLater();
              failed(tr("the renderer failed to start"));
              return;
            }
            if (!w_.rendererBound() || w_.viewport()->frames()->framesRendered() < 2 ||
                w_.lessons()->settling()) {
              if (clock->elapsed() > timeoutMs) {
                timer->stop();
                timer->deleteLater();
                failed(tr("the renderer did not start within %1 s").arg(timeoutMs / 1000));
                return;
              }
              w_.viewport()->frames()->requestFrame();
              return;
            }
            timer->stop();
            timer->deleteLater();
            ready();
          });
  timer->start(30);
}

bool Automation::openScene(const QString& nameOrPath) {
  return w_.loadScene(nameOrPath);
}

std::optional<QString> Automation::setTechnique(const QString& id) {
  if (!sl::Renderer::findTechnique(id.toStdString())) return tr("unknown technique '%1'").arg(id);
  w_.setTechnique(id);
  if (w_.viewport()->techniqueId() != id.toStdString())
    return tr("the view did not switch to '%1'").arg(id);
  return std::nullopt;
}

bool Automation::openLesson(const QString& lesson, int caseIndex) {
  return w_.startLesson(lesson, caseIndex);
}

std::optional<QString> Automation::setParameter(const QString& keyEqualsValue) {
  sl::ViewSide* r = mainSide();
  if (!r) return tr("no renderer yet");
  if (auto e = assignParameter(r->params(), r->rendererParams(), keyEqualsValue.toStdString()))
    return QString::fromStdString(*e);
  w_.viewport()->frames()->requestFrame();
  return std::nullopt;
}

void Automation::toggleContinuous() {
  w_.continuousAction()->trigger();
}

void Automation::setPaused(bool paused) {
  w_.setPaused(paused);
}

void Automation::stepFrame() {
  w_.stepFrame();
}

void Automation::setPresenterMode(bool on) {
  w_.setPresenterMode(on);
}

void Automation::setSplit(const QString& techniqueId,
                          const std::map<std::string, std::string>& params) {
  w_.teaching()->setSplitTechnique(techniqueId, params);
}

void Automation::toggleSplit() {
  w_.teaching()->toggleSplit();
}

void Automation::cycleOverlay() {
  w_.teaching()->cycleOverlay();
}

bool Automation::saveSession(const QString& path) {
  return w_.sessions()->save(path);
}

bool Automation::openSession(const QString& path) {
  return w_.sessions()->open(path);
}

QStringList Automation::recentSessions() const {
  return w_.sessions()->recent();
}

bool Automation::waitForFrames(int frames, int timeoutMs) {
  return w_.waitForFrames(frames, timeoutMs);
}

bool Automation::waitForSettled(int timeoutMs) {
  QElapsedTimer clock;
  clock.start();
  while (w_.lessons()->settling()) {
    w_.viewport()->frames()->requestFrame();
    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    if (clock.elapsed() > timeoutMs) return false;
  }
  return true;
}

QString Automation::errorReadout() const {
  return w_.statusLine()->errorLabel()->text();
}

bool Automation::errorReadoutCurrent() const {
  return w_.statusLine()->errorLabel()->isEnabled();
}

int Automation::statusTextPixelSize() const {
  return QFontInfo(w_.statusLine()->errorLabel()->font()).pixelSize();
}

QString Automation::statusMessage() const {
  return w_.statusBar()->currentMessage();
}

void Automation::clearStatusMessage() {
  w_.statusBar()->clearMessage();
}

QString Automation::sceneShown() const {
  return w_.sceneSpec();
}

QString Automation::resolutionNote() const {
  return w_.viewport()->frames()->resolutionNote();
}

ViewportWidget::Readouts Automation::viewReadouts() const {
  return w_.viewport()->readouts();
}

const sl::Publication* Automation::publication() const {
  const sl::ViewSide* r = mainSide();
  return r ? &r->publication() : nullptr;
}

QImage Automation::grabWindow() const {
  return w_.images().grabWindowFullSize();
}

QImage Automation::grabView() const {
  return w_.images().grabViewFullSize();
}

std::optional<QString> Automation::exportFigure(const QString& path) {
  return w_.images().exportFigure(path);
}

std::optional<QString> Automation::saveViewImage(const QString& path) {
  return w_.images().writeViewImage(path);
}

bool Automation::trigger(const QKeySequence& keys) {
  for (QAction* a : w_.findChildren<QAction*>())
    if (a->isEnabled() && a->shortcuts().contains(keys)) {
      a->trigger();
      return true;
    }
  return false;
}

void Automation::setEqualMemory(bool on) {
  w_.splitSide()->equalMemoryBox()->setChecked(on);
}

QImage Automation::renderedFrame() const {
  w_.viewport()->frames()->renderFullSizeNow(true);
  return w_.viewport()->frames()->renderedImage();
}

bool Automation::waitForProbe(int timeoutMs) {
  QElapsedTimer clock;
  clock.start();
  while (w_.viewport()->measure()->probePending()) {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    if (clock.elapsed() > timeoutMs) return false;
  }
  QCoreApplication::processEvents();  // the panels' repaint
  return true;
}

namespace {
/// Runs `read` on the render thread with the main renderer's complete frame of the view.
template <typename T, typename Read>
T readMain(ViewportWidget& view, Read read) {
  T out{};
  view.measure()->readCurrentFrame([&](sl::Renderer& r) { out = read(r); });
  return out;
}
}  // namespace

std::optional<sl::PixelProbe> Automation::probePixel(int x, int y) const {
  return readMain<std::optional<sl::PixelProbe>>(
      *w_.viewport(), [x, y](sl::Renderer& r) { return r.probePixel(x, y); });
}

sl::Renderer::ErrorResult Automation::computeError() const {
  return readMain<sl::Renderer::ErrorResult>(*w_.viewport(),
                                             [](sl::Renderer& r) { return r.computeError(); });
}

sl::FrameReadback Automation::readback() const {
  return readMain<sl::FrameReadback>(*w_.viewport(), [](sl::Renderer& r) { return r.readback(); });
}

}  // namespace sl::ui
