// The flow of one frame (docs/ARCHITECTURE.md), declared once as a list of steps
// (kFrameSteps): G-buffer from the camera -> the technique's shadow passes -> resolve (hard
// mask + filtered visibility) -> mask change -> composite -> outside view -> blit to the
// host's framebuffer. Only this file and the techniques call OpenGL.
#include "core/Renderer.h"

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

namespace sl {

namespace {
/// view.overlay's names, value i at index i (SL_OVERLAY_*, composite.frag).
std::vector<std::string> overlayNames() {
  std::vector<std::string> names(SL_OVERLAY_PAGES + 1);
  names[SL_OVERLAY_NONE] = "none";
  names[SL_OVERLAY_ERROR] = "error";
  names[SL_OVERLAY_ALIASING] = "aliasing";
  names[SL_OVERLAY_GRID] = "warp-grid";
  names[SL_OVERLAY_PARTITION] = "partition";
  names[SL_OVERLAY_CHANGED] = "changed";
  names[SL_OVERLAY_PAGES] = "pages";
  return names;
}
}  // namespace

std::vector<ParamDecl> rendererParamDecls() {
  return {
      {.key = "shading.ambient",
       .label = "Ambient",
       .group = "Shading",
       .type = ParamType::Float,
       .defaultValue = 0.35,
       .minValue = 0.0,
       .maxValue = 1.0,
       .step = 0.05,
       .help = "Sky light added to every surface, so shadowed areas stay readable.",
       .uniform = "u_ambient"},
      {.key = "view.overlay",
       .label = "Overlay",
       .group = "View",
       .type = ParamType::Enum,
       .defaultValue = SL_OVERLAY_NONE,
       .minValue = SL_OVERLAY_NONE,
       .maxValue = SL_OVERLAY_PAGES,
       .step = 1,
       .enumNames = overlayNames(),
       .help =
           "Drawn over the scene: shadow error against the exact reference (false-lit magenta, "
           "false-shadowed cyan; needs a computed reference for this view), perspective aliasing "
           "m as a heat map (blue: m<1 oversampled, white: m=1, red: m>1 undersampled; log2 scale "
           "-4..4; error and m in the main view only, not in the outside view), or the shadow-map "
           "texel grid (every 1/" +
           std::to_string(SL_GRID_LINES_PER_MAP) +
           " of the selected map) projected onto the scene, or the partition: each pixel coloured "
           "by the index of the map it selected (cascade, face, layer; colours repeat every " +
           std::to_string(SL_PARTITION_COLOURS) +
           "): 0 red, 1 green, 2 blue, 3 yellow, 4 magenta, 5 cyan, 6 orange, 7 violet; or "
           "changed: the pixels whose hard shadow test flipped (lit <-> shadowed) since the "
           "previous frame in vivid yellow (flicker, vibration; main view only); or pages: the "
           "borders of the page each pixel's lookup used, in orange over the scene in grey (paged "
           "maps: rmsm, asm; the partition overlay colours each pixel by the level it uses).",
       .uniform = "u_overlay"},
      {.key = "view.outside",
       .label = "Outside view",
       .group = "View",
       .type = ParamType::Bool,
       .defaultValue = 0,
       .minValue = 0,
       .maxValue = 1,
       .help = "Show the scene from a third camera, placed so that the view frustum and the "
               "light's frusta are visible, with lines: the camera's frustum (white, near to the "
               "deepest point of the scene bounds), split planes (grey), each shadow map's light "
               "frustum (its partition colour) and a warped map's frustum (cyan, its sides "
               "extended to the warp's centre of projection). The metrics still measure the "
               "main camera's image."},
      {.key = "view.adaptive",
       .label = "Adaptive resolution",
       .group = "View",
       .type = ParamType::Bool,
       .defaultValue = 0,
       .minValue = 0,
       .maxValue = 1,
       .help = "GUI only, off by default: when a frame takes longer than the frame budget, "
               "the interactive view renders at half its size (stretched to fit; never less) "
               "and says so in its corner; the first fast frame returns to full size, and a "
               "still view is redrawn at full size. Never in presenter mode, the split view, "
               "exports, grabs or a window that opened a lesson (its pictures and numbers are "
               "full-size frames); the command line always renders at the requested size."},
      {.key = "view.adaptive.budget_ms",
       .label = "Frame budget (ms)",
       .group = "View",
       .type = ParamType::Int,
       .defaultValue = 250,
       .minValue = 20,
       .maxValue = 10000,
       .step = 10,
       .help = "GUI only: a frame slower than this lowers the view's internal resolution "
               "(view.adaptive); continuous rendering spends at most half of it on a "
               "progressive technique's tiles per frame, so the window never waits on one."},
      {.key = "view.outside.azimuth_deg",
       .label = "Outside azimuth",
       .group = "View",
       .type = ParamType::Float,
       .defaultValue = 60.0,
       .minValue = -180.0,
       .maxValue = 180.0,
       .step = 5.0,
       .help = "Direction of the outside view's camera around the vertical, degrees: 0 behind "
               "the main camera, 90 from its right (dragging in the outside view changes it)."},
      {.key = "view.outside.elevation_deg",
       .label = "Outside elevation",
       .group = "View",
       .type = ParamType::Float,
       .defaultValue = 35.0,
       .minValue = -80.0,
       .maxValue = 85.0,
       .step = 5.0,
       .help = "Height of the outside view's camera above the horizon, degrees."},
      {.key = "view.outside.zoom",
       .label = "Outside zoom",
       .group = "View",
       .type = ParamType::Float,
       .defaultValue = 1.0,
       .minValue = 0.001,
       .maxValue = 1.0,
       .step = 0.01,
       .help = "1 frames every line; a smaller value frames that share of the view, centred "
               "near the main camera's view axis that share of the way in (0.05: the first "
               "twentieth of a kilometre-deep frustum). The mouse wheel in the outside view "
               "changes it."},
  };
}

namespace {

void GLAPIENTRY debugCallback(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei,
                              const GLchar* message, const void* user);

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

}  // namespace

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
    t.gbuffer = gl::Framebuffer::create();
    t.gbuffer.attach(GL_COLOR_ATTACHMENT0, t.position);
    t.gbuffer.attach(GL_COLOR_ATTACHMENT1, t.normal);
    t.gbuffer.attach(GL_COLOR_ATTACHMENT2, t.albedo);
    t.gbuffer.attach(GL_DEPTH_ATTACHMENT, t.depth);
    t.gbuffer.setDrawBuffers(3);
    t.gbuffer.checkComplete("G-buffer");
    t.resolve = gl::Framebuffer::create();
    t.resolve.attach(GL_COLOR_ATTACHMENT0, t.hard);
    t.resolve.attach(GL_COLOR_ATTACHMENT1, t.filtered);
    t.resolve.attach(GL_COLOR_ATTACHMENT2, t.aliasing);
    t.resolve.attach(GL_COLOR_ATTACHMENT3, t.texel);
    t.resolve.attach(GL_COLOR_ATTACHMENT4, t.mapIndex);
    t.resolve.setDrawBuffers(5);
    t.resolve.checkComplete("resolve");
    t.composite = gl::Framebuffer::create();
    t.composite.attach(GL_COLOR_ATTACHMENT0, t.color);
    t.composite.setDrawBuffers(1);
    t.composite.checkComplete("composite");
    return t;
  }
};

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

