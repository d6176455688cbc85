// The renderer's state behind Renderer.h's GL-free interface: the frame's targets, the
// programs, the technique and its parameters, the publication and the progressive and
// cancelled frames' bookkeeping. Internal to renderer/core (Renderer*.cpp, FrameSteps.cpp,
// FrameResolve.cpp).
#pragma once

#include <atomic>
#include <initializer_list>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "core/Renderer.h"
#include "core/SceneGpu.h"
#include "core/Technique.h"
#include "gl/Gl.h"
#include "metrics/ShadowReference.h"

namespace sl {

/// One camera's render targets: G-buffer, resolve outputs, composite.
struct Targets {
  int width = 0, height = 0;
  gl::Texture position, normal, albedo, depth, hard, filtered, aliasing, texel, mapIndex, color;
  gl::Texture reference;  // R8UI reference mask of the last computeError() (error overlay)
  /// The last COMPLETE frame's hard mask, aliasing m and map index (copied when a frame
  /// commits): what the next frame reads as the previous one (FrameContext::previous, the mask
  /// change), so that a stopped frame's partial resolve is never read. `committed`: they hold
  /// a complete frame's at this size.
  gl::Texture prevHard, prevAliasing, prevMapIndex;
  bool committed = false;
  gl::Framebuffer gbuffer, resolve, composite;
};

struct RendererState {
  gl::ShaderLibrary shaders{gl::ShaderLibrary::defaultRoot()};
  std::vector<TechniqueEntry> extraTechniques;  ///< RendererOptions::extraTechniques
  std::unique_ptr<gl::GpuTimer> timer;
  std::shared_ptr<const Scene> scene;
  std::unique_ptr<SceneGpu> sceneGpu;
  std::string techniqueId;
  std::unique_ptr<Technique> technique;
  std::map<std::string, ParamSet, std::less<>> techniqueParams;
  ParamSet rendererParams{rendererParamDecls()};
  Camera camera;
  Light light;
  Renderer::FrameSizeLimit maxFrame;  ///< the context's limits, queried once
  FrameStats stats;
  Publication publication;
  std::set<std::string> requested;  ///< publication patterns (empty: publish nothing)
  std::uint64_t frameIndex = 0;
  gl::Program gbufferProgram, compositeProgram;
  gl::Program aliasingStatsProgram;  ///< common/aliasing_stats.comp ("aliasing.*")
  gl::Buffer aliasingStats;          ///< its counters and histogram (SL_ALIASING_BINS)
  gl::Program maskChangeProgram;     ///< common/mask_change.comp (changed overlay, "mask.*")
  gl::Buffer maskChange;             ///< its two counters: compared, changed
  std::map<std::string, gl::Program> resolvePrograms;  // per lookup shader
  gl::VertexArray emptyVao;
  Targets targets;
  std::vector<std::string> glErrors;
  mutable std::mutex errorMutex;
  mutable std::shared_ptr<ShadowReference> reference;
  mutable const Scene* referenceScene = nullptr;
  /// What the error overlay's reference mask was computed for (frame signature).
  std::string referenceSignature;
  std::string frameSignature;
  /// Progressive resolve (setProgressiveBudget): the budget per call (0: off), the view whose
  /// units the main targets hold, the next unit and their number, whether a whole pass of
  /// that view has finished, and this call's progress (for FrameStats).
  double progressiveBudgetMs = 0.0;
  std::string progressSignature;
  int progressNext = 0, progressTotal = 0;
  bool progressShownComplete = false;
  std::optional<FrameStats::Progress> frameProgress;
  /// The host's stop flag (Renderer::setCancelFlag; null: never stopped) and whether it
  /// stopped the last frame (readback and computeError then refuse to measure it).
  const std::atomic<bool>* cancelFlag = nullptr;
  bool lastFrameCancelled = false;

  const gl::Program& resolveProgramFor(const std::string& lookup) {
    auto it = resolvePrograms.find(lookup);
    if (it != resolvePrograms.end()) return it->second;
    gl::ProgramDesc d{
        "common/resolve (" + lookup + ")",
        {{GL_VERTEX_SHADER, "common/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "common/resolve.frag"}},
        {{"@lookup", lookup}},
        {}};
    return resolvePrograms.emplace(lookup, gl::Program(shaders, d)).first->second;
  }

  Targets outsideTargets;  ///< the outside view's G-buffer, resolve and composite (view.outside)
  gl::Program outlineProgram;  ///< common/outline.vert/.frag: the outside view's lines
  bool lastFrameOutside = false;

  void ensureTargets(int w, int h) {
    if (targets.width == w && targets.height == h) return;
    targets = makeTargets(w, h);
  }
  void ensureOutsideTargets(int w, int h) {
    if (outsideTargets.width == w && outsideTargets.height == h) return;
    outsideTargets = makeTargets(w, h);
  }
  static Targets makeTargets(int w, int h) {
    Targets t;
    t.width = w;
    t.height = h;
    t.position = gl::Texture::create2D(GL_RGBA32F, w, h);
    t.normal = gl::Texture::create2D(GL_RGBA32F, w, h);
    t.albedo = gl::Texture::create2D(GL_RGBA8, w, h);
    t.depth = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, w, h);
    t.hard = gl::Texture::create2D(GL_R8UI, w, h);
    t.filtered = gl::Texture::create2D(GL_R8, w, h);
    t.aliasing = gl::Texture::create2D(GL_R32F, w, h);
    t.texel = gl::Texture::create2D(GL_RG32F, w, h);
    t.mapIndex = gl::Texture::create2D(GL_R8UI, w, h);
    t.reference = gl::Texture::create2D(GL_R8UI, w, h);
    t.prevHard = gl::Texture::create2D(GL_R8UI, w, h);
    t.prevAliasing = gl::Texture::create2D(GL_R32F, w, h);
    t.prevMapIndex = gl::Texture::create2D(GL_R8UI, w, h);
    t.color = gl::Texture::create2D(GL_RGBA8, w, h);
    t.gbuffer = framebufferOf({&t.position, &t.normal, &t.albedo}, &t.depth, "G-buffer");
    t.resolve = framebufferOf({&t.hard, &t.filtered, &t.aliasing, &t.texel, &t.mapIndex}, nullptr,
                              "resolve");
    t.composite = framebufferOf({&t.color}, nullptr, "composite");
    return t;
  }
  /// A framebuffer drawing into `colours` (colour attachments 0, 1, ...) with `depth` when
  /// given, checked complete (`what` names it in the error).
  static gl::Framebuffer framebufferOf(std::initializer_list<const gl::Texture*> colours,
                                       const gl::Texture* depth, const std::string& what) {
    gl::Framebuffer fb = gl::Framebuffer::create();
    GLenum attachment = GL_COLOR_ATTACHMENT0;
    for (const gl::Texture* colour : colours) fb.attach(attachment++, *colour);
    if (depth) fb.attach(GL_DEPTH_ATTACHMENT, *depth);
    fb.setDrawBuffers(int(colours.size()));
    fb.checkComplete(what);
    return fb;
  }
};

/// The built-in entry or the renderer's extra entry called `id`, or null.
const TechniqueEntry* findEntry(const RendererState& s, std::string_view id);
/// The parameters of technique `id`, made from its declarations on first use.
ParamSet& paramsFor(RendererState& s, std::string_view id);

/// Whether the host's stop flag (Renderer::setCancelFlag) is set.
inline bool cancelRequested(const RendererState& s) {
  return s.cancelFlag && s.cancelFlag->load(std::memory_order_relaxed);
}

}  // namespace sl
