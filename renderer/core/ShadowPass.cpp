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
  resolve.set("u_lightNormalMatrix", lightNormalMatrix(state.lightViewProj));
  resolve.set("u_lightExtentM", state.extentM);
  const float depthPerM = 1.0f / state.depthRangeM;
  resolve.set("u_depthPerM", depthPerM);
  resolve.set("u_biasNormal", state.bias.normalTexels);
  resolve.set("u_biasSlope", state.bias.slopeTexels);
  resolve.set("u_biasConstant", state.bias.constantM * depthPerM);
}

}  // namespace sl