namespace {

void GLAPIENTRY debugCallback(GLenum, GLenum type, GLuint, GLenum severity, GLsizei,
                              const GLchar* message, const void* user) {
  if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
  auto* s = static_cast<RendererState*>(const_cast<void*>(user));
  std::lock_guard lock(s->errorMutex);
  if (s->glErrors.size() < 64) s->glErrors.emplace_back(message);
}

/// The built-in entry or the renderer's extra entry called `id`, or null.
const TechniqueEntry* findEntry(const RendererState& s, std::string_view id) {
  for (const TechniqueEntry& e : techniqueRegistry())
    if (e.info.id == id) return &e;
  for (const TechniqueEntry& e : s.extraTechniques)
    if (e.info.id == id) return &e;
  return nullptr;
}

ParamSet& paramsFor(RendererState& s, std::string_view id) {
  auto it = s.techniqueParams.find(id);
  if (it != s.techniqueParams.end()) return it->second;
  const TechniqueEntry* entry = findEntry(s, id);
  if (!entry) throw std::out_of_range("unknown technique '" + std::string(id) + "'");
  return s.techniqueParams.emplace(std::string(id), ParamSet(entry->info.params)).first->second;
}

}  // namespace

const std::vector<TechniqueInfo>& Renderer::techniques() {
  static const std::vector<TechniqueInfo> list = [] {
    std::vector<TechniqueInfo> out;
    for (const TechniqueEntry& e : techniqueRegistry()) out.push_back(e.info);
    return out;
  }();
  return list;
}

const TechniqueInfo* Renderer::findTechnique(std::string_view id) {
  for (const TechniqueInfo& t : techniques())
    if (t.id == id) return &t;
  return nullptr;
}

std::optional<std::string> checkLightSupport(const TechniqueInfo& info, LightType type) {
  for (LightType t : info.lights)
    if (t == type) return std::nullopt;
  return "technique '" + info.id + "' supports: " + lightTypeList(info.lights) + "; the light is " +
         "a " + std::string(lightTypeName(type)) + " light";
}

std::optional<std::string> checkTechniqueParams(const TechniqueInfo& info, const ParamSet& params) {
  return info.checkParams ? info.checkParams(params) : std::nullopt;
}

Renderer::Renderer(const RendererOptions& options) : s_(std::make_unique<RendererState>()) {
  if (epoxy_gl_version() < 45 || !epoxy_is_desktop_gl())
    throw std::runtime_error("ShadowLab needs a desktop OpenGL 4.5 core context; got " +
                             std::string(reinterpret_cast<const char*>(glGetString(GL_VERSION))));
  GLint flags = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &flags);
  if (!(flags & GL_CONTEXT_CORE_PROFILE_BIT))
    throw std::runtime_error(
        "ShadowLab needs a core-profile OpenGL 4.5 context (got "
        "compatibility profile)");
  if (!options.shaderDir.empty()) s_->shaders = gl::ShaderLibrary(options.shaderDir);
  s_->extraTechniques = options.extraTechniques;
  for (const TechniqueEntry& e : s_->extraTechniques)
    if (Renderer::findTechnique(e.info.id) || !e.create)
      throw std::logic_error("extra technique '" + e.info.id +
                             "': the id is taken by a built-in technique, or it has no create");
  if (options.debugOutput) {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(debugCallback, s_.get());
  }
  s_->maxFrame = maxFrameSize();
  s_->timer = std::make_unique<gl::GpuTimer>(options.timing);
  s_->gbufferProgram = gl::Program(s_->shaders, {"common/gbuffer",
                                                 {{GL_VERTEX_SHADER, "common/gbuffer.vert"},
                                                  {GL_FRAGMENT_SHADER, "common/gbuffer.frag"}},
                                                 {},
                                                 {}});
  s_->compositeProgram = gl::Program(s_->shaders, {"common/composite",
                                                   {{GL_VERTEX_SHADER, "common/fullscreen.vert"},
                                                    {GL_FRAGMENT_SHADER, "common/composite.frag"}},
                                                   {},
                                                   {}});
  s_->aliasingStatsProgram = gl::Program(
      s_->shaders,
      {"common/aliasing_stats", {{GL_COMPUTE_SHADER, "common/aliasing_stats.comp"}}, {}, {}});
  // 4 KiB the renderer owns from the start (not a technique's memory()).
  s_->aliasingStats = gl::Buffer::create(GLsizeiptr(sizeof(std::uint32_t) * (4 + SL_ALIASING_BINS)),
                                         nullptr, GL_DYNAMIC_STORAGE_BIT);
  s_->maskChangeProgram =
      gl::Program(s_->shaders,
                  {"common/mask_change", {{GL_COMPUTE_SHADER, "common/mask_change.comp"}}, {}, {}});
  s_->maskChange =
      gl::Buffer::create(GLsizeiptr(2 * sizeof(std::uint32_t)), nullptr, GL_DYNAMIC_STORAGE_BIT);
  {
    const gl::Program* own[] = {&s_->compositeProgram};
    const std::vector<ParamDecl> decls = rendererParamDecls();
    if (auto err = checkParamUniforms(decls, own)) throw std::logic_error(*err);
  }
  s_->outlineProgram = gl::Program(s_->shaders, {"common/outline",
                                                 {{GL_VERTEX_SHADER, "common/outline.vert"},
                                                  {GL_FRAGMENT_SHADER, "common/outline.frag"}},
                                                 {},
                                                 {}});
  s_->emptyVao = gl::createVertexArray();
  if (auto err = setTechnique("uniform")) throw std::runtime_error(*err);
}

