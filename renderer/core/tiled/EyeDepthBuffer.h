// The eye-space depth buffer of the tiled techniques (Giegl & Wimmer 2007, §3.2 "Eye-Space
// Depth Buffer", fvsm's step 1): one R32F float per pixel, the linear depth along the camera's
// view axis (metres; 0 = no surface), written once per frame from the G-buffer
// (shaders/common/tiled/eye_depth.comp). `virtual-tiled`'s and `fvsm`'s deferred tile passes
// and fvsm's SMTMM rebuild each pixel's position from it with eq. 1
// (shaders/common/tiled/eye_depth.glsl; CPU mirror algo/fvsm eyePosition).
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "core/Technique.h"
#include "gl/Gl.h"
#include "gl/ShaderLibrary.h"

namespace sl {

class EyeDepthBuffer {
 public:
  explicit EyeDepthBuffer(const gl::ShaderLibrary& lib);
  /// The two tiled techniques' pass that writes it (id "eye depth"), declared once.
  static PassDecl passDecl();

  /// Writes the buffer (width x height, reallocated when the size changes) from `gPosition`
  /// (world xyz, w = covered) of a camera with `view` and the perspective `proj`; keeps eq. 1's
  /// terms of that camera for bind().
  void update(const gl::Texture& gPosition, int width, int height, const glm::mat4& view,
              const glm::mat4& proj);
  /// At the start of a deferred resolve: the main camera's buffer was written by the "eye
  /// depth" pass this frame and stays; another view's (the outside view) is written now,
  /// untimed, from its G-buffer and camera (ResolveTargets::cameraView / cameraProj).
  void updateForResolve(const ResolveTargets& targets);
  /// Binds the buffer (SL_UNIT_EYE_DEPTH) and eq. 1's terms of the last update's camera to
  /// `program` (one that includes common/tiled/eye_depth.glsl; it must be in use).
  void bind(const gl::Program& program) const;

  const gl::Texture& texture() const { return texture_; }
  /// The inverse view of the last update's camera (eye -> world).
  const glm::mat4& worldFromEye() const { return worldFromEye_; }
  const gl::Program& program() const { return program_; }
  /// Its line of Technique::memory() (nothing before the first update).
  void addMemory(MemoryStats& m) const;
  std::optional<std::string> reloadShaders(const gl::ShaderLibrary& lib) {
    return program_.rebuild(lib);
  }

 private:
  gl::Program program_;
  gl::Texture texture_;
  glm::mat4 worldFromEye_{1.0f};  ///< the inverse view of the last update's camera
  glm::vec4 rayFromPixel_{0.0f};  ///< eq. 1: (x_e, y_e) / d = pixel * .xy + .zw
};

}  // namespace sl
