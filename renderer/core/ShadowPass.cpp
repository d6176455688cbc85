#include "ShadowPass.h"

#include "core/SceneGpu.h"

namespace sl {

gl::ProgramDesc depthProgramDesc() {
  return {"common/depth",
          {{GL_VERTEX_SHADER, "common/depth.vert"}, {GL_FRAGMENT_SHADER, "common/depth.frag"}},
          {},
          {}};
}

void beginDepthPass(GLuint framebuffer, int width, int height) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  const float one = 1.0f;
  glClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &one);
}

void renderDepth(const FrameContext& ctx, const gl::Program& program, GLuint framebuffer, int width,
                 int height, const glm::mat4& lightViewProj) {
  beginDepthPass(framebuffer, width, height);
  program.use();
  program.set("u_lightViewProj", lightViewProj);
  ctx.sceneGpu.draw(program, 0);
}

DepthLookupState depthLookupState(const LightFit& fit, const ParamSet& params) {
  DepthLookupState s;
  s.lightViewProj = fit.viewProj;
  s.extentM = fit.extentM;
  s.depthRangeM = fit.depthRangeM > 0.0f ? fit.depthRangeM : 1.0f;
  s.perspective = fit.perspective;
  s.nearM = fit.nearM;
  s.farM = fit.farM;
  s.bias.normalTexels = float(params.get("bias.normal"));
  s.bias.slopeTexels = float(params.get("bias.slope"));
  s.bias.constantM = float(params.get("bias.constant"));
  s.pcfRadius = params.getInt("pcf");
  return s;
}

void bindDepthLookup(const gl::Program& resolve, int unit, const gl::Texture& map,
                     const DepthLookupState& state) {
  glBindTextureUnit(GLuint(unit), map.id());
  resolve.set("u_shadowMap", unit);
  resolve.set("u_pcfRadius", state.pcfRadius);
  resolve.set("u_lightViewProj", state.lightViewProj);
  const LightPlaneMatrix plane = lightPlaneMatrix(state.lightViewProj);
  resolve.set("u_lightNormalMatrix", plane.normal);
  resolve.set("u_lightPlaneOffset", plane.offset);
  resolve.set("u_lightExtentM", state.extentM);
  const float depthPerM =
      depthPerMAtUnitW(state.perspective, state.depthRangeM, state.nearM, state.farM);
  resolve.set("u_depthPerM", depthPerM);
  resolve.set("u_biasNormal", state.bias.normalTexels);
  resolve.set("u_biasSlope", state.bias.slopeTexels);
  resolve.set("u_biasConstant", state.bias.constantM * depthPerM);
}

void publishDepth(Publication& pub, const std::string& key, const gl::Texture& depth) {
  FloatImage img;
  img.width = depth.width();
  img.height = depth.height();
  img.values.resize(size_t(img.width) * size_t(img.height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(depth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                    GLsizei(img.values.size() * sizeof(float)), img.values.data());
  pub.images[key] = std::move(img);
}

}  // namespace sl
