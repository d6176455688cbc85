// What the view measures (see MeasureService.h). Each measurement runs as a job on the render
// service; results come back as queued calls and are kept only for the view revision they
// were measured for.
#include "view/MeasureService.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <QWidget>

#include "service/RenderService.h"
#include "service/ViewFrame.h"
#include "view/CameraController.h"
#include "view/FrameLoop.h"
#include "view/ViewModel.h"

namespace sl::ui {

MeasureService::MeasureService(QWidget& widget, ViewModel& model, const CameraController& camera,
                               FrameLoop& frames)
    : QObject(&widget),
      widget_(widget),
      model_(model),
      camera_(camera),
      frames_(frames),
      liveMain_(kLiveReferenceMinIntervalS, kLiveReferenceDurationFactor),
      liveSplit_(kLiveReferenceMinIntervalS, kLiveReferenceDurationFactor) {
  errorTimer_.setSingleShot(true);
  connect(&errorTimer_, &QTimer::timeout, this, &MeasureService::computeErrorIfStill);
}

MeasureService::~MeasureService() {
  liveMain_.cancel();
  liveSplit_.cancel();
}

bool MeasureService::errorIsCurrent() const {
  return errorRevision_ == model_.viewRevision;
}

std::optional<double> MeasureService::errorPct() const {
  return errorIsCurrent() ? mainErrorPct_ : std::nullopt;
}

QString MeasureService::errorNotMeasured() const {
  return errorIsCurrent() ? errorUnmeasured_ : QString();
}

const sl::AsyncReference* MeasureService::liveReference(bool split) const {
  return split ? liveSplit_.worker() : liveMain_.worker();
}

void MeasureService::prepareOrder(FrameOrder& o) {
  if (!o.clearOnly) {
    const qreal dpr = widget_.devicePixelRatioF();
    const int x = int(std::floor(model_.hover.x() * dpr));
    const int y = int(std::floor(model_.hover.y() * dpr));
    if (probeWanted_ && model_.hover.x() >= 0 && !model_.outsideView() && x < frames_.mainWidth()) {
      o.probe = QPoint(x / o.divisor, y / o.divisor);
      ++probesRead_;
    }
  }
  o.snapshotMain = model_.continuous && liveMain_.wantsTrace(model_.viewRevision);
  o.snapshotSplit = model_.continuous && o.split && liveSplit_.wantsTrace(model_.viewRevision);
  o.referenceMask = std::exchange(maskToUpload_, std::nullopt);
}

void MeasureService::frameApplied(const FrameOutcome& out, bool partial) {
  if (out.probed && probeWanted_) Q_EMIT pixelProbed(out.probe);
  // On demand (or paused): the error is computed once the view is still. Continuous: the
  // live reference keeps it.
  if (partial)
    errorTimer_.stop();
  else if (!errorIsCurrent() && (!model_.continuous || model_.paused))
    errorTimer_.start(kErrorDelayMs);
}

void MeasureService::continuousChanged(bool on) {
  if (on) {
    errorTimer_.stop();
    liveMain_.start();
    liveSplit_.start();
  } else {
    cancelLiveReferences();
    if (!errorIsCurrent()) errorTimer_.start(kErrorDelayMs);
  }
}

void MeasureService::pausedChanged(bool paused) {
  if (paused && !errorIsCurrent()) errorTimer_.start(kErrorDelayMs);
}

void MeasureService::forgetSplitError(bool cancelTrace) {
  splitErrorPct_.reset();
  if (cancelTrace) liveSplit_.cancel();
}

void MeasureService::dragEnded() {
  if (!errorIsCurrent()) errorTimer_.start(kErrorDelayMs);
}

void MeasureService::setProbeWanted(bool wanted) {
  if (probeWanted_ == wanted) return;
  probeWanted_ = wanted;
  if (!wanted)
    Q_EMIT pixelProbed(std::nullopt);  // an answer still on its way is dropped
  else
    probeHover();
}

void MeasureService::probeHover() {
  if (model_.hover.x() < 0 || !model_.ready || !probeWanted_ || model_.mainImage.isNull()) return;
  const qreal dpr = widget_.devicePixelRatioF();
  const int x = int(std::floor(model_.hover.x() * dpr));
  const int y = int(std::floor(model_.hover.y() * dpr));
  if (model_.outsideView() || x >= frames_.mainWidth()) {
    Q_EMIT pixelProbed(std::nullopt);
    return;
  }
  // One probe on its way at a time: moves meanwhile ask for one more, at the pointer's place
  // when the answer comes (a long frame does not queue a readback per mouse move).
  if (probeInFlight_) {
    probeAgain_ = true;
    return;
  }
  const QPoint at(x / model_.frameDivisor, y / model_.frameDivisor);  // internal pixels
  probeInFlight_ = true;
  ++probesRead_;  // asked of the render thread: one pixel read back
  frames_.service().post(RenderTag::kProbe, [this, at](RenderContext& c) {
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

void MeasureService::updateLiveReferences(FrameOutcome& out) {
  std::string failure;
  if (auto done = liveMain_.takeFinished(&failure)) {
    if (done->viewRevision == model_.viewRevision) {
      // The error overlay draws the mask only while frames show what was traced.
      maskToUpload_ = std::move(done);
      const sl::ShadowErrorStats& stats = liveMain_.latest()->trace.stats;
      mainErrorPct_ = stats.covered > 0 ? std::optional(stats.errorPct) : std::nullopt;
      errorUnmeasured_ = unmeasuredReason(stats);
      errorRevision_ = model_.viewRevision;
      if (mainErrorPct_)
        Q_EMIT errorComputed(*mainErrorPct_);
      else
        Q_EMIT errorUnmeasured(errorUnmeasured_);
    }
  }
  if (!failure.empty())
    Q_EMIT renderProblem(
        QStringLiteral("reference trace failed: %1").arg(QString::fromStdString(failure)));
  failure.clear();
  if (model_.split && liveSplit_.takeFinished(&failure) &&
      liveSplit_.latest()->viewRevision == model_.viewRevision)
    splitErrorPct_ = liveSplit_.latest()->trace.stats.errorPct;
  if (!failure.empty())
    Q_EMIT renderProblem(QStringLiteral("split view: reference trace failed: %1")
                             .arg(QString::fromStdString(failure)));
  if (auto job = referenceJob(out.mainSnapshot, out.viewRevision, model_.framesRendered))
    liveMain_.submit(std::move(*job));
  if (auto job = referenceJob(out.splitSnapshot, out.viewRevision, model_.framesRendered))
    liveSplit_.submit(std::move(*job));
}

void MeasureService::cancelLiveReferences() {
  liveMain_.cancel();
  liveSplit_.cancel();
  maskToUpload_.reset();
}

std::optional<LiveError> MeasureService::liveError() const {
  if (!model_.continuous) return std::nullopt;
  return liveMain_.error(model_.viewRevision, model_.framesRendered);
}

std::optional<LiveError> MeasureService::splitLiveError() const {
  if (!model_.continuous || !model_.split) return std::nullopt;
  return liveSplit_.error(model_.viewRevision, model_.framesRendered);
}

void MeasureService::applyError(std::uint64_t viewRevision, const SideError& main,
                                const std::optional<SideError>& split) {
  if (viewRevision != model_.viewRevision) return;  // the view moved on: not its error
  if (!main.problem.empty()) {
    Q_EMIT renderProblem(
        QStringLiteral("error metric failed: %1").arg(QString::fromStdString(main.problem)));
    return;
  }
  if (split) {
    splitErrorPct_ = split->pct;
    splitErrorUnmeasured_ = QString::fromStdString(split->unmeasured);
  }
  errorRevision_ = model_.viewRevision;
  mainErrorPct_ = main.pct;
  errorUnmeasured_ = QString::fromStdString(main.unmeasured);
  if (mainErrorPct_) {
    Q_EMIT errorComputed(*mainErrorPct_);
    // The error overlay shows the reference just computed: draw it (unless paused, where the
    // frozen frame must stay the one that was measured).
    if (sl::enumIs(model_.shared, "view.overlay", "error") && !model_.paused)
      frames_.requestFrame();
  } else {
    Q_EMIT errorUnmeasured(errorUnmeasured_);
  }
  Q_EMIT overlayChanged();
}

bool MeasureService::failedFrameUnmeasured() {
  if (model_.frameFailure.isEmpty()) return false;
  // A frame that failed is not measured: its image is the neutral frame, not the technique's.
  errorRevision_ = model_.viewRevision;
  mainErrorPct_.reset();
  errorUnmeasured_ = tr("the frame failed: %1").arg(model_.frameFailure);
  Q_EMIT errorUnmeasured(errorUnmeasured_);
  Q_EMIT overlayChanged();
  return true;
}

std::optional<double> MeasureService::computeErrorNow() {
  if (!model_.ready || model_.framesRendered == 0) return std::nullopt;
  // The error of the view as it is now: when the frame shown is older (or one is on its
  // way), a frame of it is drawn in the same job as the measurement.
  // The window goes on handling events while it waits (RenderService::call): the job reads
  // nothing the UI thread may change meanwhile, and what comes back is kept only for the view
  // it was measured for.
  std::shared_ptr<FrameOrder> order;
  if (frames_.framesInFlight() > 0 || model_.shownViewRevision != model_.viewRevision)
    order = frames_.makeOrder();
  const std::uint64_t revision = model_.viewRevision;
  const bool split = order ? order->split.has_value() : model_.split && !model_.splitImage.isNull();
  auto out = std::make_shared<FrameOutcome>();
  SideError main;
  std::optional<SideError> right;
  bool measured = false;
  if (!frames_.service().call(
          [&](RenderContext& c) {
            if (order) {
              renderOrder(c, *order, *out);
              if (out->stopped || !out->mainProblem.empty()) return;
            }
            if (c.stopFlag().load()) return;  // Esc before the trace
            measured = true;
            main = computeSideError(c, "main");
            if (split) right = computeSideError(c, "split");
          },
          tr("tracing the exact reference")))
    return std::nullopt;
  if (order) frames_.applyOutcome(out);
  if (revision != model_.viewRevision || failedFrameUnmeasured() || !measured) return std::nullopt;
  applyError(revision, main, right);
  return errorIsCurrent() ? mainErrorPct_ : std::nullopt;
}

void MeasureService::computeErrorIfStill() {
  if (errorIsCurrent() || !model_.ready) return;
  // Still interacting, or the frame of this view not shown yet: try again later.
  if (camera_.interacting() || frames_.framesInFlight() > 0 ||
      model_.shownViewRevision != model_.viewRevision) {
    errorTimer_.start(kErrorDelayMs);
    return;
  }
  if (failedFrameUnmeasured()) return;
  const std::uint64_t revision = model_.viewRevision;
  const bool split = model_.split && !model_.splitImage.isNull();
  // A newer request replaces one not started (its view is older).
  frames_.service().post(RenderTag::kError, [this, revision, split](RenderContext& c) {
    const SideError main = computeSideError(c, "main");
    std::optional<SideError> right;
    if (split) right = computeSideError(c, "split");
    QMetaObject::invokeMethod(
        this, [this, revision, main, right] { applyError(revision, main, right); },
        Qt::QueuedConnection);
  });
}

std::vector<FigureCell> MeasureService::figureCells(int dilatePx) {
  std::vector<FigureCell> cells;
  if (!model_.ready || model_.framesRendered == 0) return cells;
  auto label = [](const sl::ViewSide& side) {
    const std::string rest = side.nonDefaultParams();
    return side.techniqueId() + (rest.empty() ? "" : " " + rest);
  };
  // A full-size frame of the view as it is and its cells, in one job: a figure is never the
  // reduced (adaptive resolution) image, nor a frame drawn in between.
  frames_.setFullSizeNext();
  const std::shared_ptr<FrameOrder> order = frames_.makeOrder();
  const std::string mainLabel = label(model_.main);
  const std::optional<std::string> splitLabel =
      order->split ? std::optional(label(*model_.split)) : std::nullopt;
  auto out = std::make_shared<FrameOutcome>();
  std::string problem;
  frames_.service().call(
      [&](RenderContext& c) {
        renderOrder(c, *order, *out);
        if (out->stopped || !out->mainProblem.empty()) return;
        try {
          cells.push_back(figureCellOf(c, "main", mainLabel, dilatePx));
          if (splitLabel) cells.push_back(figureCellOf(c, "split", *splitLabel, dilatePx));
        } catch (const std::exception& ex) {
          cells.clear();
          problem = ex.what();
        }
      },
      tr("drawing the figure and its errors"));
  frames_.applyOutcome(out);
  if (out->stopped) cells.clear();  // stopped (Esc): no figure
  if (!problem.empty())
    Q_EMIT renderProblem(QStringLiteral("export figure: %1").arg(QString::fromStdString(problem)));
  return cells;
}

std::optional<MeasureService::MemoryMatch> MeasureService::matchSplitMemory(std::string* error) {
  auto fail = [&](const std::string& why) -> std::optional<MemoryMatch> {
    if (error) *error = why;
    return std::nullopt;
  };
  if (!model_.ready || !model_.split) return fail("the split view is off");
  if (model_.framesRendered == 0 || !model_.main.hasFrame() || model_.main.stats().frameIndex == 0)
    return fail("no frame of the main technique yet");
  const sl::ParamDecl* decl = sl::memoryKnob(model_.split->params().decls());
  if (!decl)
    return fail("technique '" + model_.splitTechniqueId +
                "' declares no parameter its memory grows with, so there is nothing to match");
  MemoryMatch match;
  match.key = decl->key;
  match.mainBytes = model_.main.stats().memory.bytes();
  const QSize size = frames_.deviceSize();
  const int halfW = size.width() - size.width() / 2;
  if (halfW < FrameLoop::kMinDrawnPx || size.height() < FrameLoop::kMinDrawnPx)
    return fail("the view is too small to measure");
  const std::shared_ptr<FrameOrder> order = frames_.makeOrder();
  if (!order->split) return fail("the view is too small to measure");
  MemoryMatchRun run;
  const sl::ParamDecl knob = *decl;
  const std::string splitTechnique = model_.splitTechniqueId;
  if (!frames_.service().call(
          [&](RenderContext& c) {
            run = matchSplitMemoryOn(c, *order, knob, match.mainBytes, halfW, size.height());
          },
          tr("matching the split view's memory")))
    return fail("stopped before it started");
  if (!run.problem.empty()) return fail("split view: " + run.problem);
  // The window handled events while it waited: the split view may be another now.
  if (!model_.split || model_.splitTechniqueId != splitTechnique)
    return fail("the split view changed while its memory was matched");
  match.framesMeasured = run.evaluations;
  match.value = run.value;
  match.belowMinimum = run.belowMinimum;
  match.splitBytes = run.bytes;
  (void)model_.split->params().set(knob.key, double(run.value));
  model_.splitParams[knob.key] = model_.split->params().format(knob.key);
  frames_.requestFrame();
  return match;
}

QString MeasureService::liveErrorText() const {
  if (!model_.continuous) return {};
  const auto e = liveError();
  if (!e) return tr("error \u2014  \u00b7  tracing the reference\u2026");
  const QString age = QString::fromStdString(sl::describeReferenceAge(e->age));
  if (!e->unmeasured.isEmpty()) return tr("error n/a (%1)  \u00b7  %2").arg(e->unmeasured, age);
  const QString pct = QString::number(e->errorPct, 'f', e->errorPct < 1 ? 3 : 2);
  if (e->age.stale) return tr("error %1 %  \u00b7  %2  \u00b7  re-tracing").arg(pct, age);
  return tr("error %1 %  \u00b7  %2").arg(pct, age);
}

bool MeasureService::readCurrentFrame(const std::function<void(sl::Renderer&)>& read) {
  if (!model_.ready) return false;
  // A frame of the view as it is, drawn in the same job when the one shown is older or one
  // is on its way (which the call stops): what is read is always a complete frame.
  std::shared_ptr<FrameOrder> order;
  if (frames_.framesInFlight() > 0 || model_.shownViewRevision != model_.viewRevision ||
      model_.framesRendered == 0)
    order = frames_.makeOrder();
  auto out = std::make_shared<FrameOutcome>();
  const bool ran = frames_.service().call([&](RenderContext& c) {
    if (order) renderOrder(c, *order, *out);
    sl::Renderer* r = c.existing("main");
    if (r && !r->stats().cancelled) read(*r);
  });
  if (order) frames_.applyOutcome(out);
  return ran;
}

}  // namespace sl::ui
