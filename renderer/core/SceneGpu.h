// The scene uploaded to the GPU: one interleaved vertex buffer (position, normal, uv),
// one index buffer, the material textures, and a draw list.
#pragma once

#include <vector>

#include "gl/Gl.h"
#include "gl/ShaderLibrary.h"
#include "scene/Scene.h"

namespace sl {

class SceneGpu {
 public:
  explicit SceneGpu(const Scene& scene);
  /// Draws every primitive with `program` bound; sets u_baseColor (vec4), u_alphaMask
  /// (int 0/1), u_alphaCutoff, u_hasTexture and binds the base colour texture to unit
  /// `textureUnit` (the program's u_baseColorTex must use that unit).
  /// `patches`: draws GL_PATCHES (3 vertices) for tessellation programs.
  void draw(const gl::Program& program, int textureUnit = 0, bool patches = false) const;
  std::size_t triangleCount() const { return triangles_; }

 private:
  struct Draw {
    GLsizei indexCount = 0;
    std::size_t firstIndex = 0;
    int material = -1;
  };
  gl::VertexArray vao_;
  gl::Buffer vertices_, indices_;
  std::vector<gl::Texture> textures_;
  std::vector<Material> materials_;
  std::vector<Draw> draws_;
  std::size_t triangles_ = 0;
};

}  // namespace sl