Renderer::~Renderer() {
  // Several renderers may share a context: only clear the callback if it is still ours.
  if (!s_ || epoxy_gl_version() < 43) return;
  void* user = nullptr;
  glGetPointerv(GL_DEBUG_CALLBACK_USER_PARAM, &user);
  if (user == s_.get()) glDebugMessageCallback(nullptr, nullptr);
}

Renderer::GlStrings Renderer::glStrings() const {
  auto str = [](GLenum e) {
    const char* p = reinterpret_cast<const char*>(glGetString(e));
    return std::string(p ? p : "?");
  };
  return {str(GL_VENDOR), str(GL_RENDERER), str(GL_VERSION)};
}

std::string Renderer::glDescription() const {
  const GlStrings gl = glStrings();
  return gl.renderer + " | " + gl.version;
}

Renderer::FrameSizeLimit Renderer::maxFrameSize() {
  FrameSizeLimit lim{1 << 30, 1 << 30, "", ""};
  auto apply = [](GLenum e, const char* name, int& side, std::string& limit) {
    GLint v = 0;
    glGetIntegerv(e, &v);
    if (v > 0 && v < side) side = v, limit = name;
  };
  apply(GL_MAX_TEXTURE_SIZE, "GL_MAX_TEXTURE_SIZE", lim.width, lim.widthLimit);
  apply(GL_MAX_TEXTURE_SIZE, "GL_MAX_TEXTURE_SIZE", lim.height, lim.heightLimit);
  apply(GL_MAX_RENDERBUFFER_SIZE, "GL_MAX_RENDERBUFFER_SIZE", lim.width, lim.widthLimit);
  apply(GL_MAX_RENDERBUFFER_SIZE, "GL_MAX_RENDERBUFFER_SIZE", lim.height, lim.heightLimit);
  apply(GL_MAX_FRAMEBUFFER_WIDTH, "GL_MAX_FRAMEBUFFER_WIDTH", lim.width, lim.widthLimit);
  apply(GL_MAX_FRAMEBUFFER_HEIGHT, "GL_MAX_FRAMEBUFFER_HEIGHT", lim.height, lim.heightLimit);
  return lim;
}

std::optional<std::string> Renderer::checkFrameSize(int width, int height) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  const FrameSizeLimit lim = maxFrameSize();
  if (width > lim.width)
    return size + " is wider than this OpenGL implementation renders (" + lim.widthLimit + " " +
           std::to_string(lim.width) + ")";
  if (height > lim.height)
    return size + " is taller than this OpenGL implementation renders (" + lim.heightLimit + " " +
           std::to_string(lim.height) + ")";
  // Within the constants but maybe not allocatable (llvmpipe caps one texture's bytes): ask.
  glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
  GLint proxyWidth = 0;
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &proxyWidth);
  if (proxyWidth == 0)
    return size + " is larger than this OpenGL implementation allocates (a " + size +
           " RGBA32F G-buffer target is refused by GL_PROXY_TEXTURE_2D)";
  return std::nullopt;
}

void Renderer::setScene(std::shared_ptr<const Scene> scene) {
  s_->sceneGpu = scene ? std::make_unique<SceneGpu>(*scene) : nullptr;
  s_->scene = std::move(scene);
  if (s_->scene && s_->scene->light) s_->light = *s_->scene->light;
  if (s_->technique) s_->technique->resetTemporalState();
}

const std::shared_ptr<const Scene>& Renderer::scene() const {
  return s_->scene;
}

std::optional<std::string> Renderer::setTechnique(std::string_view id) {
  if (id == s_->techniqueId && s_->technique) return std::nullopt;
  if (const TechniqueEntry* e = findEntry(*s_, id)) {
    try {
      auto t = e->create(s_->shaders);
      // Every declared uniform must exist in one of the programs it is bound to.
      std::vector<const gl::Program*> programs = t->programs();
      if (t->resolveMode() == ResolveMode::Lookup)
        programs.push_back(&s_->resolveProgramFor(t->lookupShader()));
      if (auto err = checkParamUniforms(e->info.params, programs)) throw std::logic_error(*err);
      s_->technique = std::move(t);
      s_->techniqueId = e->info.id;
      (void)paramsFor(*s_, id);
      return std::nullopt;
    } catch (const std::exception& ex) {
      return "technique '" + std::string(id) + "' could not be created: " + ex.what();
    }
  }
  std::string known;
  for (const TechniqueInfo& t : techniques()) known += (known.empty() ? "" : ", ") + t.id;
  for (const TechniqueEntry& e : s_->extraTechniques) known += ", " + e.info.id;
  return "unknown technique '" + std::string(id) + "' (known: " + known + ")";
}

const std::string& Renderer::techniqueId() const {
  return s_->techniqueId;
}
ParamSet& Renderer::params() {
  return paramsFor(*s_, s_->techniqueId);
}
ParamSet& Renderer::paramsOf(std::string_view id) {
  return paramsFor(*s_, id);
}
ParamSet& Renderer::rendererParams() {
  return s_->rendererParams;
}
void Renderer::setCamera(const Camera& camera) {
  s_->camera = camera;
}
const Camera& Renderer::camera() const {
  return s_->camera;
}
void Renderer::setLight(const Light& light) {
  s_->light = light;
}
const Light& Renderer::light() const {
  return s_->light;
}
const FrameStats& Renderer::stats() const {
  return s_->stats;
}
void Renderer::requestPublications(std::set<std::string> patterns) {
  s_->requested = std::move(patterns);
}
const std::set<std::string>& Renderer::requestedPublications() const {
  return s_->requested;
}
const Publication& Renderer::publication() const {
  return s_->publication;
}
void Renderer::setProgressiveBudget(double ms) {
  s_->progressiveBudgetMs = ms > 0.0 ? ms : 0.0;
  if (ms <= 0.0) s_->progressSignature.clear();
}

double Renderer::progressiveBudget() const {
  return s_->progressiveBudgetMs;
}

void Renderer::resetTemporalState() {
  if (s_->technique) s_->technique->resetTemporalState();
}

