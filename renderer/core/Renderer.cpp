// The flow of one frame (docs/ARCHITECTURE.md): G-buffer from the camera -> the
// technique's shadow passes -> resolve (hard mask + filtered visibility) -> composite ->
// blit to the host's framebuffer. Only this file and the techniques call OpenGL.
#include "core/Renderer.h"

#include <chrono>
#include <cmath>
#include <mutex>
#include <span>
#include <stdexcept>

#include "core/SceneGpu.h"
#include "core/Technique.h"
#include "gl/Gl.h"
#include "metrics/ShadowReference.h"

namespace sl {

std::vector<ParamDecl> rendererParamDecls() {
  return {
      {"shading.ambient",
       "Ambient",
       "Shading",
       ParamType::Float,
       0.35,
       0.0,
       1.0,
       0.05,
       {},
       "Sky light added to every surface, so shadowed areas stay readable."},
      {"view.overlay",
       "Overlay",
       "View",
       ParamType::Enum,
       0,
       0,
       3,
       1,
       {"none", "error", "aliasing", "warp-grid"},
       "Drawn over the scene: shadow error against the exact reference (false-lit magenta, "
       "false-shadowed cyan; needs a computed reference for this view), perspective aliasing "
       "m as a heat map (blue: m<1 oversampled, white: m=1, red: m>1 undersampled; log2 scale "
       "-4..4), or the shadow-map texel grid (every 1/16 of the map) projected onto the scene."},
  };
}

namespace {

void GLAPIENTRY debugCallback(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei,
                              const GLchar* message, const void* user);

struct Targets {
  int width = 0, height = 0;
  gl::Texture position, normal, albedo, depth, hard, filtered, aliasing, texel, color;
  gl::Texture reference;  // R8UI reference mask of the last computeError() (error overlay)
  gl::Framebuffer gbuffer, resolve, composite;
};

}  // namespace

struct RendererState {
  gl::ShaderLibrary shaders{gl::ShaderLibrary::defaultRoot()};
  std::unique_ptr<gl::GpuTimer> timer;
  std::shared_ptr<const Scene> scene;
  std::unique_ptr<SceneGpu> sceneGpu;
  std::string techniqueId;
  std::unique_ptr<Technique> technique;
  std::map<std::string, ParamSet, std::less<>> techniqueParams;
  ParamSet rendererParams{rendererParamDecls()};
  Camera camera;
  DirectionalLight light;
  Renderer::FrameSizeLimit maxFrame;  ///< the context's limits, queried once
  FrameStats stats;
  Publication publication;
  std::set<std::string> requested;  ///< publication patterns (empty: publish nothing)
  std::uint64_t frameIndex = 0;
  gl::Program gbufferProgram, compositeProgram;
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

