// The view's frame loop (see FrameLoop.h). It never calls GL: each frame is a job on the
// render service's thread (ViewFrame.h), and its outcome comes back as a queued call.
#include "view/FrameLoop.h"

#include <algorithm>
#include <cmath>

#include <QPainter>
#include <QWidget>

#include "service/RenderService.h"
#include "view/CameraController.h"
#include "view/MeasureService.h"
#include "view/ViewModel.h"

namespace sl::ui {

FrameLoop::FrameLoop(QWidget& widget, ViewModel& model, const CameraController& camera)
    : QObject(&widget), widget_(widget), model_(model), camera_(camera) {
  // Adaptive resolution: once the view is still, a reduced frame is redrawn at full size.
  settleTimer_.setSingleShot(true);
  connect(&settleTimer_, &QTimer::timeout, this, [this] {
    if (model_.frameDivisor == 1) return;
    // Still interacting, or a frame on its way: the view is not still yet.
    if (camera_.interacting() || framesInFlight_ > 0) return settleTimer_.start();
    fullSizeNext_ = true;
    requestFrame();
  });
  busyTimer_.setInterval(100);  // the busy note's seconds, while a frame is computed
  connect(&busyTimer_, &QTimer::timeout, this, [this] {
    // Only while the busy note is (or was just) shown: a quick frame redraws nothing here.
    const bool busy = !busyText().isEmpty();
    if (busy || busyShown_) Q_EMIT overlayChanged();
    busyShown_ = busy;
  });
  service_ = new RenderService(this);
  connect(service_, &RenderService::ready, this, &FrameLoop::serviceReady);
  // An action the window waits for: its note and seconds in the view until it ends.
  connect(service_, &RenderService::callStarted, this, [this](const QString& note) {
    if (note.isEmpty()) return;
    callNote_ = note;
    callClock_.start();
    busyTimer_.start();
    Q_EMIT overlayChanged();
  });
  connect(service_, &RenderService::callEnded, this, [this](int stillWaiting) {
    if (stillWaiting > 0) return;
    // The frames asked for during the wait, after what the caller does with its result.
    QTimer::singleShot(0, this, [this] { pump(); });
    if (callNote_.isEmpty()) return;
    callNote_.clear();
    if (framesInFlight_ == 0) busyTimer_.stop();
    Q_EMIT overlayChanged();
  });
  connect(service_, &RenderService::failed, this, &FrameLoop::initializationFailed);
}

FrameLoop::~FrameLoop() {
  delete service_;  // stops the frame in progress, frees the renderers, joins the thread
  service_ = nullptr;
}

QSize FrameLoop::deviceSize() const {
  const qreal dpr = widget_.devicePixelRatioF();
  return {static_cast<int>(std::lround(widget_.width() * dpr)),
          static_cast<int>(std::lround(widget_.height() * dpr))};
}

void FrameLoop::requestFrame() {
  frameWanted_ = true;
  pump();
}

void FrameLoop::markViewChanged() {
  ++model_.viewRevision;
  Q_EMIT viewChanged();
}

void FrameLoop::noticeEdits() {
  const bool splitEdited = model_.split && model_.split->revision() != lastSplitRevision_;
  if (model_.main.revision() == lastMainRevision_ &&
      model_.shared.revision() == lastSharedRevision_ && !splitEdited)
    return;
  lastMainRevision_ = model_.main.revision();
  lastSharedRevision_ = model_.shared.revision();
  if (model_.split) lastSplitRevision_ = model_.split->revision();
  if (splitEdited) measure_->forgetSplitError(false);
  markViewChanged();
}

void FrameLoop::pump() {
  // No new frame while a scene loads or while the window waits for an action on the render
  // thread (RenderService::call: what it reads next is of the frame it drew, not of one
  // queued during the wait); each asks again when it ends.
  if (!model_.ready || !frameWanted_ || !service_ || sceneLoading_ || service_->callsWaiting() > 0)
    return;
  noticeEdits();
  const bool inFlight = framesInFlight_ > 0;
  const bool changed = model_.viewRevision != sentViewRevision_;
  // Paused: the last frame stays unless a step is pending or the size changed.
  if (model_.paused && pendingSteps_ == 0 && lastFrameSize_ == deviceSize() &&
      model_.framesRendered > 0 && !inFlight) {
    frameWanted_ = false;
    return;
  }
  if (inFlight && !changed) return;  // its outcome pumps again
  if (pendingSteps_ > 0) --pendingSteps_;
  frameWanted_ = false;
  const std::shared_ptr<FrameOrder> order = makeOrder();
  busyTechnique_ =
      QString::fromStdString(model_.main.techniqueId()) +
      (order->split ? QStringLiteral(" | ") + QString::fromStdString(model_.splitTechniqueId)
                    : QString());
  busyTimer_.start();
  // A changed view stops the frame in progress: its result would be of the old view. Not
  // while a drag or a fly key moves the camera: every move would stop the frame before it
  // completes, and the view would show nothing new until the hand rests; the frame in
  // progress completes (drawn, one view behind) and the newest camera is rendered next.
  const bool interacting = camera_.interacting();
  const bool replaced = service_->submitFrame(
      [this, order](RenderContext& c) {
        auto out = std::make_shared<FrameOutcome>();
        renderOrder(c, *order, *out);
        QMetaObject::invokeMethod(
            this,
            [this, out] {
              --framesInFlight_;
              applyOutcome(out);
            },
            Qt::QueuedConnection);
      },
      inFlight && changed && !interacting);
  if (!replaced) ++framesInFlight_;  // a replaced order never comes back
}

std::shared_ptr<FrameOrder> FrameLoop::makeOrder() {
  auto o = std::make_shared<FrameOrder>();
  o->id = ++ordersSent_;
  o->scene = model_.scene;
  o->camera = model_.camera;
  o->light = model_.light;
  o->main = model_.main.takeRequest();
  const QSize size = deviceSize();
  lastFrameSize_ = size;
  const int w = size.width(), h = size.height();
  // A view dragged down to a few pixels draws nothing: a frame that small feeds temporal
  // state (DA-RTW's rotation, kept by its vibration threshold) a degenerate importance map.
  if (w < kMinDrawnPx || h < kMinDrawnPx) {
    o->clearOnly = true;
  } else {
    // No right half narrower than the smallest drawn view: the left half takes it all.
    const bool split = model_.split && w / 2 >= kMinDrawnPx;
    const int mainWidth = split ? w / 2 : w;
    lastMainWidth_ = mainWidth;
    // Adaptive resolution: 1/divisor of the size (never below the smallest drawn view); a
    // still view's settle frame (and an export's) is drawn at full size.
    const bool adaptive = adaptiveActive();
    if (!adaptive && adaptive_.divisor() != 1) adaptive_.reset();
    o->fullSize = std::exchange(fullSizeNext_, false);
    int divisor = o->fullSize ? 1 : adaptive_.divisor();
    while (divisor > 1 && (mainWidth / divisor < kMinDrawnPx || h / divisor < kMinDrawnPx))
      divisor /= 2;
    if (divisor != model_.frameDivisor) markViewChanged();  // another image: the error is not its
    o->divisor = divisor;
    o->frameWidth = sl::AdaptiveResolution::scaled(mainWidth, divisor);
    o->frameHeight = sl::AdaptiveResolution::scaled(h, divisor);
    if (split) {
      o->split = model_.split->takeRequest();
      o->split->publications = model_.splitPublicationKeys;
      o->splitWidth = sl::AdaptiveResolution::scaled(w - mainWidth, divisor);
    }
    // Progressive resolve (continuous rendering in an interactive window): a technique that
    // resolves tile by tile spends at most half the budget on tiles per frame and keeps its
    // result between frames. Scripted runs and on-demand frames resolve in one call.
    if (adaptiveAllowed_ && model_.continuous && !model_.paused)
      o->progressiveBudgetMs =
          kProgressiveShare * double(model_.shared.getInt("view.adaptive.budget_ms"));
  }
  o->viewRevision = model_.viewRevision;
  sentViewRevision_ = model_.viewRevision;
  o->shared = model_.shared;
  measure_->prepareOrder(*o);
  return o;
}

void FrameLoop::applyOutcome(const std::shared_ptr<FrameOutcome>& out) {
  ordersDone_ = std::max(ordersDone_, out->id);
  if (framesInFlight_ == 0 && callNote_.isEmpty()) busyTimer_.stop();
  if (out->stopped) {  // never shown, never measured
    ++framesStopped_;
    if (out->id == ordersSent_) frameWanted_ = true;  // stopped by an export: draw it again
    pump();
    Q_EMIT overlayChanged();
    return;
  }
  if (out->id <= lastAppliedId_) return;  // older than the frame shown (an export's came first)
  lastAppliedId_ = out->id;
  ++framesDrawn_;
  model_.shownViewRevision = out->viewRevision;
  model_.mainImage = out->mainImage;
  model_.splitImage = out->hasSplit ? out->splitImage : QImage();
  model_.frameDivisor = out->divisor;
  model_.internalSize = model_.mainImage.size();
  if (out->viewRevision != model_.viewRevision) {
    // Of a view that has changed since (a drag, an edit): shown while the current one is
    // computed, but neither counted, measured nor published.
    Q_EMIT frameShown();
    pump();
    return;
  }
  model_.lastFrameMs = out->wallMs;
  model_.frameFailure = QString::fromStdString(out->mainProblem);
  model_.main.setFrame(std::move(out->mainStats), std::move(out->mainPublication));
  if (model_.split && out->hasSplit)
    model_.split->setFrame(std::move(out->splitStats), std::move(out->splitPublication));
  // A progressive frame's tiles are bounded by their own budget: the resolution follows the
  // rest (the per-pixel work), else a slow tile would drop the view and restart the tiles.
  const auto& progress = model_.main.stats().progress;
  const bool failed = !out->mainProblem.empty();
  if (adaptiveActive() && !failed && !out->fullSize)
    adaptive_.onFrame(
        progress ? std::max(0.0, model_.lastFrameMs - progress->spentMs) : model_.lastFrameMs,
        double(model_.shared.getInt("view.adaptive.budget_ms")));
  progressNote_ = progress && !failed ? progress : std::nullopt;
  ++model_.framesRendered;
  std::string problem = out->splitProblem;
  if (failed) problem += (problem.empty() ? "" : "; ") + out->mainProblem;
  for (const std::string& glError : out->glErrors)
    problem += (problem.empty() ? "" : "; ") + glError;
  if (!problem.empty() && problem != lastProblem_)
    Q_EMIT renderProblem(QString::fromStdString(problem));
  lastProblem_ = problem;
  // A partial progressive frame is neither traced nor measured: the error waits.
  const bool partial = !model_.main.stats().complete();
  if (model_.continuous && !failed && !partial) measure_->updateLiveReferences(*out);
  Q_EMIT frameShown();
  Q_EMIT frameRendered();
  // On demand (or paused): a reduced frame is redrawn at full size once the view is still,
  // and the error is computed. Continuous: the live reference keeps it.
  measure_->frameApplied(*out, partial);
  if (model_.frameDivisor > 1 && (!model_.continuous || model_.paused))
    settleTimer_.start(kSettleDelayMs);
  else
    settleTimer_.stop();
  if (model_.continuous && !model_.paused) frameWanted_ = true;
  pump();
}

bool FrameLoop::renderNow(const std::shared_ptr<FrameOrder>& order) {
  auto out = std::make_shared<FrameOutcome>();
  if (!service_->call([&](RenderContext& c) { renderOrder(c, *order, *out); },
                      tr("drawing the view at full size")))
    return false;
  applyOutcome(out);
  return !out->stopped;
}

QString FrameLoop::busyText() const {
  if (!service_) return {};
  if (!callNote_.isEmpty())
    return tr("%1 \u2026 %2 s  \u00b7  Esc stops")
        .arg(callNote_)
        .arg(callClock_.elapsed() / 1000.0, 0, 'f', 1);
  const RenderService::Activity a = service_->activity();
  if (!a.busy || !a.frame || a.elapsedMs < kBusyNoteMs) return {};
  return tr("computing %1 \u2026 %2 s (the last complete frame is shown)")
      .arg(busyTechnique_)
      .arg(a.elapsedMs / 1000.0, 0, 'f', 1);
}

std::optional<std::string> FrameLoop::setSplitTechnique(
    const std::string& techniqueId, const std::map<std::string, std::string>& params) {
  std::optional<sl::ViewSide> side;
  if (!techniqueId.empty()) {
    side.emplace();
    if (auto e = side->setTechnique(techniqueId)) return e;
    for (const auto& [key, value] : params) {
      if (!side->params().has(key))
        return "split view: technique '" + techniqueId + "' has no parameter '" + key + "'";
      if (auto e = side->params().setFromString(key, value)) return "split view: " + *e;
    }
    side->setSharedParams(&model_.shared);
    side->requestPublications(model_.splitPublicationKeys);
    side->resetTemporalState();
  }
  model_.split = std::move(side);
  model_.splitTechniqueId = techniqueId;
  if (model_.split) lastSplitRevision_ = model_.split->revision();
  measure_->forgetSplitError(true);  // of the previous right half
  markViewChanged();
  if (model_.paused) ++pendingSteps_;
  requestFrame();
  if (techniqueId.empty()) Q_EMIT overlayChanged();
  Q_EMIT splitChanged();
  return std::nullopt;
}

const std::string& FrameLoop::splitTechnique() const {
  return model_.splitTechniqueId;
}

std::map<std::string, std::string> FrameLoop::splitParams() const {
  std::map<std::string, std::string> out;
  if (!model_.split) return out;
  const sl::ParamSet& set = model_.split->params();
  for (const sl::ParamDecl& d : set.decls()) out[d.key] = set.format(d.key);
  return out;
}

void FrameLoop::setSplitPublications(std::set<std::string> keys) {
  model_.splitPublicationKeys = std::move(keys);
  if (model_.split) model_.split->requestPublications(model_.splitPublicationKeys);
}

QImage FrameLoop::renderedImage() const {
  const QImage& mainImage = model_.mainImage;
  const QImage& splitImage = model_.splitImage;
  if (mainImage.isNull()) return {};
  if (splitImage.isNull()) return mainImage;
  QImage both(mainImage.width() + splitImage.width(),
              std::max(mainImage.height(), splitImage.height()), QImage::Format_RGBA8888);
  both.fill(Qt::black);
  QPainter p(&both);
  p.drawImage(0, 0, mainImage);
  p.drawImage(mainImage.width(), 0, splitImage);
  return both;
}

void FrameLoop::setSceneLoading(bool loading) {
  sceneLoading_ = loading;
  if (!loading) pump();
}

bool FrameLoop::continuous() const {
  return model_.continuous;
}

void FrameLoop::setContinuous(bool on) {
  model_.continuous = on;
  measure_->continuousChanged(on);
  if (on) {
    requestFrame();
  } else if (progressNote_) {  // a progressive frame's view: drawn again in one call
    markViewChanged();
    requestFrame();
  }
  Q_EMIT overlayChanged();
}

void FrameLoop::setAdaptiveAllowed(bool allowed) {
  adaptiveAllowed_ = allowed;
  requestFrame();
}

void FrameLoop::setPresenting(bool on) {
  presenting_ = on;
  requestFrame();
}

bool FrameLoop::adaptiveActive() const {
  if (!adaptiveAllowed_ || presenting_ || model_.split) return false;
  return model_.shared.has("view.adaptive") && model_.shared.getBool("view.adaptive");
}

void FrameLoop::renderFullSizeNow(bool always) {
  if (!model_.ready) return;
  const bool current = framesInFlight_ == 0 && model_.shownViewRevision == model_.viewRevision &&
                       lastFrameSize_ == deviceSize() && model_.framesRendered > 0;
  if (model_.frameDivisor == 1 && current && !always) return;
  fullSizeNext_ = true;
  (void)renderNow(makeOrder());
}

std::optional<std::string> FrameLoop::reloadShaders() {
  if (!model_.ready) return std::string("the renderer is not running");
  std::optional<std::string> error;
  service_->call(
      [&](RenderContext& c) {
        for (const char* name : {"main", "split", "charts"})
          if (sl::Renderer* r = c.existing(name))
            if (auto e = r->reloadShaders(); e && !error) error = e;
      },
      tr("reloading the shaders"));
  markViewChanged();
  requestFrame();
  return error;
}

bool FrameLoop::paused() const {
  return model_.paused;
}

void FrameLoop::setPaused(bool paused, bool badge) {
  model_.pausedBadge = badge;
  if (model_.paused == paused) return Q_EMIT overlayChanged();
  model_.paused = paused;
  pendingSteps_ = 0;
  // Paused in continuous rendering: no more frames, so the still view's error is computed
  // as on demand.
  measure_->pausedChanged(paused);
  Q_EMIT overlayChanged();
  requestFrame();
}

void FrameLoop::stepFrame() {
  ++pendingSteps_;
  requestFrame();
}

std::uint64_t FrameLoop::framesRendered() const {
  return model_.framesRendered;
}

QSize FrameLoop::frameSize() const {
  return model_.internalSize;
}

QString FrameLoop::frameFailure() const {
  return model_.frameFailure;
}

QString FrameLoop::resolutionNote() const {
  QString note;
  if (model_.frameDivisor > 1)
    note = tr("internal resolution %1\u00d7%2: frame took %3 ms")
               .arg(model_.internalSize.width())
               .arg(model_.internalSize.height())
               .arg(adaptive_.dropFrameMs() > 0 ? adaptive_.dropFrameMs() : model_.lastFrameMs, 0,
                    'f', 0);
  const QString tiles = progressText();
  if (!tiles.isEmpty()) note += (note.isEmpty() ? QString() : QStringLiteral("  \u00b7  ")) + tiles;
  return note;
}

QString FrameLoop::progressText() const {
  if (!progressNote_ || progressNote_->shownComplete) return {};
  const int per = std::max(1, progressNote_->unitsPerTile);
  const int bands = progressNote_->done % per;
  const QString ofNext = bands ? tr(" (+ %1 of %2 bands)").arg(bands).arg(per) : QString();
  return tr("tile %1 of %2%3: drawn progressively, error when complete")
      .arg(progressNote_->done / per)
      .arg(progressNote_->total / per)
      .arg(ofNext);
}

}  // namespace sl::ui
