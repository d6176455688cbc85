// The renderer (Renderer.h): its parameters, its GL context's setup, the scene, technique,
// camera and light it is given, and the frame's plan (renderFrame: the checks, the frame's
// setup, then the declared list of steps in core/FrameSteps.h, docs/ARCHITECTURE.md).
// Only renderer/core, renderer/gl and the techniques call OpenGL.
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
#include "core/RendererState.h"

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
      floatParam("shading.ambient", "Ambient", "Shading", 0.35, {0.0, 1.0, 0.05})
          .withUniform("u_ambient")
          .withHelp("Sky light added to every surface, so shadowed areas stay readable."),
      choiceParam("view.overlay", "Overlay", "View", overlayNames(), SL_OVERLAY_NONE)
          .withUniform("u_overlay")
          .withHelp("Drawn over the scene: shadow error against the exact reference (false-lit "
                    "magenta, false-shadowed cyan; needs a computed reference for this view), "
                    "perspective aliasing m as a heat map (blue: m<1 oversampled, white: m=1, red: "
                    "m>1 undersampled; log2 scale -4..4; error and m in the main view only, not in "
                    "the outside view), or the shadow-map texel grid (every 1/" +
                    std::to_string(SL_GRID_LINES_PER_MAP) +
                    " of the selected map) projected onto the scene, or the partition: each pixel "
                    "coloured by the index of the map it selected (cascade, face, layer; colours "
                    "repeat every " +
                    std::to_string(SL_PARTITION_COLOURS) +
                    "): 0 red, 1 green, 2 blue, 3 yellow, 4 magenta, 5 cyan, 6 orange, 7 violet; "
                    "or changed: the pixels whose hard shadow test flipped (lit <-> shadowed) "
                    "since the previous frame in vivid yellow (flicker, vibration; main view "
                    "only); or pages: the borders of the page each pixel's lookup used, in orange "
                    "over the scene in grey (paged maps: rmsm, asm; the partition overlay colours "
                    "each pixel by the level it uses)."),
      switchParam("view.outside", "Outside view", "View", false)
          .withHelp(
              "Show the scene from a third camera, placed so that the view frustum and the light's "
              "frusta are visible, with lines: the camera's frustum (white, near to the deepest "
              "point of the scene bounds), split planes (grey), each shadow map's light frustum "
              "(its partition colour) and a warped map's frustum (cyan, its sides extended to the "
              "warp's centre of projection). The metrics still measure the main camera's image."),
      switchParam("view.adaptive", "Adaptive resolution", "View", false)
          .withHelp("GUI only, off by default: when a frame takes longer than the frame budget, "
                    "the interactive view renders at half its size (stretched to fit; never less) "
                    "and says so in its corner; the first fast frame returns to full size, and a "
                    "still view is redrawn at full size. Never in presenter mode, the split view, "
                    "exports, grabs or a window that opened a lesson (its pictures and numbers are "
                    "full-size frames); the command line always renders at the requested size."),
      intParam("view.adaptive.budget_ms", "Frame budget (ms)", "View", 250, {20, 10000, 10})
          .withHelp("GUI only: a frame slower than this lowers the view's internal resolution "
                    "(view.adaptive); continuous rendering spends at most half of it on a "
                    "progressive technique's tiles per frame, so the window never waits on one."),
      floatParam("view.outside.azimuth_deg", "Outside azimuth", "View", 60.0, {-180.0, 180.0, 5.0})
          .withHelp(
              "Direction of the outside view's camera around the vertical, degrees: 0 behind the "
              "main camera, 90 from its right (dragging in the outside view changes it)."),
      floatParam("view.outside.elevation_deg", "Outside elevation", "View", 35.0,
                 {-80.0, 85.0, 5.0})
          .withHelp("Height of the outside view's camera above the horizon, degrees."),
      floatParam("view.outside.zoom", "Outside zoom", "View", 1.0, {0.001, 1.0, 0.01})
          .withHelp(
              "1 frames every line; a smaller value frames that share of the view, centred near "
              "the main camera's view axis that share of the way in (0.05: the first twentieth of "
              "a kilometre-deep frustum). The mouse wheel in the outside view changes it."),
  };
}

namespace {

void GLAPIENTRY debugCallback(GLenum, GLenum type, GLuint, GLenum severity, GLsizei,
                              const GLchar* message, const void* user) {
  if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
  auto* s = static_cast<RendererState*>(const_cast<void*>(user));
  std::lock_guard lock(s->errorMutex);
  if (s->glErrors.size() < 64) s->glErrors.emplace_back(message);
}

}  // namespace

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

namespace {
/// The id of the first technique that declares `flag`, else of the first technique.
const std::string& techniqueDeclaring(bool TechniqueInfo::*flag) {
  const std::vector<TechniqueInfo>& all = Renderer::techniques();
  for (const TechniqueInfo& t : all)
    if (t.*flag) return t.id;
  static const std::string none;
  return all.empty() ? none : all.front().id;
}
}  // namespace

const std::string& Renderer::baselineTechniqueId() {
  return techniqueDeclaring(&TechniqueInfo::baseline);
}

const std::string& Renderer::firstScreenTechniqueId() {
  return techniqueDeclaring(&TechniqueInfo::firstScreen);
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
  if (auto err = setTechnique(baselineTechniqueId())) throw std::runtime_error(*err);
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
  using namespace frame;
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
