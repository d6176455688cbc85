// The resolve of a frame and its statistics (FrameSteps.h): the lookup or deferred resolve,
// progressive or in one call; the mask change and the aliasing histogram on the GPU; the
// renderer's own published numbers; the frame's FrameStats.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <mutex>
#include <span>
#include <stdexcept>
#include <utility>

#include "common/shared_constants.h"
#include "core/LightBinding.h"
#include "core/ParamBinding.h"
#include "core/SceneGpu.h"
#include "core/Technique.h"
#include "algo/metrics/BenchStats.h"
#include "gl/Gl.h"
#include "metrics/ShadowReference.h"
#include "core/FrameSteps.h"

namespace sl {

void ResolveTargets::bindForCompute() const {
  glBindTextureUnit(SL_UNIT_G_POSITION, gbuffer.position.id());
  glBindTextureUnit(SL_UNIT_G_NORMAL, gbuffer.normal.id());
  glBindImageTexture(SL_IMAGE_RESOLVE_HARD, outputs.hard.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                     GL_R8UI);
  glBindImageTexture(SL_IMAGE_RESOLVE_FILTERED, outputs.filtered.id(), 0, GL_FALSE, 0,
                     GL_WRITE_ONLY, GL_R8);
  glBindImageTexture(SL_IMAGE_RESOLVE_ALIASING, outputs.aliasing.id(), 0, GL_FALSE, 0,
                     GL_WRITE_ONLY, GL_R32F);
  glBindImageTexture(SL_IMAGE_RESOLVE_TEXEL, outputs.texel.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                     GL_RG32F);
  glBindImageTexture(SL_IMAGE_RESOLVE_MAP, outputs.mapIndex.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                     GL_R8UI);
}

namespace frame {
namespace {

/// A GPU reduction of the aliasing target (common/aliasing_stats.comp): a histogram of log2 m,
/// the count and the exact maximum, read back (4 KiB, counted in readbackBytes) instead of
/// the whole m image.
void publishAliasingStats(RendererState& s) {
  constexpr GLsizeiptr bytes = GLsizeiptr(sizeof(std::uint32_t) * (4 + SL_ALIASING_BINS));
  const std::uint32_t zero = 0;
  glClearNamedBufferData(s.aliasingStats.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  s.aliasingStatsProgram.use();
  glBindTextureUnit(SL_UNIT_ALIASING, s.targets.aliasing.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_BUFFER_ALIASING_STATS, s.aliasingStats.id());
  const auto groups = [](int n) { return GLuint((n + SL_ALIASING_GROUP - 1) / SL_ALIASING_GROUP); };
  glDispatchCompute(groups(s.targets.width), groups(s.targets.height), 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<std::uint32_t> data(4 + SL_ALIASING_BINS);
  glGetNamedBufferSubData(s.aliasingStats.id(), 0, bytes, data.data());
  s.publication.readbackBytes += std::uint64_t(bytes);
  Log2Histogram h;
  for (std::size_t b = 0; b < h.counts.size(); ++b) h.counts[b] = data[4 + b];
  float maxM = 0.0f;
  std::memcpy(&maxM, &data[1], sizeof maxM);
  Publication& pub = s.publication;
  auto number = [&](const std::string& key, double v) {
    if (pub.wants(key)) pub.numbers[key] = v;
  };
  number("aliasing.pixels", data[0]);
  number("aliasing.bin_octaves", h.binOctaves());
  // No covered pixel with a shadow-map coordinate: m is not measured, so its statistics are
  // not published (absent, "n/a"), never 0.
  if (data[0] == 0) return;
  number("aliasing.max", maxM);
  number("aliasing.p50", histogramPercentile(h, 50.0, maxM));
  number("aliasing.p95", histogramPercentile(h, 95.0, maxM));
}

/// The pixels of `t`'s hard mask that differ from its copy of the previous frame's
/// (common/mask_change.comp; CPU mirror compareConsecutiveMasks): two counters read back.
FrameStats::MaskChangeCount countMaskChange(RendererState& s, const Targets& t) {
  const std::uint32_t zero = 0;
  glClearNamedBufferData(s.maskChange.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  s.maskChangeProgram.use();
  glBindTextureUnit(SL_UNIT_HARD, t.hard.id());
  glBindTextureUnit(SL_UNIT_PREV_HARD, t.prevHard.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_BUFFER_MASK_CHANGE, s.maskChange.id());
  const auto groups = [](int n) {
    return GLuint((n + SL_MASK_CHANGE_GROUP - 1) / SL_MASK_CHANGE_GROUP);
  };
  glDispatchCompute(groups(t.width), groups(t.height), 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::uint32_t counts[2] = {0, 0};
  glGetNamedBufferSubData(s.maskChange.id(), 0, sizeof counts, counts);
  return {counts[0], counts[1]};
}

/// The main camera's progressive resolve (ResolveProgress): where it goes on, and afterwards
/// what the renderer keeps of it between calls and shows in FrameStats::progress.
void beginProgress(RendererState& s, ResolveProgress& progress) {
  progress.budgetMs = s.progressiveBudgetMs;
  progress.resume = s.progressSignature == s.frameSignature && s.progressTotal > 0;
  progress.next = progress.resume && s.progressNext < s.progressTotal ? s.progressNext : 0;
  if (!progress.resume) s.progressShownComplete = false;
  s.progressSignature.clear();  // until this call's units are done
}
void endProgress(RendererState& s, const ResolveProgress& progress) {
  if (progress.total <= 0) return;
  s.progressSignature = s.frameSignature;
  s.progressNext = progress.next;
  s.progressTotal = progress.total;
  const bool done = progress.next >= progress.total;
  if (done) s.progressShownComplete = true;
  s.frameProgress = FrameStats::Progress{.done = std::min(progress.next, progress.total),
                                         .total = progress.total,
                                         .shownComplete = s.progressShownComplete,
                                         .completedNow = done,
                                         .spentMs = progress.spentMs,
                                         .unitsPerTile = std::max(1, progress.unitsPerTile)};
}

}  // namespace

void publishFrameNumbers(RendererState& s, int height, float aspect) {
  Publication& pub = s.publication;
  auto number = [&](const std::string& key, double v) {
    if (pub.wants(key)) pub.numbers[key] = v;
  };
  const Camera& c = s.camera;
  number("camera.near_m", c.nearM);
  number("camera.far_m", c.farM);
  number("camera.fov_deg", c.fovYDeg);
  number("camera.aspect", aspect);
  number("camera.height_px", height);
  const glm::vec3 f = c.forward();
  const glm::vec3 up = glm::normalize(glm::cross(glm::cross(f, c.up), f));
  const char* axes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    number(std::string("camera.forward.") + axes[i], f[i]);
    number(std::string("camera.up.") + axes[i], up[i]);
  }
  number("light.type", double(int(s.light.type)));
  if (s.light.type == LightType::Directional) {  // a spot or point light has no direction
    number("light.azimuth_deg", s.light.azimuthDeg);
    number("light.elevation_deg", s.light.elevationDeg);
  }
  const ParamSet& params = paramsFor(s, s.techniqueId);
  for (const ParamDecl& d : params.decls()) number("param." + d.key, params.get(d.key));
}

bool wantsAliasingStats(const Publication& pub) {
  for (const char* k :
       {"aliasing.p50", "aliasing.p95", "aliasing.max", "aliasing.pixels", "aliasing.bin_octaves"})
    if (pub.wants(k)) return true;
  return false;
}

bool wantsMaskChange(RendererState& s, bool publishing) {
  return s.rendererParams.getInt("view.overlay") == SL_OVERLAY_CHANGED ||
         (publishing && (s.publication.wants("mask.changed_pixels") ||
                         s.publication.wants("mask.compared_pixels")));
}

void resolveStep(RendererState& s, Frame& f) {
  const CameraPass& c = *f.camera;
  Targets& t = c.targets;
  const ParamSet& params = paramsFor(s, s.techniqueId);
  glBindFramebuffer(GL_FRAMEBUFFER, t.resolve.id());
  glViewport(0, 0, t.width, t.height);
  glDisable(GL_DEPTH_TEST);
  glBindTextureUnit(SL_UNIT_G_POSITION, t.position.id());
  glBindTextureUnit(SL_UNIT_G_NORMAL, t.normal.id());
  if (s.technique->resolveMode() == ResolveMode::Lookup) {
    const gl::Program& resolve = s.resolveProgramFor(s.technique->lookupShader());
    resolve.use();
    bindLight(resolve, s.light);
    bindParams(resolve, params);
    s.technique->bindLookup(resolve, SL_UNIT_LOOKUP_FIRST);
    glBindVertexArray(s.emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
  } else {
    // A progressive resolve continues the view the targets hold (the main camera only).
    ResolveProgress progress;
    const bool progressive = c.mainCamera && s.progressiveBudgetMs > 0.0;
    if (progressive) beginProgress(s, progress);
    // Map 0 for every pixel unless the technique writes its selection.
    const GLuint zero = 0;
    if (!progress.resume)
      glClearTexImage(t.mapIndex.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    const ResolveTargets targets{
        .width = t.width,
        .height = t.height,
        .gbuffer = {.position = t.position, .normal = t.normal},
        .outputs = {.hard = t.hard,
                    .filtered = t.filtered,
                    .aliasing = t.aliasing,
                    .texel = t.texel,
                    .mapIndex = t.mapIndex},
        .framebuffer = t.resolve.id(),
        .light = s.light,
        .sceneGpu = s.sceneGpu.get(),
        .timer = c.mainCamera ? s.timer.get() : nullptr,
        .mainCamera = c.mainCamera,
        .progress = progressive ? &progress : nullptr,
        .cancel = s.cancelFlag,
        .cameraView = c.view,
        .cameraProj = c.proj,
    };
    s.technique->resolveDeferred(targets, params);
    if (progressive) endProgress(s, progress);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT);
  }
}

void maskChangeStep(RendererState& s, Frame& f) {
  const Targets& t = f.mainCamera.targets;
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  const FrameStats::MaskChangeCount count = countMaskChange(s, t);
  f.results.maskChange = count;
  Publication& pub = s.publication;
  if (!f.setup.publishing) return;
  const bool changed = pub.wants("mask.changed_pixels"),
             compared = pub.wants("mask.compared_pixels");
  if (changed || compared) pub.readbackBytes += 2 * sizeof(std::uint32_t);  // the two counters
  if (changed) pub.numbers["mask.changed_pixels"] = double(count.changed);
  if (compared) pub.numbers["mask.compared_pixels"] = double(count.compared);
}

void aliasingStatsStep(RendererState& s, Frame&) {
  publishAliasingStats(s);
}

void fillStats(RendererState& s, Frame& f, const FrameStep* stoppedBefore) {
  s.stats = FrameStats{};
  s.stats.frameIndex = s.frameIndex;
  s.stats.width = f.setup.width;
  s.stats.height = f.setup.height;
  s.stats.cancelled = stoppedBefore != nullptr;
  if (stoppedBefore) s.stats.stoppedBefore = stoppedBefore->name;
  s.stats.passes = s.timer->endFrame();
  s.stats.passSequence = s.timer->sequence();
  s.stats.passOrder = s.timer->passOrder();
  if (f.setup.publishing) {  // per-tile times (TechniqueInfo::tileTiming) from the same results
    const TechniqueEntry* entry = findEntry(s, s.techniqueId);
    const TechniqueInfo* info = entry ? &entry->info : nullptr;
    if (info && info->tileTiming && s.publication.wants(info->tileTiming->key))
      s.publication.curves[info->tileTiming->key] = tileTimingCurve(
          s.stats.passSequence, info->tileTiming->depthPass, info->tileTiming->applyPass);
  }
  s.stats.timingMethod = s.timer->methodName();
  s.stats.timingFramesLate = s.timer->framesLate();
  s.stats.memory = s.technique->memory();
  s.stats.publicationBytes = f.setup.publishing ? s.publication.readbackBytes : 0;
  for (const PassTiming& p : s.stats.passes) s.stats.totalMs += p.ms;
  s.stats.outlines = std::move(f.results.outlines);
  s.stats.outsideCamera = f.results.outsideCamera;
  s.stats.maskChange = f.results.maskChange;
  s.stats.progress = s.frameProgress;
}

}  // namespace frame
}  // namespace sl
