// The render thread's side of a view frame (see ViewFrame.h).
#include "service/ViewFrame.h"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "service/RenderService.h"
#include "algo/MemoryMatch.h"
#include "metrics/ErrorMetrics.h"

namespace sl::ui {

std::optional<std::string> applySide(sl::Renderer& r, const FrameOrder& order,
                                     const sl::SideRequest& side) {
  if (r.scene() != order.scene) r.setScene(order.scene);
  if (r.techniqueId() != side.techniqueId)
    if (auto e = r.setTechnique(side.techniqueId)) return e;
  sl::syncParams(r.params(), side.params);
  sl::syncParams(r.rendererParams(), order.shared);
  if (side.resetTemporal) r.resetTemporalState();
  if (r.requestedPublications() != side.publications) r.requestPublications(side.publications);
  r.setCamera(order.camera);
  r.setLight(order.light);
  return std::nullopt;
}

namespace {

QImage toImage(const sl::ImageRGBA8& color) {
  if (color.width == 0) return {};
  return QImage(color.pixels.data(), color.width, color.height, QImage::Format_RGBA8888).copy();
}

}  // namespace

void renderOrder(RenderContext& c, const FrameOrder& order, FrameOutcome& out) {
  // The frame's wall clock leaves out making a technique (shaders compiled on first use):
  // that is not what a frame of it costs.
  auto start = std::chrono::steady_clock::now();
  auto applyTimed = [&](sl::Renderer& r, const sl::SideRequest& side) {
    const auto t0 = std::chrono::steady_clock::now();
    auto problem = applySide(r, order, side);
    start += std::chrono::steady_clock::now() - t0;
    return problem;
  };
  out.id = order.id;
  out.viewRevision = order.viewRevision;
  out.divisor = order.divisor;
  out.fullSize = order.fullSize;
  out.hasSplit = order.split.has_value();
  sl::Renderer& main = c.renderer("main");
  if (order.clearOnly) {
    if (auto e = applySide(main, order, order.main)) out.mainProblem = *e;
    return;
  }
  if (order.split) {
    try {
      sl::Renderer& split = c.renderer("split");
      if (auto e = applyTimed(split, *order.split)) {
        out.splitProblem = "split view: " + *e;
      } else {
        split.setProgressiveBudget(0.0);  // compared at full size, never progressive
        if (auto problem = split.renderFrame(order.splitWidth, order.frameHeight, 0))
          out.splitProblem = "split view: " + *problem;
        if (split.stats().cancelled || c.stopFlag()) {
          out.stopped = true;
          return;
        }
        out.splitImage = toImage(split.readColor());
        out.splitStats = split.stats();
        out.splitPublication = split.publication();
        if (order.snapshotSplit && out.splitProblem.empty())
          out.splitSnapshot =
              std::make_shared<sl::Renderer::ReferenceSnapshot>(split.snapshotForReference());
      }
    } catch (const std::exception& e) {
      out.splitProblem = std::string("split view: ") + e.what();
    }
  }
  try {
    if (auto e = applyTimed(main, order.main)) {
      out.mainProblem = *e;
    } else {
      if (order.referenceMask)  // drawn by the error overlay while frames show that view
        main.setReferenceMask(order.referenceMask->trace.frameSignature,
                              order.referenceMask->trace.referenceMask,
                              order.referenceMask->trace.width, order.referenceMask->trace.height);
      main.setProgressiveBudget(order.progressiveBudgetMs);
      if (auto problem = main.renderFrame(order.frameWidth, order.frameHeight, 0))
        out.mainProblem = *problem;
    }
  } catch (const std::exception& e) {
    out.mainProblem = std::string("renderer: ") + e.what();
  }
  if (main.stats().cancelled) {
    out.stopped = true;
    return;
  }
  out.mainStats = main.stats();
  out.mainPublication = main.publication();
  out.glErrors = main.takeGlErrors();
  try {
    out.mainImage = toImage(main.readColor());
    if (order.probe) {
      out.probed = true;
      out.probe = main.probePixel(order.probe->x(), order.probe->y());
    }
    if (order.snapshotMain && out.mainProblem.empty() && out.mainStats.complete())
      out.mainSnapshot =
          std::make_shared<sl::Renderer::ReferenceSnapshot>(main.snapshotForReference());
  } catch (const std::exception& e) {
    out.mainProblem = std::string("renderer: ") + e.what();
  }
  out.wallMs = std::max(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count(),
      out.mainStats.totalMs);
}

MemoryMatchRun matchSplitMemoryOn(RenderContext& c, const FrameOrder& order,
                                  const sl::ParamDecl& knob, std::uint64_t mainBytes, int width,
                                  int height) {
  MemoryMatchRun run;
  sl::Renderer& split = c.renderer("split");
  if (auto e = applySide(split, order, *order.split)) {
    run.problem = *e;
    return run;
  }
  split.setProgressiveBudget(0.0);
  sl::ParamSet params = order.split->params;
  const sl::MemoryMatchResult m = sl::matchMemory(
      std::llround(knob.minValue), std::llround(knob.maxValue), std::llround(knob.step), mainBytes,
      [&](long long value, std::string& problem) -> std::optional<std::uint64_t> {
        if (auto e = params.set(knob.key, double(value))) {
          problem = *e;
          return std::nullopt;
        }
        sl::syncParams(split.params(), params);
        if (auto e = split.renderFrame(width, height, 0)) {
          problem = *e;
          return std::nullopt;
        }
        if (split.stats().cancelled || c.stopFlag().load()) {  // Esc: no value measured
          problem = "stopped";
          return std::nullopt;
        }
        return split.stats().memory.bytes();
      });
  split.resetTemporalState();
  run.value = m.value;
  run.bytes = m.bytes;
  run.belowMinimum = m.belowMinimum;
  run.evaluations = m.evaluations;
  if (!m.ok()) run.problem = m.problem;
  return run;
}

SideError computeSideError(RenderContext& c, const std::string& name) {
  SideError e;
  sl::Renderer* r = c.existing(name);
  if (!r) {
    e.problem = "no frame of the " + name + " view yet";
    return e;
  }
  try {
    const sl::ShadowErrorStats stats = r->computeError().stats;
    if (stats.covered > 0)
      e.pct = stats.errorPct;
    else
      e.unmeasured = "no covered pixel";
  } catch (const std::exception& ex) {
    e.problem = ex.what();
  }
  return e;
}

std::optional<sl::ReferenceJob> referenceJob(
    std::shared_ptr<sl::Renderer::ReferenceSnapshot> snapshot, std::uint64_t viewRevision,
    std::uint64_t frameNumber) {
  if (!snapshot || !snapshot->reference) return std::nullopt;
  sl::ReferenceJob job;
  job.viewRevision = viewRevision;
  job.frameNumber = frameNumber;
  job.trace = [snapshot](const std::atomic<bool>& cancelled) -> std::optional<sl::ReferenceTrace> {
    const int width = snapshot->frame.width, height = snapshot->frame.height;
    std::string signature = snapshot->frameSignature;
    auto result = sl::Renderer::traceReference(std::move(*snapshot), &cancelled);
    if (!result) return std::nullopt;
    sl::ReferenceTrace t;
    t.stats = result->stats;
    t.referenceMask = std::move(result->referenceMask);
    t.width = width;
    t.height = height;
    t.frameSignature = std::move(signature);
    return t;
  };
  return job;
}

FigureCell figureCellOf(RenderContext& c, const std::string& name, const std::string& label,
                        int dilatePx) {
  sl::Renderer& r = c.renderer(name);
  const sl::Renderer::ErrorResult e = r.computeError();
  FigureCell cell;
  cell.label = label;
  const sl::FrameStats& st = r.stats();
  char facts[160];
  const double mib = double(st.memory.bytes()) / double(1 << 20);
  if (e.stats.covered == 0)
    std::snprintf(facts, sizeof facts, "%.3g M texels (%.3g MiB), error n/a, %.1f ms",
                  double(st.memory.texels()) / 1e6, mib, st.totalMs);
  else
    std::snprintf(facts, sizeof facts, "%.3g M texels (%.3g MiB), error %.3f %%, %.1f ms",
                  double(st.memory.texels()) / 1e6, mib, e.stats.errorPct, st.totalMs);
  cell.facts = facts;
  if (const std::uint64_t debug = st.memory.debugViewBytes()) {
    char views[64];
    std::snprintf(views, sizeof views, "; debug views %.3g MiB", double(debug) / double(1 << 20));
    cell.facts += views;
  }
  cell.shaded = e.frame.color;
  cell.error = sl::makeErrorImage(e.frame.color, e.frame.hardMask, e.referenceMask, dilatePx);
  return cell;
}

}  // namespace sl::ui
