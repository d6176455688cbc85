// The test-only techniques of TestTechniques.h. Their shaders are in tests/gl/shaders/
// (absolute paths: gl::ShaderLibrary reads them from there and resolves their #includes
// in the renderer's shader root).
#include "TestTechniques.h"

#include <array>
#include <stdexcept>

#include "GlTestEnv.h"
#include "algo/Focus.h"
#include "common/shared_constants.h"
#include "core/LightBinding.h"
#include "core/ShadowPass.h"
#include "core/Technique.h"
#include "techniques/uniform/UniformShadowMap.h"

namespace sl::test {

namespace {

std::string testShader(const char* file) {
  return std::string(SHADOWLAB_TEST_SHADER_DIR) + "/" + file;
}

class Array2x2 : public Technique {
 public:
  explicit Array2x2(const gl::ShaderLibrary& lib) : depth_(lib) {}

  void renderShadows(FrameContext& ctx) override {
    auto pass = ctx.timer.scope("shadow map");
    const int sub = ctx.params.getInt("resolution") / 2;
    LightFit fit;
    if (auto err = fitDirectionalLight(ctx.camera, ctx.aspect, ctx.scene.bounds,
                                       ctx.light.directionalTowards(), FocusSettings{}, fit))
      throw std::runtime_error(*err);
    select_ = fit.viewProj;
    if (!maps_ || maps_.width() != sub) {
      maps_ = gl::Texture::create2DArray(GL_DEPTH_COMPONENT32F, sub, sub, 4);
      for (int k = 0; k < 4; ++k) {
        fbos_[size_t(k)] = gl::Framebuffer::create();
        fbos_[size_t(k)].attachLayer(GL_DEPTH_ATTACHMENT, maps_, k);
        fbos_[size_t(k)].setDrawBuffers(0);
        fbos_[size_t(k)].checkComplete("2x2 sub-map");
      }
    }
    for (int k = 0; k < 4; ++k) {
      // Sub-map (kx, ky) sees light uv [kx/2, kx/2 + 1/2] x [ky/2, ...] as its [0, 1]:
      // clip' = 2 clip + 1 - 2 k per axis.
      const int kx = k & 1, ky = k >> 1;
      glm::mat4 s(1.0f);
      s[0][0] = 2.0f;
      s[1][1] = 2.0f;
      s[3][0] = 1.0f - 2.0f * float(kx);
      s[3][1] = 1.0f - 2.0f * float(ky);
      views_[size_t(k)] = {s * fit.viewProj, 0.5f * fit.extentM,
                           fit.depthRangeM > 0.0f ? fit.depthRangeM : 1.0f};
      renderDepth(ctx, depth_, fbos_[size_t(k)].id(), sub, sub, views_[size_t(k)].lightViewProj);
    }
  }
  std::string lookupShader() const override { return testShader("array2x2_lookup.glsl"); }
  void bindLookup(const gl::Program& resolve, int firstUnit) const override {
    bindDepthLookup(resolve, views_);
    glBindTextureUnit(GLuint(firstUnit), maps_.id());
    resolve.set("u_maps", firstUnit);
    resolve.set("u_selectViewProj", select_);
  }
  std::vector<const gl::Program*> programs() const override { return depth_.programs(); }
  MemoryStats memory() const override {
    MemoryStats m;
    if (maps_) m.add("2x2 sub-maps", "DEPTH_COMPONENT32F", maps_.width(), maps_.height(), 4, 4);
    return m;
  }
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override {
    return depth_.rebuild(lib);
  }

 private:
  DepthProgram depth_;
  gl::Texture maps_;
  std::array<gl::Framebuffer, 4> fbos_;
  std::array<DepthMapView, 4> views_;
  glm::mat4 select_{1.0f};
};

class DeferredUniform : public Technique {
 public:
  explicit DeferredUniform(const gl::ShaderLibrary& lib)
      : inner_(lib),
        resolve_(lib, {"test/deferred_resolve",
                       {{GL_COMPUTE_SHADER, testShader("deferred_resolve.comp")}},
                       {},
                       {}}) {}

