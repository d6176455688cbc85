// The 3D view (see ViewportWidget.h). It never calls GL: frames, errors, probes, figures and
// the memory match run on the render service's thread (ViewFrame.h), and their results come
// back as queued calls.
#include "view/ViewportWidget.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <QPainter>

#include "view/LightGizmo.h"
#include "window/MessageText.h"
#include "service/RenderService.h"
#include "service/ViewFrame.h"
#include "view/ViewOverlay.h"

namespace sl::ui {

ViewportWidget::ViewportWidget(QWidget* parent)
    : QWidget(parent),
      shared_(sl::rendererParamDecls()),
      liveMain_(kLiveReferenceMinIntervalS, kLiveReferenceDurationFactor),
      liveSplit_(kLiveReferenceMinIntervalS, kLiveReferenceDurationFactor) {
  main_.setSharedParams(&shared_);
  setAttribute(Qt::WA_OpaquePaintEvent);
  overlay_ = new ViewOverlay(this);
  overlay_->hide();
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(true);  // hover: the pixel under the mouse (pixelProbed)
  setMinimumSize(160, 120);
  errorTimer_.setSingleShot(true);
  connect(&errorTimer_, &QTimer::timeout, this, &ViewportWidget::computeErrorIfStill);
  // Adaptive resolution: once the view is still, a reduced frame is redrawn at full size.
  settleTimer_.setSingleShot(true);
  connect(&settleTimer_, &QTimer::timeout, this, [this] {
    if (frameDivisor_ == 1) return;
    // Still interacting, or a frame on its way: the view is not still yet.
    if (dragButton_ != Qt::NoButton || !heldKeys_.empty() || framesInFlight_ > 0)
      return settleTimer_.start();
    fullSizeNext_ = true;
    requestFrame();
  });
  flyTimer_.setInterval(kFlyTickMs);
  connect(&flyTimer_, &QTimer::timeout, this, &ViewportWidget::flyStep);
  busyTimer_.setInterval(100);  // the busy note's seconds, while a frame is computed
  connect(&busyTimer_, &QTimer::timeout, this, [this] {
    // Only while the busy note is (or was just) shown: a quick frame redraws nothing here.
    const bool busy = !busyText().isEmpty();
    if (busy || busyShown_) updateOverlayWidget();
    busyShown_ = busy;
  });
  service_ = new RenderService(this);
  connect(service_, &RenderService::ready, this, &ViewportWidget::serviceReady);
  // An action the window waits for: its note and seconds in the view until it ends.
  connect(service_, &RenderService::callStarted, this, [this](const QString& note) {
    if (note.isEmpty()) return;
    callNote_ = note;
    callClock_.start();
    busyTimer_.start();
    updateOverlayWidget();
  });
  connect(service_, &RenderService::callEnded, this, [this](int stillWaiting) {
    if (stillWaiting > 0) return;
    // The frames asked for during the wait, after what the caller does with its result.
    QTimer::singleShot(0, this, [this] { pump(); });
    if (callNote_.isEmpty()) return;
    callNote_.clear();
    if (framesInFlight_ == 0) busyTimer_.stop();
    updateOverlayWidget();
  });
  connect(service_, &RenderService::failed, this,
          [this](const QString& message) { Q_EMIT initializationFailed(message); });
  service_->start();
}

ViewportWidget::~ViewportWidget() {
  liveMain_.cancel();
  liveSplit_.cancel();
  if (ready_) Q_EMIT rendererAboutToBeDestroyed();
  delete service_;  // stops the frame in progress, frees the renderers, joins the thread
  service_ = nullptr;
}

void ViewportWidget::serviceReady(const QString& description) {
  glDescription_ = description;
  ready_ = true;
  Q_EMIT rendererReady();
  requestFrame();
}

QSize ViewportWidget::deviceSize() const {
  const qreal dpr = devicePixelRatioF();
  return {static_cast<int>(std::lround(width() * dpr)),
          static_cast<int>(std::lround(height() * dpr))};
}

void ViewportWidget::requestFrame() {
  frameWanted_ = true;
  pump();
}

void ViewportWidget::noticeEdits() {
  const bool splitEdited = split_ && split_->revision() != lastSplitRevision_;
  if (main_.revision() == lastMainRevision_ && shared_.revision() == lastSharedRevision_ &&
      !splitEdited)
    return;
  lastMainRevision_ = main_.revision();
  lastSharedRevision_ = shared_.revision();
  if (split_) lastSplitRevision_ = split_->revision();
  if (splitEdited) splitErrorPct_.reset();
  markViewChanged();
}

void ViewportWidget::pump() {
  // No new frame while a scene loads or while the window waits for an action on the render
  // thread (RenderService::call: what it reads next is of the frame it drew, not of one
  // queued during the wait); each asks again when it ends.
  if (!ready_ || !frameWanted_ || !service_ || sceneLoading_ || service_->callsWaiting() > 0)
    return;
  noticeEdits();
  const bool inFlight = framesInFlight_ > 0;
  const bool changed = viewRevision_ != sentViewRevision_;
  // Paused: the last frame stays unless a step is pending or the size changed.
  if (paused_ && pendingSteps_ == 0 && lastFrameSize_ == deviceSize() && framesRendered_ > 0 &&
      !inFlight) {
    frameWanted_ = false;
    return;
  }
  if (inFlight && !changed) return;  // its outcome pumps again
  if (pendingSteps_ > 0) --pendingSteps_;
  frameWanted_ = false;
  const std::shared_ptr<FrameOrder> order = makeOrder();
  busyTechnique_ = QString::fromStdString(main_.techniqueId()) +
                   (order->split ? QStringLiteral(" | ") + QString::fromStdString(splitTechniqueId_)
                                 : QString());
  busyTimer_.start();
  // A changed view stops the frame in progress: its result would be of the old view. Not
  // while a drag or a fly key moves the camera: every move would stop the frame before it
  // completes, and the view would show nothing new until the hand rests; the frame in
  // progress completes (drawn, one view behind) and the newest camera is rendered next.
  const bool interacting = dragButton_ != Qt::NoButton || !heldKeys_.empty();
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

std::shared_ptr<FrameOrder> ViewportWidget::makeOrder() {
  auto o = std::make_shared<FrameOrder>();
  o->id = ++ordersSent_;
  o->scene = scene_;
  o->camera = camera_;
  o->light = light_;
  o->main = main_.takeRequest();
  const QSize size = deviceSize();
  lastFrameSize_ = size;
  const int w = size.width(), h = size.height();
  // A view dragged down to a few pixels draws nothing: a frame that small feeds temporal
  // state (DA-RTW's rotation, kept by its vibration threshold) a degenerate importance map.
  if (w < kMinDrawnPx || h < kMinDrawnPx) {
    o->clearOnly = true;
  } else {
    // No right half narrower than the smallest drawn view: the left half takes it all.
    const bool split = split_ && w / 2 >= kMinDrawnPx;
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
    if (divisor != frameDivisor_) markViewChanged();  // another image: the error is not its
    o->divisor = divisor;
    o->frameWidth = sl::AdaptiveResolution::scaled(mainWidth, divisor);
    o->frameHeight = sl::AdaptiveResolution::scaled(h, divisor);
    if (split) {
      o->split = split_->takeRequest();
      o->split->publications = splitPublicationKeys_;
      o->splitWidth = sl::AdaptiveResolution::scaled(w - mainWidth, divisor);
    }
    // Progressive resolve (continuous rendering in an interactive window): a technique that
    // resolves tile by tile spends at most half the budget on tiles per frame and keeps its
    // result between frames. Scripted runs and on-demand frames resolve in one call.
    if (adaptiveAllowed_ && continuous_ && !paused_)
      o->progressiveBudgetMs =
          kProgressiveShare * double(shared_.getInt("view.adaptive.budget_ms"));
    const qreal dpr = devicePixelRatioF();
    const int x = int(std::floor(hover_.x() * dpr)), y = int(std::floor(hover_.y() * dpr));
    if (probeWanted_ && hover_.x() >= 0 && !outsideView() && x < mainWidth) {
      o->probe = QPoint(x / divisor, y / divisor);
      ++probesRead_;
    }
  }
  o->viewRevision = viewRevision_;
  sentViewRevision_ = viewRevision_;
  o->shared = shared_;
  o->snapshotMain = continuous_ && liveMain_.wantsTrace(viewRevision_);
  o->snapshotSplit = continuous_ && o->split && liveSplit_.wantsTrace(viewRevision_);
  o->referenceMask = std::exchange(maskToUpload_, std::nullopt);
  return o;
}

void ViewportWidget::applyOutcome(const std::shared_ptr<FrameOutcome>& out) {
  ordersDone_ = std::max(ordersDone_, out->id);
  if (framesInFlight_ == 0 && callNote_.isEmpty()) busyTimer_.stop();
  if (out->stopped) {  // never shown, never measured
    ++framesStopped_;
    if (out->id == ordersSent_) frameWanted_ = true;  // stopped by an export: draw it again
    pump();
    updateOverlayWidget();
    return;
  }
  if (out->id <= lastAppliedId_) return;  // older than the frame shown (an export's came first)
  lastAppliedId_ = out->id;
  ++framesDrawn_;
  shownViewRevision_ = out->viewRevision;
  mainImage_ = out->mainImage;
  splitImage_ = out->hasSplit ? out->splitImage : QImage();
  frameDivisor_ = out->divisor;
  internalSize_ = mainImage_.size();
  if (out->viewRevision != viewRevision_) {
    // Of a view that has changed since (a drag, an edit): shown while the current one is
    // computed, but neither counted, measured nor published.
    updateZoomInset();
    updateOverlayWidget();
    update();
    pump();
    return;
  }
  lastFrameMs_ = out->wallMs;
  frameFailure_ = QString::fromStdString(out->mainProblem);
  main_.setFrame(std::move(out->mainStats), std::move(out->mainPublication));
  if (split_ && out->hasSplit)
    split_->setFrame(std::move(out->splitStats), std::move(out->splitPublication));
  // A progressive frame's tiles are bounded by their own budget: the resolution follows the
  // rest (the per-pixel work), else a slow tile would drop the view and restart the tiles.
  const auto& progress = main_.stats().progress;
  const bool failed = !out->mainProblem.empty();
  if (adaptiveActive() && !failed && !out->fullSize)
    adaptive_.onFrame(progress ? std::max(0.0, lastFrameMs_ - progress->spentMs) : lastFrameMs_,
                      double(shared_.getInt("view.adaptive.budget_ms")));
  progressNote_ = progress && !failed ? progress : std::nullopt;
  ++framesRendered_;
  std::string problem = out->splitProblem;
  if (failed) problem += (problem.empty() ? "" : "; ") + out->mainProblem;
  for (const std::string& glError : out->glErrors)
    problem += (problem.empty() ? "" : "; ") + glError;
  if (!problem.empty() && problem != lastProblem_)
    Q_EMIT renderProblem(QString::fromStdString(problem));
  lastProblem_ = problem;
  // A partial progressive frame is neither traced nor measured: the error waits.
  const bool partial = !main_.stats().complete();
  if (continuous_ && !failed && !partial) updateLiveReferences(*out);
  updateZoomInset();
  updateOverlayWidget();
  update();
  Q_EMIT frameRendered();
  if (out->probed && probeWanted_) Q_EMIT pixelProbed(out->probe);
  // On demand (or paused): the error is computed once the view is still. Continuous: the
  // live reference keeps it.
  if (frameDivisor_ > 1 && (!continuous_ || paused_))
    settleTimer_.start(kSettleDelayMs);
  else
    settleTimer_.stop();
  if (partial)
    errorTimer_.stop();
  else if (!errorIsCurrent() && (!continuous_ || paused_))
    errorTimer_.start(kErrorDelayMs);
  if (continuous_ && !paused_) frameWanted_ = true;
  pump();
}

bool ViewportWidget::renderNow(const std::shared_ptr<FrameOrder>& order) {
  auto out = std::make_shared<FrameOutcome>();
  if (!service_->call([&](RenderContext& c) { renderOrder(c, *order, *out); },
                      tr("drawing the view at full size")))
    return false;
  applyOutcome(out);
  return !out->stopped;
}

void ViewportWidget::paintEvent(QPaintEvent*) {
  QPainter p(this);
  if (mainImage_.isNull()) {
    p.fillRect(rect(), QColor(24, 26, 29));
    return;
  }
  // A reduced (adaptive) frame is stretched smoothly, as a GPU blit would; a full-size one is
  // drawn pixel for pixel.
  p.setRenderHint(QPainter::SmoothPixmapTransform, frameDivisor_ > 1);
  const int mainW = splitImage_.isNull() ? width() : width() / 2;
  p.drawImage(QRect(0, 0, mainW, height()), mainImage_);
  if (mainW < width() && splitImage_.isNull())
    p.fillRect(QRect(mainW, 0, width() - mainW, height()), Qt::black);
}

void ViewportWidget::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  overlay_->setGeometry(rect());
  markViewChanged();
  requestFrame();
}

QString ViewportWidget::busyText() const {
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

std::optional<std::string> ViewportWidget::setSplitTechnique(
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
    side->setSharedParams(&shared_);
    side->requestPublications(splitPublicationKeys_);
    side->resetTemporalState();
  }
  split_ = std::move(side);
  splitTechniqueId_ = techniqueId;
  if (split_) lastSplitRevision_ = split_->revision();
  splitErrorPct_.reset();
  liveSplit_.cancel();  // of the previous right half
  markViewChanged();
  if (paused_) ++pendingSteps_;
  requestFrame();
  if (techniqueId.empty()) updateOverlayWidget();
  Q_EMIT splitChanged();
  return std::nullopt;
}

std::map<std::string, std::string> ViewportWidget::splitParams() const {
  std::map<std::string, std::string> out;
  if (!split_) return out;
  const sl::ParamSet& set = split_->params();
  for (const sl::ParamDecl& d : set.decls()) out[d.key] = set.format(d.key);
  return out;
}

void ViewportWidget::setSplitPublications(std::set<std::string> keys) {
  splitPublicationKeys_ = std::move(keys);
  if (split_) split_->requestPublications(splitPublicationKeys_);
}

void ViewportWidget::setZoomArea(const std::optional<QRect>& area) {
  zoomArea_ = area ? std::optional<QRect>(area->intersected(rect())) : std::nullopt;
  if (zoomArea_ && zoomArea_->isEmpty()) zoomArea_.reset();
  updateZoomInset();
  updateOverlayWidget();
}

ViewportWidget::Readouts ViewportWidget::readouts() const {
  Readouts r;
  r.internalDivisor = frameDivisor_;
  r.adaptiveDivisor = adaptive_.divisor();
  r.lastFrameMs = lastFrameMs_;
  r.progress = progressNote_;
  r.framesStopped = framesStopped_;
  r.framesDrawn = framesDrawn_;
  r.probesRead = probesRead_;
  r.leftCaption = splitCaption(false);
  r.rightCaption = splitCaption(true);
  r.errorOverlayNote = errorOverlayNote();
  r.pointerHighlight = pointerHighlight_;
  r.zoomArea = zoomArea_;
  r.zoomInset = zoomInsetRect();
  r.zoomFactor = zoomFactor();
  r.liveReference = liveMain_.worker();
  r.splitLiveReference = liveSplit_.worker();
  return r;
}

QImage ViewportWidget::renderedImage() const {
  if (mainImage_.isNull()) return {};
  if (splitImage_.isNull()) return mainImage_;
  QImage both(mainImage_.width() + splitImage_.width(),
              std::max(mainImage_.height(), splitImage_.height()), QImage::Format_RGBA8888);
  both.fill(Qt::black);
  QPainter p(&both);
  p.drawImage(0, 0, mainImage_);
  p.drawImage(mainImage_.width(), 0, splitImage_);
  return both;
}

void ViewportWidget::updateZoomInset() {
  if (!zoomArea_ || mainImage_.isNull()) {
    overlay_->zoomSource = QImage();
    return;
  }
  // The view as shown, in device pixels: each half stretched over its part (nearest).
  const QSize size = deviceSize();
  QImage shown(size, QImage::Format_RGBA8888);
  shown.fill(Qt::black);
  QPainter p(&shown);
  const int mainW = splitImage_.isNull() ? size.width() : size.width() / 2;
  p.drawImage(QRect(0, 0, mainW, size.height()), mainImage_);
  if (!splitImage_.isNull())
    p.drawImage(QRect(mainW, 0, size.width() - mainW, size.height()), splitImage_);
  p.end();
  shown.setDevicePixelRatio(devicePixelRatioF());
  overlay_->zoomSource = shown;
}

QImage ViewportWidget::grabView() {
  renderFullSizeNow();
  return grab().toImage();
}

void ViewportWidget::setSceneLoading(bool loading) {
  sceneLoading_ = loading;
  if (!loading) pump();
}

void ViewportWidget::setScene(std::shared_ptr<const sl::Scene> scene) {
  scene_ = std::move(scene);
  cancelLiveReferences();  // a trace of the old scene is never shown
  if (scene_ && scene_->light) light_ = *scene_->light;
  Q_EMIT lightChanged();
  resetView();
}

std::optional<std::string> ViewportWidget::setTechnique(const std::string& id) {
  if (auto error = main_.setTechnique(id)) return error;
  requestFrame();
  return std::nullopt;
}

void ViewportWidget::setCamera(const sl::Camera& camera) {
  camera_ = camera;
  markViewChanged();
  Q_EMIT cameraChanged();
  requestFrame();
}

bool ViewportWidget::outsideView() const {
  return shared_.has("view.outside") && shared_.getBool("view.outside");
}

bool ViewportWidget::setOutsideView(bool on) {
  if (!shared_.has("view.outside")) return false;
  if (outsideView() == on) return true;
  if (shared_.set("view.outside", on ? 1.0 : 0.0)) return false;
  updateOverlayWidget();
  requestFrame();
  return true;
}

void ViewportWidget::setContinuous(bool on) {
  continuous_ = on;
  if (on) {
    errorTimer_.stop();
    liveMain_.start();
    liveSplit_.start();
    requestFrame();
  } else {
    cancelLiveReferences();
    if (!errorIsCurrent()) errorTimer_.start(kErrorDelayMs);
    if (progressNote_) {  // a progressive frame's view: drawn again in one call
      markViewChanged();
      requestFrame();
    }
  }
  updateOverlayWidget();
}

void ViewportWidget::setAdaptiveAllowed(bool allowed) {
  adaptiveAllowed_ = allowed;
  requestFrame();
}

void ViewportWidget::setPresenting(bool on) {
  presenting_ = on;
  requestFrame();
}

bool ViewportWidget::adaptiveActive() const {
  if (!adaptiveAllowed_ || presenting_ || split_) return false;
  return shared_.has("view.adaptive") && shared_.getBool("view.adaptive");
}

void ViewportWidget::renderFullSizeNow(bool always) {
  if (!ready_) return;
  const bool current = framesInFlight_ == 0 && shownViewRevision_ == viewRevision_ &&
                       lastFrameSize_ == deviceSize() && framesRendered_ > 0;
  if (frameDivisor_ == 1 && current && !always) return;
  fullSizeNext_ = true;
  (void)renderNow(makeOrder());
}

void ViewportWidget::setProbeWanted(bool wanted) {
  if (probeWanted_ == wanted) return;
  probeWanted_ = wanted;
  if (!wanted)
    Q_EMIT pixelProbed(std::nullopt);  // an answer still on its way is dropped
  else
    probeHover();
}

void ViewportWidget::probeHover() {
  if (hover_.x() < 0 || !ready_ || !probeWanted_ || mainImage_.isNull()) return;
  const qreal dpr = devicePixelRatioF();
  const int x = int(std::floor(hover_.x() * dpr)), y = int(std::floor(hover_.y() * dpr));
  if (outsideView() || x >= lastMainWidth_) {
    Q_EMIT pixelProbed(std::nullopt);
    return;
  }
  // One probe on its way at a time: moves meanwhile ask for one more, at the pointer's place
  // when the answer comes (a long frame does not queue a readback per mouse move).
  if (probeInFlight_) {
    probeAgain_ = true;
    return;
  }
  const QPoint at(x / frameDivisor_, y / frameDivisor_);  // internal pixels
  probeInFlight_ = true;
  ++probesRead_;  // asked of the render thread: one pixel read back
  service_->post(RenderTag::kProbe, [this, at](RenderContext& c) {
    std::optional<sl::PixelProbe> probe;
    if (sl::Renderer* r = c.existing("main")) probe = r->probePixel(at.x(), at.y());
    QMetaObject::invokeMethod(
        this,
        [this, probe] {
          probeInFlight_ = false;
          if (std::exchange(probeAgain_, false)) return probeHover();  // the mouse moved on
          if (probeWanted_) Q_EMIT pixelProbed(probe);
        },
        Qt::QueuedConnection);
  });
}

void ViewportWidget::markViewChanged() {
  ++viewRevision_;
  Q_EMIT viewChanged();
}

void ViewportWidget::updateOverlayWidget() {
  const LightGizmo gizmo =
      outsideView() ? LightGizmo{} : lightGizmo(scene_.get(), light_, camera_, width(), height());
  overlay_->gizmoLines = gizmo.lines;
  overlay_->gizmoPoint = gizmo.point;
  const bool split = split_ && !splitImage_.isNull();
  overlay_->split = split ? splitImage_ : QImage();
  if (split) {
    // Continuous rendering: each half's live error (its own reference) and how old it is.
    auto caption = [this](const std::string& id, const sl::FrameStats& stats,
                          std::optional<double> exact, const std::optional<LiveError>& live,
                          const QString& unmeasured) {
      if (!continuous_)
        return QString::fromStdString(
            sl::sideCaption(id, stats, errorIsCurrent() ? exact : std::nullopt, {},
                            errorIsCurrent() ? unmeasured.toStdString() : std::string()));
      const bool measured = live && live->unmeasured.isEmpty();
      return QString::fromStdString(
          sl::sideCaption(id, stats, measured ? std::optional(live->errorPct) : std::nullopt,
                          live ? sl::describeReferenceAge(live->age)
                               : tr("tracing the reference\u2026").toStdString(),
                          live ? live->unmeasured.toStdString() : std::string()));
    };
    overlay_->leftCaption =
        caption(main_.techniqueId(), main_.stats(), mainErrorPct_, liveError(), errorUnmeasured_);
    overlay_->rightCaption = caption(splitTechniqueId_, split_->stats(), splitErrorPct_,
                                     splitLiveError(), splitErrorUnmeasured_);
  }
  const sl::TechniqueInfo* mainInfo = sl::Renderer::findTechnique(main_.techniqueId());
  overlay_->setLegends(shared_, main_.stats(), outsideView(),
                       mainInfo ? mainInfo->aliasingPattern : std::string());
  overlay_->pointerRing.reset();
  if (pointerHighlight_ && hover_.x() >= 0) overlay_->pointerRing = hover_;
  overlay_->zoomArea = zoomArea_.value_or(QRect());
  overlay_->zoomDrag = zoomDragging_.value_or(QRect());
  overlay_->resolutionNote = resolutionNote();
  if (const QString busy = busyText(); !busy.isEmpty())
    overlay_->resolutionNote +=
        (overlay_->resolutionNote.isEmpty() ? QString() : QStringLiteral("  \u00b7  ")) + busy;
  overlay_->errorNote.clear();
  if (continuous_) {  // the live reference: how old, or being traced for this view
    const auto live = liveError();
    overlay_->errorNote = !live || live->age.stale
                              ? tr("view changed: tracing its reference\u2026")
                              : QString::fromStdString(sl::describeReferenceAge(live->age));
  } else if (!errorIsCurrent()) {
    overlay_->errorNote = tr("(computing the reference\u2026)");
  }
  overlay_->pausedText = paused_ && pausedBadge_
                             ? tr("PAUSED at frame %1  \u00b7  . step  \u00b7  Space resume")
                                   .arg(static_cast<qulonglong>(main_.stats().frameIndex))
                             : QString();
  overlay_->setVisible(overlay_->hasContent());
  overlay_->raise();
  overlay_->update();
}

void ViewportWidget::setPaused(bool paused, bool badge) {
  pausedBadge_ = badge;
  if (paused_ == paused) return updateOverlayWidget();
  paused_ = paused;
  pendingSteps_ = 0;
  // Paused in continuous rendering: no more frames, so the still view's error is computed
  // as on demand.
  if (paused_ && !errorIsCurrent()) errorTimer_.start(kErrorDelayMs);
  updateOverlayWidget();
  requestFrame();
}

void ViewportWidget::stepFrame() {
  ++pendingSteps_;
  requestFrame();
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

QRect ViewportWidget::zoomInsetRect() const {
  overlay_->placeInset();
  return overlay_->insetRect;
}

int ViewportWidget::zoomFactor() const {
  overlay_->placeInset();
  return overlay_->insetFactor;
}

void ViewportWidget::goToBookmark(int index) {
  if (!scene_) return;
  if (index >= 0 && index < static_cast<int>(scene_->cameras.size()))
    setCamera(scene_->cameras[static_cast<size_t>(index)].camera);
  else
    setCamera(scene_->defaultCamera());
}

void ViewportWidget::resetView() {
  goToBookmark(0);
}

void ViewportWidget::setLight(const sl::Light& light) {
  if (light_ == light) return;
  light_ = light;
  markViewChanged();
  requestFrame();
  Q_EMIT lightChanged();
}

QString ViewportWidget::splitCaption(bool right) const {
  return right ? overlay_->rightCaption : overlay_->leftCaption;
}

QString ViewportWidget::resolutionNote() const {
  QString note;
  if (frameDivisor_ > 1)
    note =
        tr("internal resolution %1\u00d7%2: frame took %3 ms")
            .arg(internalSize_.width())
            .arg(internalSize_.height())
            .arg(adaptive_.dropFrameMs() > 0 ? adaptive_.dropFrameMs() : lastFrameMs_, 0, 'f', 0);
  const QString tiles = progressText();
  if (!tiles.isEmpty()) note += (note.isEmpty() ? QString() : QStringLiteral("  \u00b7  ")) + tiles;
  return note;
}

QString ViewportWidget::progressText() const {
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
