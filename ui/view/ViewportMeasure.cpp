// What the view measures (see ViewportWidget.h): the error of the view as it is (computed
// on the render thread once the view is still, or at once for exports and scripts), the live
// reference of each side in continuous rendering, the figure export and the split view's
// equal-memory match. Each runs as a job on the render service; results come back as queued
// calls and are kept only for the view revision they were measured for.
#include <algorithm>
#include <functional>

#include "service/RenderService.h"
#include "service/ViewFrame.h"
#include "view/ViewOverlay.h"
#include "view/ViewportWidget.h"

namespace sl::ui {

void ViewportWidget::updateLiveReferences(FrameOutcome& out) {
  std::string failure;
  if (auto done = liveMain_.takeFinished(&failure)) {
    if (done->viewRevision == viewRevision_) {
      // The error overlay draws the mask only while frames show what was traced.
      maskToUpload_ = std::move(done);
      const sl::ShadowErrorStats& stats = liveMain_.latest()->trace.stats;
      mainErrorPct_ = stats.covered > 0 ? std::optional(stats.errorPct) : std::nullopt;
      errorUnmeasured_ = unmeasuredReason(stats);
      errorRevision_ = viewRevision_;
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
  if (split_ && liveSplit_.takeFinished(&failure) &&
      liveSplit_.latest()->viewRevision == viewRevision_)
    splitErrorPct_ = liveSplit_.latest()->trace.stats.errorPct;
  if (!failure.empty())
    Q_EMIT renderProblem(QStringLiteral("split view: reference trace failed: %1")
                             .arg(QString::fromStdString(failure)));
  if (auto job = referenceJob(out.mainSnapshot, out.viewRevision, framesRendered_))
    liveMain_.submit(std::move(*job));
  if (auto job = referenceJob(out.splitSnapshot, out.viewRevision, framesRendered_))
    liveSplit_.submit(std::move(*job));
}

void ViewportWidget::cancelLiveReferences() {
  liveMain_.cancel();
  liveSplit_.cancel();
  maskToUpload_.reset();
}

std::optional<LiveError> ViewportWidget::liveError() const {
  if (!continuous_) return std::nullopt;
  return liveMain_.error(viewRevision_, framesRendered_);
}

std::optional<LiveError> ViewportWidget::splitLiveError() const {
  if (!continuous_ || !split_) return std::nullopt;
  return liveSplit_.error(viewRevision_, framesRendered_);
}

void ViewportWidget::applyError(std::uint64_t viewRevision, const SideError& main,
                                const std::optional<SideError>& split) {
  if (viewRevision != viewRevision_) return;  // the view moved on: not its error
  if (!main.problem.empty()) {
    Q_EMIT renderProblem(
        QStringLiteral("error metric failed: %1").arg(QString::fromStdString(main.problem)));
    return;
  }
  if (split) {
    splitErrorPct_ = split->pct;
    splitErrorUnmeasured_ = QString::fromStdString(split->unmeasured);
  }
  errorRevision_ = viewRevision_;
  mainErrorPct_ = main.pct;
  errorUnmeasured_ = QString::fromStdString(main.unmeasured);
  if (mainErrorPct_) {
    Q_EMIT errorComputed(*mainErrorPct_);
    // The error overlay shows the reference just computed: draw it (unless paused, where the
    // frozen frame must stay the one that was measured).
    if (sl::enumIs(shared_, "view.overlay", "error") && !paused_) requestFrame();
  } else {
    Q_EMIT errorUnmeasured(errorUnmeasured_);
  }
  updateOverlayWidget();
}

bool ViewportWidget::failedFrameUnmeasured() {
  if (frameFailure_.isEmpty()) return false;
  // A frame that failed is not measured: its image is the neutral frame, not the technique's.
  errorRevision_ = viewRevision_;
  mainErrorPct_.reset();
  errorUnmeasured_ = tr("the frame failed: %1").arg(frameFailure_);
  Q_EMIT errorUnmeasured(errorUnmeasured_);
  updateOverlayWidget();
  return true;
}

std::optional<double> ViewportWidget::computeErrorNow() {
  if (!ready_ || framesRendered_ == 0) return std::nullopt;
  // The error of the view as it is now: when the frame shown is older (or one is on its
  // way), a frame of it is drawn in the same job as the measurement.
  // The window goes on handling events while it waits (RenderService::call): the job reads
  // nothing the UI thread may change meanwhile, and what comes back is kept only for the view
  // it was measured for.
  std::shared_ptr<FrameOrder> order;
  if (framesInFlight_ > 0 || shownViewRevision_ != viewRevision_) order = makeOrder();
  const std::uint64_t revision = viewRevision_;
  const bool split = order ? order->split.has_value() : split_ && !splitImage_.isNull();
  auto out = std::make_shared<FrameOutcome>();
  SideError main;
  std::optional<SideError> right;
  bool measured = false;
  if (!service_->call(
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
  if (order) applyOutcome(out);
  if (revision != viewRevision_ || failedFrameUnmeasured() || !measured) return std::nullopt;
  applyError(revision, main, right);
  return errorIsCurrent() ? mainErrorPct_ : std::nullopt;
}

void ViewportWidget::computeErrorIfStill() {
  if (errorIsCurrent() || !ready_) return;
  // Still interacting, or the frame of this view not shown yet: try again later.
  if (dragButton_ != Qt::NoButton || !heldKeys_.empty() || framesInFlight_ > 0 ||
      shownViewRevision_ != viewRevision_) {
    errorTimer_.start(kErrorDelayMs);
    return;
  }
  if (failedFrameUnmeasured()) return;
  const std::uint64_t revision = viewRevision_;
  const bool split = split_ && !splitImage_.isNull();
  // A newer request replaces one not started (its view is older).
  service_->post(RenderTag::kError, [this, revision, split](RenderContext& c) {
    const SideError main = computeSideError(c, "main");
    std::optional<SideError> right;
    if (split) right = computeSideError(c, "split");
    QMetaObject::invokeMethod(
        this, [this, revision, main, right] { applyError(revision, main, right); },
        Qt::QueuedConnection);
  });
}

std::optional<std::string> ViewportWidget::reloadShaders() {
  if (!ready_) return std::string("the renderer is not running");
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

std::vector<FigureCell> ViewportWidget::figureCells(int dilatePx) {
  std::vector<FigureCell> cells;
  if (!ready_ || framesRendered_ == 0) return cells;
  auto label = [](const sl::ViewSide& side) {
    const std::string rest = side.nonDefaultParams();
    return side.techniqueId() + (rest.empty() ? "" : " " + rest);
  };
  // A full-size frame of the view as it is and its cells, in one job: a figure is never the
  // reduced (adaptive resolution) image, nor a frame drawn in between.
  fullSizeNext_ = true;
  const std::shared_ptr<FrameOrder> order = makeOrder();
  const std::string mainLabel = label(main_);
  const std::optional<std::string> splitLabel =
      order->split ? std::optional(label(*split_)) : std::nullopt;
  auto out = std::make_shared<FrameOutcome>();
  std::string problem;
  service_->call(
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
  applyOutcome(out);
  if (out->stopped) cells.clear();  // stopped (Esc): no figure
  if (!problem.empty())
    Q_EMIT renderProblem(QStringLiteral("export figure: %1").arg(QString::fromStdString(problem)));
  return cells;
}

std::optional<ViewportWidget::MemoryMatch> ViewportWidget::matchSplitMemory(std::string* error) {
  auto fail = [&](const std::string& why) -> std::optional<MemoryMatch> {
    if (error) *error = why;
    return std::nullopt;
  };
  if (!ready_ || !split_) return fail("the split view is off");
  if (framesRendered_ == 0 || !main_.hasFrame() || main_.stats().frameIndex == 0)
    return fail("no frame of the main technique yet");
  const sl::ParamDecl* decl = sl::memoryKnob(split_->params().decls());
  if (!decl)
    return fail("technique '" + splitTechniqueId_ +
                "' declares no parameter its memory grows with, so there is nothing to match");
  MemoryMatch match;
  match.key = decl->key;
  match.mainBytes = main_.stats().memory.bytes();
  const QSize size = deviceSize();
  const int halfW = size.width() - size.width() / 2;
  if (halfW < kMinDrawnPx || size.height() < kMinDrawnPx)
    return fail("the view is too small to measure");
  const std::shared_ptr<FrameOrder> order = makeOrder();
  if (!order->split) return fail("the view is too small to measure");
  MemoryMatchRun run;
  const sl::ParamDecl knob = *decl;
  const std::string splitTechnique = splitTechniqueId_;
  if (!service_->call(
          [&](RenderContext& c) {
            run = matchSplitMemoryOn(c, *order, knob, match.mainBytes, halfW, size.height());
          },
          tr("matching the split view's memory")))
    return fail("stopped before it started");
  if (!run.problem.empty()) return fail("split view: " + run.problem);
  // The window handled events while it waited: the split view may be another now.
  if (!split_ || splitTechniqueId_ != splitTechnique)
    return fail("the split view changed while its memory was matched");
  match.framesMeasured = run.evaluations;
  match.value = run.value;
  match.belowMinimum = run.belowMinimum;
  match.splitBytes = run.bytes;
  (void)split_->params().set(knob.key, double(run.value));
  splitParams_[knob.key] = split_->params().format(knob.key);
  requestFrame();
  return match;
}

QString ViewportWidget::liveErrorText() const {
  if (!continuous_) return {};
  const auto e = liveError();
  if (!e) return tr("error \u2014  \u00b7  tracing the reference\u2026");
  const QString age = QString::fromStdString(sl::describeReferenceAge(e->age));
  if (!e->unmeasured.isEmpty()) return tr("error n/a (%1)  \u00b7  %2").arg(e->unmeasured, age);
  const QString pct = QString::number(e->errorPct, 'f', e->errorPct < 1 ? 3 : 2);
  if (e->age.stale) return tr("error %1 %  \u00b7  %2  \u00b7  re-tracing").arg(pct, age);
  return tr("error %1 %  \u00b7  %2").arg(pct, age);
}

QString ViewportWidget::errorOverlayNote() const {
  return overlay_->errorNote;
}

bool ViewportWidget::readCurrentFrame(const std::function<void(sl::Renderer&)>& read) {
  if (!ready_) return false;
  // A frame of the view as it is, drawn in the same job when the one shown is older or one
  // is on its way (which the call stops): what is read is always a complete frame.
  std::shared_ptr<FrameOrder> order;
  if (framesInFlight_ > 0 || shownViewRevision_ != viewRevision_ || framesRendered_ == 0)
    order = makeOrder();
  auto out = std::make_shared<FrameOutcome>();
  const bool ran = service_->call([&](RenderContext& c) {
    if (order) renderOrder(c, *order, *out);
    sl::Renderer* r = c.existing("main");
    if (r && !r->stats().cancelled) read(*r);
  });
  if (order) applyOutcome(out);
  return ran;
}

}  // namespace sl::ui
