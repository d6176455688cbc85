// The tiled techniques' eye-space depth buffer (EyeDepthBuffer.h).
#include "EyeDepthBuffer.h"

#include "algo/fvsm/Fvsm.h"
#include "common/shared_constants.h"

namespace sl {

EyeDepthBuffer::EyeDepthBuffer(const gl::ShaderLibrary& lib)
    : program_(lib, {"common/tiled/eye_depth",
                     {{GL_COMPUTE_SHADER, "common/tiled/eye_depth.comp"}},
                     {},
                     {}}) {}

void EyeDepthBuffer::update(const gl::Texture& gPosition, int width, int height,
                            const glm::mat4& view, const glm::mat4& proj) {
  if (!texture_ || texture_.width() != width || texture_.height() != height)
    texture_ = gl::Texture::create2D(GL_R32F, width, height);
  // Eq. 1's two matrices multiplied (fvsm::eyePosition): (x_e, y_e) / d = (2 pixel / size − 1
  // + b) tanHalfFov, an affine map per axis.
  const fvsm::EyeProjection terms = fvsm::eyeProjectionOf(glm::dmat4(proj));
  const glm::dvec2 scale = 2.0 * terms.tanHalfFov / glm::dvec2(width, height);
  const glm::dvec2 offset = (terms.ndcOffset - 1.0) * terms.tanHalfFov;
  rayFromPixel_ = glm::vec4(glm::vec2(scale), glm::vec2(offset));
  worldFromEye_ = glm::mat4(glm::inverse(glm::dmat4(view)));
  program_.use();
  program_.set("u_size", glm::ivec2(width, height));
  program_.set("u_eyeFromWorld", view);
  glBindTextureUnit(SL_UNIT_G_POSITION, gPosition.id());
  glBindImageTexture(SL_IMAGE_EYE_DEPTH, texture_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  glDispatchCompute(GLuint((width + 7) / 8), GLuint((height + 7) / 8), 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

void EyeDepthBuffer::updateForResolve(const ResolveTargets& t) {
  if (!t.mainCamera) update(t.gbuffer.position, t.width, t.height, t.cameraView, t.cameraProj);
}

PassDecl EyeDepthBuffer::passDecl() {
  return {"eye depth", "Eye-space depth buffer",
          "Giegl & Wimmer §3.2 (fvsm's step 1, §4.2): every pixel's linear depth along the "
          "camera's view axis, one float, from the G-buffer. Every later pass of the technique "
          "(the SMTMM, each tile's deferred shadowing) rebuilds the pixel's world position from "
          "it and its screen position (their eq. 1) instead of reading a position texture.",
          ""};
}

void EyeDepthBuffer::bind(const gl::Program& program) const {
  glBindTextureUnit(SL_UNIT_EYE_DEPTH, texture_.id());
  program.set("u_eyeRayFromPixel", rayFromPixel_);
  program.set("u_worldFromEye", worldFromEye_);
}

void EyeDepthBuffer::addMemory(MemoryStats& m) const {
  if (texture_)
    m.add("eye-space depth buffer", gl::formatName(texture_.format()), texture_.width(),
          texture_.height(), 1, gl::bytesPerTexel(texture_.format()));
}

}  // namespace sl
