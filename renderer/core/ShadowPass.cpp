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
                 int height, const glm::mat4& lightViewProj, float slopeBias, float constantBias) {
  beginDepthPass(framebuffer, width, height);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(slopeBias, constantBias);
  program.use();
  program.set("u_lightViewProj", lightViewProj);
  ctx.sceneGpu.draw(program, 0);
  glDisable(GL_POLYGON_OFFSET_FILL);
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