namespace {

/// The renderer's own numbers (rendererPublicationDecls): camera, light, parameter values.
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

bool wantsMaskChange(RendererState& s, bool publishing) {
  return s.rendererParams.getInt("view.overlay") == SL_OVERLAY_CHANGED ||
         (publishing && (s.publication.wants("mask.changed_pixels") ||
                         s.publication.wants("mask.compared_pixels")));
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

/// One camera's way through the G-buffer, resolve and composite steps: the main camera's
/// (timed, measured) or the outside view's (view.outside: untimed, read by no metric).
struct CameraPass {
  Targets& targets;
  glm::mat4 view{1.0f}, proj{1.0f};
  glm::vec3 eye{0.0f};
  bool mainCamera = true;
};

/// What renderFrame was asked for and what follows from it before the first step.
struct FrameSetup {
  int width = 0, height = 0;                ///< internal size: targets, readback, metrics
  int presentWidth = 0, presentHeight = 0;  ///< what the host's framebuffer shows it at
  unsigned hostFramebuffer = 0;             ///< 0: the default (none on surfaceless EGL)
  float aspect = 1.0f;
  bool publishing = false;       ///< publications requested this frame
  bool countMaskChange = false;  ///< the changed overlay or a "mask.*" key is on
  bool hadMask = false;          ///< a complete frame's mask at this size is kept (prevHard)
  bool showOutsideView = false;  ///< view.outside
};

/// What the steps hand on to later steps and to FrameStats.
struct FrameResults {
  FrameOutlines outlines;  ///< what the outside view draws (the technique adds its frusta)
  std::optional<FrameStats::MaskChangeCount> maskChange;
  std::optional<Camera> outsideCamera;
};

/// One frame while its steps run: the setup, the camera the per-camera steps draw (the main
/// one, or the outside view's while its step runs), and the results so far.
struct Frame {
  const FrameSetup setup;
  CameraPass mainCamera;
  CameraPass* camera = nullptr;
  FrameResults results;
};

bool cancelRequested(const RendererState& s) {
  return s.cancelFlag && s.cancelFlag->load(std::memory_order_relaxed);
}

// --- The steps. Each reads the frame's setup and results and the renderer's state.

/// G-buffer of the frame's camera: world position (w = covered), normal, albedo, depth.
void gbufferStep(RendererState& s, Frame& f) {
  const CameraPass& c = *f.camera;
  Targets& t = c.targets;
  glBindFramebuffer(GL_FRAMEBUFFER, t.gbuffer.id());
  glViewport(0, 0, t.width, t.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  const float zero[4] = {0, 0, 0, 0}, one = 1.0f;
  for (int i = 0; i < 3; ++i) glClearNamedFramebufferfv(t.gbuffer.id(), GL_COLOR, i, zero);
  glClearNamedFramebufferfv(t.gbuffer.id(), GL_DEPTH, 0, &one);
  s.gbufferProgram.use();
  s.gbufferProgram.set("u_viewProj", c.proj * c.view);
  s.gbufferProgram.set("u_cameraPos", c.eye);
  s.sceneGpu->draw(s.gbufferProgram, SL_UNIT_MATERIAL);
}

/// The technique's shadow passes (its own timer scopes), its parameters bound to its programs
/// from their declarations first.
void shadowsStep(RendererState& s, Frame& f) {
  const ParamSet& params = paramsFor(s, s.techniqueId);
  const FrameSetup& setup = f.setup;
  const Targets& t = f.mainCamera.targets;
  FrameContext ctx{
      .scene = *s.scene,
      .sceneGpu = *s.sceneGpu,
      .camera = s.camera,
      .aspect = setup.aspect,
      .cameraView = f.mainCamera.view,
      .cameraProj = f.mainCamera.proj,
      .light = s.light,
      .width = setup.width,
      .height = setup.height,
      .gbuffer = {.position = t.position, .normal = t.normal},
      .previous = {.hard = t.prevHard, .aliasing = t.prevAliasing, .mapIndex = t.prevMapIndex},
      .params = params,
      .timer = *s.timer,
      .shaders = s.shaders,
      .frameIndex = s.frameIndex,
      .publication = setup.publishing ? &s.publication : nullptr,
      .outlines = &f.results.outlines,
  };
  for (const gl::Program* p : s.technique->programs()) bindParams(*p, params);
  s.technique->renderShadows(ctx);
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

/// Resolve of the frame's camera's G-buffer with the technique's maps as this frame built
/// them (lookup pass or deferred): hard mask, filtered visibility, aliasing m, selected map
/// and its uv per pixel.
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

/// The mask change (changed overlay, "mask.*"): the pixels whose hard test flipped since the
/// last complete frame; nothing on the first frame of a size.
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

/// The measured aliasing statistics ("aliasing.*"), timed with the resolve.
void aliasingStatsStep(RendererState& s, Frame&) {
  publishAliasingStats(s);
}

/// Shading of the frame's camera with the view.overlay: the error overlay only for the main
/// camera of a whole frame whose exact view has a reference; the aliasing and changed
/// overlays only for the main camera (the outside view's own derivatives would show m for a
/// camera that is not measured).
void compositeStep(RendererState& s, Frame& f) {
  const CameraPass& cam = *f.camera;
  const Targets& t = cam.targets;
  glBindFramebuffer(GL_FRAMEBUFFER, t.composite.id());
  glViewport(0, 0, t.width, t.height);
  const gl::Program& c = s.compositeProgram;
  c.use();
  // Samplers: layout(binding = SL_UNIT_*) in composite.frag.
  glBindTextureUnit(SL_UNIT_G_POSITION, t.position.id());
  glBindTextureUnit(SL_UNIT_G_NORMAL, t.normal.id());
  glBindTextureUnit(SL_UNIT_G_ALBEDO, t.albedo.id());
  glBindTextureUnit(SL_UNIT_VISIBILITY, t.filtered.id());
  glBindTextureUnit(SL_UNIT_HARD, t.hard.id());
  glBindTextureUnit(SL_UNIT_REFERENCE, t.reference.id());
  glBindTextureUnit(SL_UNIT_ALIASING, t.aliasing.id());
  glBindTextureUnit(SL_UNIT_TEXEL, t.texel.id());
  glBindTextureUnit(SL_UNIT_MAP_INDEX, t.mapIndex.id());
  // The changed overlay: against the last complete frame's mask (none yet: against itself, empty).
  const bool hasPrevious = cam.mainCamera && f.setup.hadMask;
  glBindTextureUnit(SL_UNIT_PREV_HARD, hasPrevious ? t.prevHard.id() : t.hard.id());
  bindLight(c, s.light);
  c.set("u_cameraPos", cam.eye);
  bindParams(c, s.rendererParams);  // shading.ambient, view.overlay
  const int overlay = s.rendererParams.getInt("view.overlay");
  // The pages overlay's page grid per selectable map (none: 0), read by that overlay only:
  // not set (SL_MAX_DEPTH_MAPS uniforms) on every other frame.
  if (overlay == SL_OVERLAY_PAGES) {
    const std::vector<int> grid = s.technique ? s.technique->pageGrid() : std::vector<int>{};
    for (int i = 0; i < SL_MAX_DEPTH_MAPS; ++i)
      c.set(("u_pageCells[" + std::to_string(i) + "]").c_str(),
            i < int(grid.size()) ? grid[std::size_t(i)] : 0);
  }
  // A partial progressive frame draws no error pixels: its reference is of the whole frame.
  const bool shownComplete = !s.frameProgress || s.frameProgress->shownComplete;
  const bool referenceMatches =
      cam.mainCamera && shownComplete && s.referenceSignature == s.frameSignature;
  if (overlay == SL_OVERLAY_ERROR && !referenceMatches)
    c.set("u_overlay", SL_OVERLAY_NONE);  // no reference of this exact view
  if ((overlay == SL_OVERLAY_ALIASING || overlay == SL_OVERLAY_CHANGED) && !cam.mainCamera)
    c.set("u_overlay", SL_OVERLAY_NONE);  // m and the mask change of the main camera only
  glBindVertexArray(s.emptyVao.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

/// The outline segments as lines two pixels wide over `t`'s composite, on top (no depth
/// test: a frustum is never hidden by the scene).
void drawOutlines(RendererState& s, const Targets& t, const glm::mat4& viewProj,
                  const std::vector<OutlineSegment>& segments) {
  if (segments.empty()) return;
  struct Vertex {
    glm::vec3 position, colour;
  };
  std::vector<Vertex> vertices;
  vertices.reserve(segments.size() * 2);
  for (const OutlineSegment& seg : segments) {
    vertices.push_back({seg.a, seg.colour});
    vertices.push_back({seg.b, seg.colour});
  }
  const gl::Buffer buffer =
      gl::Buffer::create(GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), 0);
  const gl::VertexArray vao = gl::createVertexArray();
  glVertexArrayVertexBuffer(vao.id(), 0, buffer.id(), 0, sizeof(Vertex));
  glEnableVertexArrayAttrib(vao.id(), 0);
  glEnableVertexArrayAttrib(vao.id(), 1);
  glVertexArrayAttribFormat(vao.id(), 0, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, position));
  glVertexArrayAttribFormat(vao.id(), 1, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, colour));
  glVertexArrayAttribBinding(vao.id(), 0, 0);
  glVertexArrayAttribBinding(vao.id(), 1, 0);

  glBindFramebuffer(GL_FRAMEBUFFER, t.composite.id());
  glViewport(0, 0, t.width, t.height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  s.outlineProgram.use();
  s.outlineProgram.set("u_viewProj", viewProj);
  glBindVertexArray(vao.id());
  const glm::vec2 pixel(2.0f / float(t.width), 2.0f / float(t.height));
  for (const glm::vec2 offset :
       {glm::vec2(0.0f), glm::vec2(pixel.x, 0.0f), glm::vec2(0.0f, pixel.y)}) {
    s.outlineProgram.set("u_pixelOffset", offset);
    glDrawArrays(GL_LINES, 0, GLsizei(vertices.size()));
  }
  glBindVertexArray(0);
}

/// The outside view (view.outside) into s.outsideTargets: the G-buffer, resolve and composite
/// steps again with a third camera placed around the frusta the technique outlined (the
/// warp-grid and partition overlays, not the error and aliasing ones), then the outlines.
/// The main camera's targets stay what every metric reads.
void outsideViewStep(RendererState& s, Frame& f) {
  const FrameSetup& setup = f.setup;
  const ParamSet& p = s.rendererParams;
  const std::vector<OutlineSegment> segments =
      outlineSegments(s.camera, setup.aspect, s.scene->bounds, f.results.outlines);
  const OutsideViewSettings settings{
      .azimuthDeg = float(p.get("view.outside.azimuth_deg")),
      .elevationDeg = float(p.get("view.outside.elevation_deg")),
      .zoom = float(p.get("view.outside.zoom")),
  };
  const Camera cam = fitOutsideCamera(s.camera, setup.aspect, segments, settings);
  if (auto err = cam.validate()) throw std::runtime_error(*err);
  s.ensureOutsideTargets(setup.width, setup.height);
  CameraPass outside{.targets = s.outsideTargets,
                     .view = cam.view(),
                     .proj = cam.projection(setup.aspect),
                     .eye = cam.position,
                     .mainCamera = false};
  f.camera = &outside;
  for (void (*step)(RendererState&, Frame&) : {gbufferStep, resolveStep, compositeStep}) {
    if (cancelRequested(s)) break;
    step(s, f);
  }
  f.camera = &f.mainCamera;
  if (cancelRequested(s)) return;  // renderFrame drops the frame
  drawOutlines(s, s.outsideTargets, outside.proj * outside.view, segments);
  f.results.outsideCamera = cam;
  s.lastFrameOutside = true;
}

/// To the host's framebuffer (a surfaceless EGL context has none: the frame then stays in the
/// renderer's colour target, which readback() returns): the outside view's image while on. A
/// smaller internal size (the GUI's adaptive resolution) is stretched over the present size.
void presentStep(RendererState& s, Frame& f) {
  const FrameSetup& setup = f.setup;
  const Targets& shown = s.lastFrameOutside ? s.outsideTargets : f.mainCamera.targets;
  const bool scaled = setup.presentWidth != setup.width || setup.presentHeight != setup.height;
  const unsigned target = setup.hostFramebuffer;
  if (glCheckNamedFramebufferStatus(target, GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE)
    glBlitNamedFramebuffer(shown.composite.id(), target, 0, 0, setup.width, setup.height, 0, 0,
                           scaled ? setup.presentWidth : setup.width,
                           scaled ? setup.presentHeight : setup.height, GL_COLOR_BUFFER_BIT,
                           scaled ? GL_LINEAR : GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, target);
}

// --- The frame, declared once.

/// What an error a step throws is reported as (renderFrame then renders a neutral frame).
enum class StepFailure {
  Propagates,        ///< not caught (the renderer's own passes)
  NamesTechnique,    ///< "technique '<id>': ..."
  NamesOutsideView,  ///< "outside view: ..."
};

/// One step of renderFrame.
struct FrameStep {
  const char* name;  ///< FrameStats::stoppedBefore names it
  /// The timer scope it runs in (consecutive steps of one pass share one scope); null: not
  /// timed by the renderer (the technique times its own passes; the outside view is not timed).
  const char* timedPass;
  StepFailure failure;
  /// The host's stop flag is read before the step. Not before the first (a frame stopped at
  /// once still has its G-buffer) nor before the main resolve (the maps of this frame go with
  /// their resolve; a deferred resolve stops between its units itself). Wherever a frame stops,
  /// endFrame discards what it changed (the frame is transactional).
  bool stopsBefore;
  /// When it runs (null: every frame).
  bool (*when)(const RendererState&, const Frame&);
  void (*run)(RendererState&, Frame&);
};

/// Every step of a frame, in order. renderFrame walks it once, reading the host's stop flag
/// before the steps that say so (and a deferred resolve between its units).
constexpr FrameStep kFrameSteps[] = {
    {.name = "gbuffer",
     .timedPass = "gbuffer",
     .failure = StepFailure::Propagates,
     .stopsBefore = false,
     .when = nullptr,
     .run = gbufferStep},
    {.name = "shadows",
     .timedPass = nullptr,
     .failure = StepFailure::NamesTechnique,
     .stopsBefore = true,
     .when = nullptr,
     .run = shadowsStep},
    {.name = "resolve",
     .timedPass = "resolve",
     .failure = StepFailure::NamesTechnique,
     .stopsBefore = false,
     .when = nullptr,
     .run = resolveStep},
    {.name = "mask change",
     .timedPass = "resolve",
     .failure = StepFailure::NamesTechnique,
     .stopsBefore = true,
     .when = [](const RendererState&,
                const Frame& f) { return f.setup.countMaskChange && f.setup.hadMask; },
     .run = maskChangeStep},
    {.name = "aliasing statistics",
     .timedPass = "resolve",
     .failure = StepFailure::NamesTechnique,
     .stopsBefore = true,
     .when = [](const RendererState& s,
                const Frame& f) { return f.setup.publishing && wantsAliasingStats(s.publication); },
     .run = aliasingStatsStep},
    {.name = "composite",
     .timedPass = "composite",
     .failure = StepFailure::Propagates,
     .stopsBefore = true,
     .when = nullptr,
     .run = compositeStep},
    {.name = "outside view",
     .timedPass = nullptr,
     .failure = StepFailure::NamesOutsideView,
     .stopsBefore = true,
     .when = [](const RendererState&, const Frame& f) { return f.setup.showOutsideView; },
     .run = outsideViewStep},
    {.name = "present",
     .timedPass = nullptr,
     .failure = StepFailure::Propagates,
     .stopsBefore = true,
     .when = nullptr,
     .run = presentStep},
};

/// The message of a step's error, or nothing when it propagates.
std::optional<std::string> stepFailureMessage(const RendererState& s, StepFailure failure,
                                              const std::exception& e) {
  switch (failure) {
    case StepFailure::NamesTechnique:
      return "technique '" + s.techniqueId + "': " + e.what();
    case StepFailure::NamesOutsideView:
      return std::string("outside view: ") + e.what();
    case StepFailure::Propagates:
      break;
  }
  return std::nullopt;
}

/// What this frame shows (scene, technique, parameters, size, camera, light); the error
/// overlay is only drawn for a matching reference.
std::string frameSignatureOf(const RendererState& s, const ParamSet& params, int width,
                             int height) {
  const Camera& c = s.camera;
  char buf[512];
  std::snprintf(buf, sizeof buf, "%p|%s|%u|%d|%d|%g,%g,%g|%g,%g,%g|%g,%g,%g|%g|%s",
                static_cast<const void*>(s.scene.get()), s.techniqueId.c_str(), params.revision(),
                width, height, c.position.x, c.position.y, c.position.z, c.target.x, c.target.y,
                c.target.z, c.up.x, c.up.y, c.up.z, c.fovYDeg, s.light.describe().c_str());
  return buf;
}

/// The end of a frame's transaction: a complete frame (FrameStats::complete) keeps its resolve
/// targets as the previous frame's and commits the technique's state across frames; any other
/// call (stopped, failed, a progressive call short of its last unit) discards that state, and
/// the next frame starts from the last complete one (Technique::commitFrame).
void endFrame(RendererState& s, bool complete) {
  const TechniqueEntry* entry = findEntry(s, s.techniqueId);
  const bool carriesState = s.technique && entry && entry->info.temporalState;
  if (!complete) {
    if (carriesState) s.technique->discardFrame();
    return;
  }
  Targets& t = s.targets;
  for (auto [from, to] : {std::pair{&t.hard, &t.prevHard}, std::pair{&t.aliasing, &t.prevAliasing},
                          std::pair{&t.mapIndex, &t.prevMapIndex}})
    glCopyImageSubData(from->id(), GL_TEXTURE_2D, 0, 0, 0, 0, to->id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       t.width, t.height, 1);
  t.committed = true;
  if (carriesState) s.technique->commitFrame();
}

/// FrameStats of the frame the steps rendered, or of the part a frame the host's flag stopped
/// before `stoppedBefore` did.
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

}  // namespace

void Renderer::clearFrame(int width, int height, unsigned target) {
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  if (glCheckNamedFramebufferStatus(target, GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE) {
    if (width > 0 && height > 0) glViewport(0, 0, width, height);
    glClearColor(0.25f, 0.25f, 0.28f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
}

void Renderer::setCancelFlag(const std::atomic<bool>* flag) {
  s_->cancelFlag = flag;
}

std::optional<std::string> Renderer::renderFrame(int width, int height, unsigned target) {
  return renderFrame(width, height, target, width, height);
}

std::optional<std::string> Renderer::renderFrame(int width, int height, unsigned target,
                                                 int presentWidth, int presentHeight) {
  RendererState& s = *s_;
  s.stats.cancelled = false;
  s.stats.stoppedBefore.clear();
  s.lastFrameCancelled = false;
  auto neutral = [&](const std::string& why) -> std::optional<std::string> {
    clearFrame(std::max(width, presentWidth), std::max(height, presentHeight), target);
    return why;
  };
  if (width <= 0 || height <= 0 || width > s.maxFrame.width || height > s.maxFrame.height)
    return neutral("frame size " + std::to_string(width) + "x" + std::to_string(height) +
                   " is not drawable (need 1.." + std::to_string(s.maxFrame.width) + " x 1.." +
                   std::to_string(s.maxFrame.height) + ": " + s.maxFrame.widthLimit + ", " +
                   s.maxFrame.heightLimit + ")");
  if (!s.scene || !s.sceneGpu) return neutral("no scene loaded");
  if (auto err = s.camera.validate()) return neutral(*err);
  if (auto err = s.light.validate()) return neutral(*err);
  if (const TechniqueInfo* info = findTechnique(s.techniqueId)) {
    if (auto err = checkLightSupport(*info, s.light.type)) return neutral(*err);
    if (auto err = checkTechniqueParams(*info, params()))
      return neutral("technique '" + s.techniqueId + "': " + *err);
  }

  s.frameSignature = frameSignatureOf(s, params(), width, height);
  s.ensureTargets(width, height);
  const float aspect = float(width) / float(height);
  ++s.frameIndex;
  s.frameProgress.reset();
  s.lastFrameOutside = false;
  s.timer->beginFrame();
  const bool publishing = !s.requested.empty();
  Publication lastComplete;  // the publication a stopped frame leaves in place
  if (publishing) {
    lastComplete = std::exchange(s.publication, Publication{});
    s.publication.frameIndex = s.frameIndex;
    s.publication.techniqueId = s.techniqueId;
    s.publication.requested = s.requested;
    publishFrameNumbers(s, height, aspect);
  }
  Frame f{
      .setup = {.width = width,
                .height = height,
                .presentWidth = presentWidth,
                .presentHeight = presentHeight,
                .hostFramebuffer = target,
                .aspect = aspect,
                .publishing = publishing,
                .countMaskChange = wantsMaskChange(s, publishing),
                .hadMask = s.targets.committed,
                .showOutsideView = s.rendererParams.getBool("view.outside")},
      .mainCamera = {.targets = s.targets,
                     .view = s.camera.view(),
                     .proj = s.camera.projection(aspect),
                     .eye = s.camera.position,
                     .mainCamera = true},
  };
  f.camera = &f.mainCamera;

  const char* openPass = nullptr;  // the renderer's timer scope open now
  const auto enterPass = [&](const char* pass) {
    if (openPass && pass && std::strcmp(openPass, pass) == 0) return;
    if (openPass) s.timer->end();
    if (pass) s.timer->begin(pass);
    openPass = pass;
  };
  for (const FrameStep& step : kFrameSteps) {
    if (step.stopsBefore && cancelRequested(s)) {
      enterPass(nullptr);
      s.lastFrameCancelled = true;
      fillStats(s, f, &step);
      endFrame(s, false);
      if (publishing) s.publication = std::move(lastComplete);  // not a frame's publication
      return std::nullopt;
    }
    if (step.when && !step.when(s, f)) continue;
    enterPass(step.timedPass);
    if (step.failure == StepFailure::Propagates) {
      step.run(s, f);
      continue;
    }
    try {
      step.run(s, f);
    } catch (const std::exception& e) {
      enterPass(nullptr);
      s.timer->endFrame();
      endFrame(s, false);
      return neutral(*stepFailureMessage(s, step.failure, e));
    }
  }
  enterPass(nullptr);
  fillStats(s, f, nullptr);
  endFrame(s, s.stats.complete());
  return std::nullopt;
}

std::optional<PixelProbe> Renderer::probePixel(int x, int y) const {
  const Targets& t = s_->targets;
  if (t.width == 0 || x < 0 || y < 0 || x >= t.width || y >= t.height) return std::nullopt;
  const int row = t.height - 1 - y;  // GL textures: bottom row first
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  auto read = [&](const gl::Texture& tex, GLenum format, GLenum type, GLsizei bytes, void* out) {
    glGetTextureSubImage(tex.id(), 0, x, row, 0, 1, 1, 1, format, type, bytes, out);
  };
  PixelProbe p;
  p.x = x;
  p.y = y;
  glm::vec4 position(0.0f);
  read(t.position, GL_RGBA, GL_FLOAT, sizeof(position), &position);
  p.covered = position.w > 0.0f;
  if (!p.covered) return p;
  p.worldM = glm::vec3(position);
  read(t.hard, GL_RED_INTEGER, GL_UNSIGNED_BYTE, 1, &p.hard);
  read(t.aliasing, GL_RED, GL_FLOAT, sizeof(float), &p.aliasing);
  std::uint8_t map = 0;
  read(t.mapIndex, GL_RED_INTEGER, GL_UNSIGNED_BYTE, 1, &map);
  p.map = map;
  read(t.texel, GL_RG, GL_FLOAT, sizeof(glm::vec2), &p.mapUv);
  return p;
}

ImageRGBA8 Renderer::readColor() const {
  const Targets& t = s_->targets;
  const bool outside = s_->lastFrameOutside && s_->outsideTargets.width == t.width &&
                       s_->outsideTargets.height == t.height;
  ImageRGBA8 image;
  image.width = t.width;
  image.height = t.height;
  if (t.width == 0) return image;
  image.pixels.resize(size_t(t.width) * size_t(t.height) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage((outside ? s_->outsideTargets : t).color.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                    GLsizei(image.pixels.size()), image.pixels.data());
  flipVertically(image);
  return image;
}

FrameReadback Renderer::readback() const {
  const Targets& t = s_->targets;
  FrameReadback r;
  r.cancelled = s_->lastFrameCancelled;
  if (r.cancelled) return r;  // the targets hold part of a frame: not one to measure
  r.width = t.width;
  r.height = t.height;
  if (t.width == 0) return r;
  const size_t n = size_t(t.width) * size_t(t.height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  r.positions.resize(n);
  r.normals.resize(n);
  r.hardMask.resize(n);
  glGetTextureImage(t.position.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(n * sizeof(glm::vec4)),
                    r.positions.data());
  glGetTextureImage(t.normal.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(n * sizeof(glm::vec4)),
                    r.normals.data());
  glGetTextureImage(t.hard.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, GLsizei(n),
                    r.hardMask.data());
  r.aliasing.resize(n);
  glGetTextureImage(t.aliasing.id(), 0, GL_RED, GL_FLOAT, GLsizei(n * sizeof(float)),
                    r.aliasing.data());
  r.texel.resize(n);
  glGetTextureImage(t.texel.id(), 0, GL_RG, GL_FLOAT, GLsizei(n * sizeof(glm::vec2)),
                    r.texel.data());
  r.mapIndex.resize(n);
  glGetTextureImage(t.mapIndex.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, GLsizei(n),
                    r.mapIndex.data());
  r.color.width = t.width;
  r.color.height = t.height;
  r.color.pixels.resize(n * 4);
  glGetTextureImage(t.color.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(n * 4),
                    r.color.pixels.data());
  // Everything top row first, like the colour image (GL textures are bottom row first).
  flipVertically(r.color);
  if (s_->lastFrameOutside && s_->outsideTargets.width == t.width &&
      s_->outsideTargets.height == t.height) {
    r.outside.width = t.width;
    r.outside.height = t.height;
    r.outside.pixels.resize(n * 4);
    glGetTextureImage(s_->outsideTargets.color.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(n * 4),
                      r.outside.pixels.data());
    flipVertically(r.outside);
  }
  auto flip = [&](auto& v) {
    std::span<std::uint8_t> bytes(reinterpret_cast<std::uint8_t*>(v.data()),
                                  v.size() * sizeof(v[0]));
    flipRowsVertically(bytes, size_t(t.width) * sizeof(v[0]), t.height);
  };
  flip(r.positions);
  flip(r.normals);
  flip(r.hardMask);
  flip(r.aliasing);
  flip(r.texel);
  flip(r.mapIndex);
  return r;
}

Renderer::ReferenceSnapshot Renderer::snapshotForReference() const {
  ReferenceSnapshot snap;
  snap.frame = readback();
  snap.light = s_->light;
  snap.frameSignature = s_->frameSignature;
  if (!s_->scene || snap.frame.width == 0 || !ShadowReference::available()) return snap;
  if (!s_->reference || s_->referenceScene != s_->scene.get()) {
    s_->reference = std::make_shared<ShadowReference>(*s_->scene);
    s_->referenceScene = s_->scene.get();
  }
  snap.reference = s_->reference;
  return snap;
}

std::optional<Renderer::ErrorResult> Renderer::traceReference(ReferenceSnapshot snap,
                                                              const std::atomic<bool>* cancelled) {
  if (snap.frame.cancelled) return std::nullopt;  // a stopped frame is not measured
  ErrorResult res;
  res.frame = std::move(snap.frame);
  if (!snap.reference) return res;
  const FrameReadback& f = res.frame;
  const std::size_t n = f.positions.size();
  if (f.normals.size() != n || f.hardMask.size() != n)
    throw std::invalid_argument("traceReference: positions, normals and mask differ in size");
  // Bands of rows, so that a cancel (scene changed, window closed) is seen soon.
  const std::size_t band = std::size_t(std::max(1, f.width)) * 64;
  res.referenceMask.resize(n);
  std::vector<std::uint8_t> part;
  for (std::size_t begin = 0; begin < n; begin += band) {
    if (cancelled && cancelled->load()) return std::nullopt;
    const std::size_t count = std::min(band, n - begin);
    snap.reference->evaluate(std::span(f.positions).subspan(begin, count),
                             std::span(f.normals).subspan(begin, count), snap.light, part);
    std::copy(part.begin(), part.end(), res.referenceMask.begin() + std::ptrdiff_t(begin));
  }
  res.stats = compareShadowMasks(f.hardMask, res.referenceMask);
  return res;
}

namespace {
/// Keeps a traced reference mask (row 0 = top) for the error overlay of `frameSignature`.
bool uploadReferenceMask(RendererState& s, const std::string& frameSignature,
                         std::span<const std::uint8_t> mask, int width, int height) {
  const Targets& t = s.targets;
  if (width != t.width || height != t.height ||
      mask.size() != std::size_t(t.width) * std::size_t(t.height) || mask.empty())
    return false;
  std::vector<std::uint8_t> glOrder(mask.begin(), mask.end());  // GL: bottom row first
  flipRowsVertically(glOrder, size_t(t.width), t.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(t.reference.id(), 0, 0, 0, t.width, t.height, GL_RED_INTEGER,
                      GL_UNSIGNED_BYTE, glOrder.data());
  s.referenceSignature = frameSignature;
  return true;
}
}  // namespace

bool Renderer::setReferenceMask(const std::string& frameSignature,
                                std::span<const std::uint8_t> mask, int width, int height) {
  return uploadReferenceMask(*s_, frameSignature, mask, width, height);
}

const std::string& Renderer::frameSignature() const {
  return s_->frameSignature;
}

Renderer::ErrorResult Renderer::computeError() const {
  if (s_->lastFrameCancelled)
    throw std::runtime_error(
        "computeError: the last frame was cancelled before it was complete (setCancelFlag); "
        "render a complete frame to measure its error");
  ReferenceSnapshot snap = snapshotForReference();
  const std::string signature = snap.frameSignature;
  ErrorResult res = *traceReference(std::move(snap));  // not cancellable: always a result
  // Keep it for the error overlay of this frame.
  uploadReferenceMask(*s_, signature, res.referenceMask, res.frame.width, res.frame.height);
  return res;
}

std::optional<std::string> Renderer::reloadShaders() {
  std::string errors;
  auto note = [&](std::optional<std::string> e) {
    if (e) errors += (errors.empty() ? "" : "\n") + *e;
  };
  note(s_->gbufferProgram.rebuild(s_->shaders));
  note(s_->compositeProgram.rebuild(s_->shaders));
  note(s_->aliasingStatsProgram.rebuild(s_->shaders));
  note(s_->maskChangeProgram.rebuild(s_->shaders));
  note(s_->outlineProgram.rebuild(s_->shaders));
  for (auto& [name, prog] : s_->resolvePrograms) note(prog.rebuild(s_->shaders));
  if (s_->technique) note(s_->technique->reloadShaders(s_->shaders));
  if (errors.empty()) return std::nullopt;
  return errors;
}

std::vector<std::string> Renderer::takeGlErrors() {
  std::lock_guard lock(s_->errorMutex);
  return std::exchange(s_->glErrors, {});
}

}  // namespace sl