  void renderShadows(FrameContext& ctx) override { inner_.renderShadows(ctx); }
  ResolveMode resolveMode() const override { return ResolveMode::Deferred; }
  void resolveDeferred(const ResolveTargets& t, const ParamSet&) override {
    t.bindForCompute();
    resolve_.use();
    bindLight(resolve_, t.light);
    resolve_.set("u_size", glm::ivec2(t.width, t.height));
    inner_.bindLookup(resolve_, SL_UNIT_LOOKUP_FIRST);
    glDispatchCompute(GLuint((t.width + 7) / 8), GLuint((t.height + 7) / 8), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT);
  }
  std::vector<const gl::Program*> programs() const override {
    std::vector<const gl::Program*> p = inner_.programs();
    p.push_back(&resolve_);
    return p;
  }
  MemoryStats memory() const override { return inner_.memory(); }
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) override {
    if (auto e = inner_.reloadShaders(lib)) return e;
    return resolve_.rebuild(lib);
  }

 private:
  UniformShadowMap inner_;
  gl::Program resolve_;
};

class TypoKey : public UniformShadowMap {
 public:
  using UniformShadowMap::UniformShadowMap;
  void renderShadows(FrameContext& ctx) override {
    (void)ctx.params.getInt("resolutoin");  // misspelled on purpose
    UniformShadowMap::renderShadows(ctx);
  }
};

class AllLit : public UniformShadowMap {
 public:
  using UniformShadowMap::UniformShadowMap;
  std::string lookupShader() const override { return testShader("all_lit_lookup.glsl"); }
};

class Counting : public UniformShadowMap {
 public:
  using UniformShadowMap::UniformShadowMap;
  void renderShadows(FrameContext& ctx) override {
    countedFrames().push_back({this, ctx.camera.position});
    UniformShadowMap::renderShadows(ctx);
  }
};

template <typename T>
TechniqueEntry entry(TechniqueInfo info) {
  return {std::move(info), [](const gl::ShaderLibrary& lib) -> std::unique_ptr<Technique> {
            return std::make_unique<T>(lib);
          }};
}

TechniqueInfo infoOf(const char* id, const char* name) {
  return {id, name, "Test-only technique (tests/gl/TestTechniques.h).", shadowMapParamDecls(2048)};
}

}  // namespace

TechniqueEntry array2x2Technique() {
  return entry<Array2x2>(infoOf("uniform-array2x2", "Uniform as 2x2 sub-maps"));
}

TechniqueEntry deferredUniformTechnique() {
  return entry<DeferredUniform>(infoOf("uniform-deferred", "Uniform, deferred resolve"));
}

TechniqueEntry typoUniformTechnique() {
  TechniqueInfo info = infoOf("typo-uniform", "Misspelled uniform");
  info.params.push_back({.key = "bias.extra",
                         .label = "Extra slope",
                         .group = "Bias",
                         .type = ParamType::Float,
                         .defaultValue = 0.0,
                         .minValue = 0.0,
                         .maxValue = 1.0,
                         .help = "Declares a uniform no program has.",
                         .uniform = "u_biasSlpoe"});
  return entry<UniformShadowMap>(std::move(info));
}

TechniqueEntry typoKeyTechnique() {
  return entry<TypoKey>(infoOf("typo-key", "Misspelled parameter key"));
}

TechniqueEntry allLitTechnique() {
  return entry<AllLit>(infoOf("test-all-lit", "Uniform, everything lit"));
}

TechniqueEntry countingTechnique() {
  return entry<Counting>(infoOf("test-count", "Uniform, frames counted"));
}

std::vector<CountedFrame>& countedFrames() {
  static std::vector<CountedFrame> frames;
  return frames;
}

std::unique_ptr<Renderer> makeTestRenderer(const std::string& scene, const std::string& technique) {
  eglContext().makeCurrent();
  RendererOptions options;
  options.extraTechniques = {array2x2Technique(), deferredUniformTechnique(),
                             typoUniformTechnique(), typoKeyTechnique()};
  auto r = std::make_unique<Renderer>(options);
  auto s = loadBuiltin(scene);
  if (!s) return nullptr;
  r->setScene(s);
  r->setCamera(s->cameras.empty() ? s->defaultCamera() : s->cameras.front().camera);
  EXPECT_FALSE(r->setTechnique(technique));
  return r;
}

}  // namespace sl::test