  void ensureTargets(int w, int h) {
    if (targets.width == w && targets.height == h) return;
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
    t.reference = gl::Texture::create2D(GL_R8UI, w, h);
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
    t.resolve.setDrawBuffers(4);
    t.resolve.checkComplete("resolve");
    t.composite = gl::Framebuffer::create();
    t.composite.attach(GL_COLOR_ATTACHMENT0, t.color);
    t.composite.setDrawBuffers(1);
    t.composite.checkComplete("composite");
    targets = std::move(t);
  }
};

namespace {

void GLAPIENTRY debugCallback(GLenum, GLenum type, GLuint, GLenum severity, GLsizei,
                              const GLchar* message, const void* user) {
  if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
  auto* s = static_cast<RendererState*>(const_cast<void*>(user));
  std::lock_guard lock(s->errorMutex);
  if (s->glErrors.size() < 64) s->glErrors.emplace_back(message);
}

ParamSet& paramsFor(RendererState& s, std::string_view id) {
  auto it = s.techniqueParams.find(id);
  if (it != s.techniqueParams.end()) return it->second;
  const TechniqueInfo* info = Renderer::findTechnique(id);
  if (!info) throw std::out_of_range("unknown technique '" + std::string(id) + "'");
  return s.techniqueParams.emplace(std::string(id), ParamSet(info->params)).first->second;
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
  if (options.debugOutput) {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(debugCallback, s_.get());
  }
  s_->maxFrame = maxFrameSize();
  s_->timer = std::make_unique<gl::GpuTimer>();
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

std::string Renderer::glDescription() const {
  auto str = [](GLenum e) {
    const char* p = reinterpret_cast<const char*>(glGetString(e));
    return std::string(p ? p : "?");
  };
  return str(GL_RENDERER) + " | " + str(GL_VERSION);
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
  if (s_->scene && s_->scene->sun) s_->light = *s_->scene->sun;
  if (s_->technique) s_->technique->resetTemporalState();
}

const std::shared_ptr<const Scene>& Renderer::scene() const {
  return s_->scene;
}

std::optional<std::string> Renderer::setTechnique(std::string_view id) {
  if (id == s_->techniqueId && s_->technique) return std::nullopt;
  for (const TechniqueEntry& e : techniqueRegistry()) {
    if (e.info.id != id) continue;
    try {
      auto t = e.create(s_->shaders);
      (void)s_->resolveProgramFor(t->lookupShader());
      s_->technique = std::move(t);
      s_->techniqueId = e.info.id;
      (void)paramsFor(*s_, id);
      return std::nullopt;
    } catch (const std::exception& ex) {
      return "technique '" + std::string(id) + "' could not be created: " + ex.what();
    }
  }
  std::string known;
  for (const TechniqueInfo& t : techniques()) known += (known.empty() ? "" : ", ") + t.id;
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
void Renderer::setLight(const DirectionalLight& light) {
  s_->light = light;
}
const DirectionalLight& Renderer::light() const {
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
void Renderer::resetTemporalState() {
  if (s_->technique) s_->technique->resetTemporalState();
}

std::optional<std::string> Renderer::renderFrame(int width, int height, unsigned target) {
  RendererState& s = *s_;
  auto neutral = [&](const std::string& why) -> std::optional<std::string> {
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    if (glCheckNamedFramebufferStatus(target, GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE) {
      if (width > 0 && height > 0) glViewport(0, 0, width, height);
      glClearColor(0.25f, 0.25f, 0.28f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
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

  {  // What this frame shows; the error overlay is only drawn for a matching reference.
    const Camera& c = s.camera;
    char buf[512];
    std::snprintf(buf, sizeof buf, "%p|%s|%u|%d|%d|%g,%g,%g|%g,%g,%g|%g,%g,%g|%g|%g,%g",
                  static_cast<const void*>(s.scene.get()), s.techniqueId.c_str(),
                  params().revision(), width, height, c.position.x, c.position.y, c.position.z,
                  c.target.x, c.target.y, c.target.z, c.up.x, c.up.y, c.up.z, c.fovYDeg,
                  s.light.azimuthDeg, s.light.elevationDeg);
    s.frameSignature = buf;
  }
  const auto frameStart = std::chrono::steady_clock::now();
  s.ensureTargets(width, height);
  Targets& t = s.targets;
  const float aspect = float(width) / float(height);
  const glm::mat4 view = s.camera.view(), proj = s.camera.projection(aspect);
  const glm::vec3 towardsLight = s.light.towardsLight();
  ++s.frameIndex;
  s.timer->beginFrame();
  const bool publishing = !s.requested.empty();
  if (publishing) {
    s.publication = Publication{};
    s.publication.frameIndex = s.frameIndex;
    s.publication.techniqueId = s.techniqueId;
    s.publication.requested = s.requested;
  }

  {  // 1. Camera G-buffer.
    auto pass = s.timer->scope("gbuffer");
    glBindFramebuffer(GL_FRAMEBUFFER, t.gbuffer.id());
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    const float zero[4] = {0, 0, 0, 0}, one = 1.0f;
    for (int i = 0; i < 3; ++i) glClearNamedFramebufferfv(t.gbuffer.id(), GL_COLOR, i, zero);
    glClearNamedFramebufferfv(t.gbuffer.id(), GL_DEPTH, 0, &one);
    s.gbufferProgram.use();
    s.gbufferProgram.set("u_viewProj", proj * view);
    s.gbufferProgram.set("u_cameraPos", s.camera.position);
    s.sceneGpu->draw(s.gbufferProgram, 0);
  }

  // 2. The technique's shadow passes.
  FrameContext ctx{*s.scene,
                   *s.sceneGpu,
                   s.camera,
                   aspect,
                   view,
                   proj,
                   towardsLight,
                   width,
                   height,
                   t.position,
                   t.normal,
                   t.hard,
                   params(),
                   *s.timer,
                   s.shaders,
                   s.frameIndex,
                   publishing ? &s.publication : nullptr};
  try {
    s.technique->renderShadows(ctx);
  } catch (const std::exception& e) {
    s.timer->endFrame();
    return neutral(std::string("technique '") + s.techniqueId + "': " + e.what());
  }

  {  // 3. Resolve: hard mask + filtered visibility per pixel.
    auto pass = s.timer->scope("resolve");
    const gl::Program& resolve = s.resolveProgramFor(s.technique->lookupShader());
    glBindFramebuffer(GL_FRAMEBUFFER, t.resolve.id());
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    resolve.use();
    glBindTextureUnit(0, t.position.id());
    glBindTextureUnit(1, t.normal.id());
    resolve.set("u_gPosition", 0);
    resolve.set("u_gNormal", 1);
    resolve.set("u_towardsLight", towardsLight);
    s.technique->bindLookup(resolve, 2);
    glBindVertexArray(s.emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }

  {  // 4. Composite (shading).
    auto pass = s.timer->scope("composite");
    glBindFramebuffer(GL_FRAMEBUFFER, t.composite.id());
    glViewport(0, 0, width, height);
    const gl::Program& c = s.compositeProgram;
    c.use();
    glBindTextureUnit(0, t.position.id());
    glBindTextureUnit(1, t.normal.id());
    glBindTextureUnit(2, t.albedo.id());
    glBindTextureUnit(3, t.filtered.id());
    c.set("u_gPosition", 0);
    c.set("u_gNormal", 1);
    c.set("u_gAlbedo", 2);
    c.set("u_visibility", 3);
    c.set("u_towardsLight", towardsLight);
    c.set("u_ambient", float(s.rendererParams.get("shading.ambient")));
    c.set("u_cameraPos", s.camera.position);
    glBindTextureUnit(4, t.hard.id());
    glBindTextureUnit(5, t.reference.id());
    glBindTextureUnit(6, t.aliasing.id());
    glBindTextureUnit(7, t.texel.id());
    c.set("u_hard", 4);
    c.set("u_reference", 5);
    c.set("u_aliasing", 6);
    c.set("u_texel", 7);
    int overlay = s.rendererParams.getInt("view.overlay");
    if (overlay == 1 && s.referenceSignature != s.frameSignature) overlay = 0;  // stale
    c.set("u_overlay", overlay);
    glBindVertexArray(s.emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
  }

  // 5. To the host's framebuffer (a surfaceless EGL context has none: the frame then
  // stays in the renderer's colour target, which readback() returns).
  if (glCheckNamedFramebufferStatus(target, GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE)
    glBlitNamedFramebuffer(t.composite.id(), target, 0, 0, width, height, 0, 0, width, height,
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, target);

  s.stats = FrameStats{};
  s.stats.frameIndex = s.frameIndex;
  s.stats.width = width;
  s.stats.height = height;
  s.stats.passes = s.timer->endFrame();
  s.stats.timingMethod = s.timer->methodName();
  s.stats.timingFramesLate = s.timer->framesLate();
  s.stats.memory = s.technique->memory();
  s.stats.publicationBytes = publishing ? s.publication.readbackBytes : 0;
  for (const PassTiming& p : s.stats.passes) s.stats.totalMs += p.ms;
  (void)frameStart;
  return std::nullopt;
}

FrameReadback Renderer::readback() const {
  const Targets& t = s_->targets;
  FrameReadback r;
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
  r.color.width = t.width;
  r.color.height = t.height;
  r.color.pixels.resize(n * 4);
  glGetTextureImage(t.color.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(n * 4),
                    r.color.pixels.data());
  // Everything top row first, like the colour image (GL textures are bottom row first).
  flipVertically(r.color);
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
  return r;
}

Renderer::ErrorResult Renderer::computeError() const {
  ErrorResult res;
  res.frame = readback();
  if (!s_->scene || res.frame.width == 0) return res;
  if (!s_->reference || s_->referenceScene != s_->scene.get()) {
    s_->reference = std::make_shared<ShadowReference>(*s_->scene);
    s_->referenceScene = s_->scene.get();
  }
  s_->reference->evaluate(res.frame.positions, res.frame.normals, s_->light.towardsLight(),
                          res.referenceMask);
  res.stats = compareShadowMasks(res.frame.hardMask, res.referenceMask);
  // Keep it for the error overlay (GL order: bottom row first).
  const Targets& t = s_->targets;
  if (res.referenceMask.size() == size_t(t.width) * size_t(t.height)) {
    std::vector<std::uint8_t> glOrder = res.referenceMask;
    flipRowsVertically(glOrder, size_t(t.width), t.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(t.reference.id(), 0, 0, 0, t.width, t.height, GL_RED_INTEGER,
                        GL_UNSIGNED_BYTE, glOrder.data());
    s_->referenceSignature = s_->frameSignature;
  }
  return res;
}

std::optional<std::string> Renderer::reloadShaders() {
  std::string errors;
  auto note = [&](std::optional<std::string> e) {
    if (e) errors += (errors.empty() ? "" : "\n") + *e;
  };
  note(s_->gbufferProgram.rebuild(s_->shaders));
  note(s_->compositeProgram.rebuild(s_->shaders));
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
