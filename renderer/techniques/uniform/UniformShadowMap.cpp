// Uniform shadow map (UniformShadowMap.h): fit, exact depth pass, single-map lookup.
#include "UniformShadowMap.h"

#include <stdexcept>

#include "algo/Focus.h"
#include "core/SceneGpu.h"
#include "core/Publish.h"
#include "core/ShadowPass.h"

namespace sl {

TechniqueInfo UniformShadowMap::info() {
  TechniqueInfo info{"uniform", "Uniform shadow map",
                     "Standard shadow map (Williams 1978): one orthographic depth map from the "
                     "light, focused on what the camera sees (directional); for a spot, one "
                     "perspective map covering its cone. The baseline.",
                     shadowMapParamDecls(2048)};
  info.passes = {{"shadow map", "Shadow map",
                  "Fit the light's frustum (directional: orthographic, focused on what the "
                  "camera sees; spot: perspective, its cone), then render the scene's depth "
                  "from the light: uniform texels over the frustum.",
                  "shadowmap"}};
  info.publications = {shadowMapPublicationDecl()};
  info.lights = {LightType::Directional, LightType::Spot};
  return info;
}

UniformShadowMap::UniformShadowMap(const gl::ShaderLibrary& lib)
    : depthProgram_(lib, depthProgramDesc()) {}

void UniformShadowMap::renderShadows(FrameContext& ctx) {
  auto pass = ctx.timer.scope("shadow map");
  const int res = ctx.params.getInt("resolution");
  LightFit fit;
  if (ctx.light.type == LightType::Spot) {
    if (auto err = fitSpotLight(ctx.light, ctx.scene.bounds, fit)) throw std::runtime_error(*err);
  } else if (auto err = fitDirectionalLight(ctx.camera, ctx.aspect, ctx.scene.bounds,
                                            ctx.light.directionalTowards(), FocusSettings{}, fit)) {
    throw std::runtime_error(*err);
  }
  view_ = depthMapView(fit);

  if (!shadowMap_ || shadowMap_.width() != res) {
    shadowMap_ = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, res, res);
    fbo_ = gl::Framebuffer::create();
    fbo_.attach(GL_DEPTH_ATTACHMENT, shadowMap_);
    fbo_.setDrawBuffers(0);
    fbo_.checkComplete("uniform shadow map");
  }
  renderDepth(ctx, depthProgram_, fbo_.id(), res, res, fit.viewProj);
  publishDepth(ctx, "shadow map", shadowMap_);
}

void UniformShadowMap::bindLookup(const gl::Program& resolve, int firstUnit) const {
  bindDepthLookup(resolve, std::span(&view_, 1));
  glBindTextureUnit(GLuint(firstUnit), shadowMap_.id());
  resolve.set("u_shadowMap", firstUnit);
}

MemoryStats UniformShadowMap::memory() const {
  MemoryStats m;
  if (shadowMap_)
    m.add("shadow map", gl::formatName(shadowMap_.format()), shadowMap_.width(),
          shadowMap_.height(), 1, gl::bytesPerTexel(shadowMap_.format()));
  return m;
}

std::optional<std::string> UniformShadowMap::reloadShaders(const gl::ShaderLibrary& lib) {
  return depthProgram_.rebuild(lib);
}

}  // namespace sl
