// Uniform shadow map (UniformShadowMap.h): fit, exact depth pass, single-map lookup.
#include "UniformShadowMap.h"

#include <stdexcept>

#include "algo/Focus.h"
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
  info.baseline = true;
  return info;
}

UniformShadowMap::UniformShadowMap(const gl::ShaderLibrary& lib)
    : SingleDepthMapTechnique(lib, "uniform shadow map") {}

void UniformShadowMap::renderShadows(FrameContext& ctx) {
  auto pass = ctx.timer.scope("shadow map");
  LightFit fit;
  if (ctx.light.type == LightType::Spot) {
    if (auto err = fitSpotLight(ctx.light, ctx.scene.bounds, fit)) throw std::runtime_error(*err);
  } else if (auto err = fitDirectionalLight(ctx.camera, ctx.aspect, ctx.scene.bounds,
                                            ctx.light.directionalTowards(), FocusSettings{}, fit)) {
    throw std::runtime_error(*err);
  }
  map_.render(ctx, ctx.params.getInt("resolution"), depthMapView(fit));
}

}  // namespace sl
